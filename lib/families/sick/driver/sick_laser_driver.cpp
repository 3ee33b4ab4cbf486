#include "families/sick/driver/sick_laser_driver.hpp"

#include <algorithm>
#include <thread>
#include <utility>

#include "core/device.hpp"
#include "families/sick/driver/sick_scan_conversion.hpp"
#include "families/sick/protocol/scan.hpp"
#include "links/link_error.hpp"
#include "protocol/binary_codec.hpp"

namespace playerkit::drivers::sick_laser {

namespace sick = hardware::sick;
using namespace std::chrono_literals;
using SteadyClock = std::chrono::steady_clock;

namespace {

// A silent laser is lost after this many scan periods, and never sooner
// than kShortestDataTimeout (a loaded machine must not lose a fast laser).
constexpr int kScanPeriodsOfSilence = 4;
constexpr auto kShortestDataTimeout = 1s;
// The speed a laser run faster is left at: where every setup looks first.
constexpr int kRestingBaud = 38400;

std::string milliseconds(SteadyClock::duration duration) {
  return std::to_string(std::chrono::duration_cast<std::chrono::milliseconds>(duration).count()) + " ms";
}

links::SerialSettings line_settings(Model model) {
  links::SerialSettings line;
  line.baud = 9600;  // both lasers power up at 9600; find() moves on from there
  line.parity = model == Model::pls ? links::Parity::even : links::Parity::none;
  return line;
}

}  // namespace

SickLaserDriver::SickLaserDriver(SickDriverSettings settings)
    : SerialDeviceDriver(settings.port, line_settings(settings.model),
                         {.interval = settings.retry_interval, .reopen_timeout = settings.reply_timeout}),
      settings_(std::move(settings)),
      scan_(settings_.scan) {}

SickLaserDriver::~SickLaserDriver() = default;

std::string SickLaserDriver::where() const { return device().name(); }

std::string SickLaserDriver::subject() const { return "the " + model_name(settings_.model) + " on " + settings_.port; }

std::string SickLaserDriver::recovery_detail() const {
  return state_.baud > 0 ? " at " + std::to_string(state_.baud) + " baud" : "";
}

SickLaserControl SickLaserDriver::control() {
  return SickLaserControl(*session_, settings_.model, settings_.port, settings_.reply_timeout);
}

void SickLaserDriver::start_device(links::ByteLink& link, bool recovering) {
  if (!recovering) {
    session_ = std::make_unique<SickSession>(link, [this] { return stopping(); });
    // A laser powered through the port needs this long to boot (1.5's `delay`).
    if (settings_.delay.count() > 0) std::this_thread::sleep_for(settings_.delay);
    scan_ = settings_.scan;
  } else {
    // Requests are answered from what the driver knows while it looks.
    session_->set_idle_callback([this] { device().service_requests(); });
  }
  try {
    bring_up(probe_rates(recovering));
  } catch (const SickExchangeError& e) {
    session_->set_idle_callback({});
    if (e.kind() == SickExchangeError::Kind::stopped) throw hardware_driver::Stopping();
    throw;
  } catch (...) {
    session_->set_idle_callback({});
    throw;
  }
  session_->set_idle_callback({});
  more_buffered_ = false;
  lost_in_request_.reset();
  port_gone_in_request_ = false;
  last_scan_ = SteadyClock::now();
  if (recovering) return;
  std::string type = state_.type.empty() ? "" : " (" + state_.type + ")";
  std::string speed = state_.baud > 0 ? " at " + std::to_string(state_.baud) + " baud" : "";
  device().logger().info(where() + ": " + model_name(settings_.model) + type + " on " + settings_.port + speed +
                         ": " + describe(scan_, settings_.model));
}

void SickLaserDriver::bring_up(const std::vector<int>& rates) {
  state_ = control().bring_up(scan_, settings_.rate, rates);
}

std::vector<int> SickLaserDriver::probe_rates(bool recovering) const {
  // Both sheets: 38400 first, then 9600 (power-up); then the speed asked
  // for, where a laser run at 500000 is after a crash. A lost laser is
  // most likely still at the speed it was run at.
  std::vector<int> rates;
  if (recovering && state_.baud > 0) rates.push_back(state_.baud);
  for (const int rate : {38400, 9600, settings_.rate}) {
    if (std::find(rates.begin(), rates.end(), rate) == rates.end()) rates.push_back(rate);
  }
  return rates;
}

void SickLaserDriver::serve(links::ByteLink& /*link*/, const core::Wakeup::Woken& woke) {
  try {
    if (woke.readable || more_buffered_) {
      // The line has bytes: a short look lets poll(2) see them; only
      // buffered telegrams: no look at the line at all.
      const auto look = woke.readable ? 1ms : 0ms;
      more_buffered_ = false;
      if (auto reply = session_->next_reply(SteadyClock::now() + look)) {
        take_telegram(*reply);
        more_buffered_ = true;
      }
    }
    device().service_requests();
  } catch (const SickExchangeError& e) {
    if (e.kind() == SickExchangeError::Kind::stopped) throw hardware_driver::Stopping();
    throw hardware_driver::DeviceLost(e.what());
  }
  if (lost_in_request_) {
    const std::string reason = *std::exchange(lost_in_request_, std::nullopt);
    if (std::exchange(port_gone_in_request_, false)) {
      throw links::LinkError(links::LinkErrorKind::io_error, settings_.port, reason);
    }
    throw hardware_driver::DeviceLost(reason);
  }
  const auto silence = SteadyClock::now() - last_scan_;
  if (silence > data_timeout()) throw hardware_driver::DeviceLost("no scan for " + milliseconds(silence));
}

SickLaserDriver::Clock::time_point SickLaserDriver::next_deadline() const {
  if (more_buffered_) return SteadyClock::now();
  // Just past the data timeout, so that serve() finds it passed.
  return last_scan_ + data_timeout() + 1ms;
}

void SickLaserDriver::take_telegram(const sick::Reply& reply) {
  if (reply.code != sick::kScanReply && reply.code != sick::kSubrangeScanReply) return;
  const auto arrived = device().clock().now();
  try {
    const sick::Scan scan = sick::parse_scan(reply);
    const protocol::LaserData data =
        to_laser_data(scan, {scan_, settings_.model, state_.unit, settings_.invert});
    device().publish(protocol::encode(data), arrived);
    ++scans_;
    last_scan_ = SteadyClock::now();
  } catch (const std::exception& e) {
    // A scan for another configuration (queued before a reconfiguration)
    // or a malformed one: not data, and not a reason to give up.
    device().logger().debug(where() + ": scan dropped: " + e.what());
  }
}

SteadyClock::duration SickLaserDriver::data_timeout() const {
  const int baud = state_.baud > 0 ? state_.baud : 9600;
  const int bits_per_byte = settings_.model == Model::pls ? 11 : 10;  // 8E1 has a parity bit
  const auto values = static_cast<std::size_t>(device_value_count(scan_, settings_.model));
  const auto bytes = sick::subrange_scan_telegram_size(values);
  const auto period = std::chrono::microseconds(bytes * static_cast<std::size_t>(bits_per_byte) * 1'000'000 /
                                                static_cast<std::size_t>(baud));
  return std::max<SteadyClock::duration>(kShortestDataTimeout, kScanPeriodsOfSilence * period);
}

void SickLaserDriver::stop_device(links::ByteLink& /*link*/) noexcept {
  // 1.5 left the laser streaming: the next program to open the port found
  // a stream where it expected replies.
  if (!session_) return;
  try {
    SickLaserControl laser = control();
    laser.stop_streaming();
    if (state_.baud > kRestingBaud) {
      laser.switch_rate(kRestingBaud);
    }
  } catch (const std::exception& e) {
    device().logger().warning(where() + ": could not stop the laser cleanly: " + e.what());
  }
}

void SickLaserDriver::link_closing() noexcept { session_.reset(); }

std::vector<core::DriverCounter> SickLaserDriver::protocol_counters() const { return {{"scans", scans_.load()}}; }

}  // namespace playerkit::drivers::sick_laser
