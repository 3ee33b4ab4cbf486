#include "families/sick/driver/sick_laser_driver.hpp"

#include <algorithm>
#include <thread>
#include <utility>

#include "core/device.hpp"
#include "families/sick/driver/sick_scan_conversion.hpp"
#include "families/sick/protocol/scan.hpp"
#include "links/link_error.hpp"
#include "links/open_link.hpp"
#include "protocol/binary_codec.hpp"

namespace playerkit::drivers::sick_laser {

namespace sick = hardware::sick;
using namespace std::chrono_literals;
using SteadyClock = std::chrono::steady_clock;

namespace {

// How long the thread waits for a telegram before it looks at requests,
// the data timeout and the stop flag again.
constexpr auto kPollInterval = 100ms;
// A silent laser is lost after this many scan periods, and never sooner
// than kShortestDataTimeout (a loaded machine must not lose a fast laser).
constexpr int kScanPeriodsOfSilence = 4;
constexpr auto kShortestDataTimeout = 1s;
// The speed a laser run faster is left at: where every setup looks first.
constexpr int kRestingBaud = 38400;

std::string milliseconds(SteadyClock::duration duration) {
  return std::to_string(std::chrono::duration_cast<std::chrono::milliseconds>(duration).count()) + " ms";
}

links::LinkCounterSnapshot sum(const links::LinkCounterSnapshot& a, const links::LinkCounterSnapshot& b) {
  links::LinkCounterSnapshot s;
  s.bytes_in = a.bytes_in + b.bytes_in;
  s.bytes_out = a.bytes_out + b.bytes_out;
  s.telegrams = a.telegrams + b.telegrams;
  s.checksum_errors = a.checksum_errors + b.checksum_errors;
  s.resyncs = a.resyncs + b.resyncs;
  s.bytes_dropped = a.bytes_dropped + b.bytes_dropped;
  s.timeouts = a.timeouts + b.timeouts;
  s.reconnects = a.reconnects + b.reconnects;
  return s;
}

}  // namespace

SickLaserDriver::SickLaserDriver(SickDriverSettings settings)
    : settings_(std::move(settings)), scan_(settings_.scan) {}

SickLaserDriver::~SickLaserDriver() = default;

std::string SickLaserDriver::where() const { return device().name(); }

SickLaserControl SickLaserDriver::control() {
  return SickLaserControl(*session_, settings_.model, settings_.port, settings_.reply_timeout);
}

void SickLaserDriver::open() {
  links::SerialSettings line;
  line.baud = 9600;  // both lasers power up at 9600; find() moves on from there
  line.parity = settings_.model == Model::pls ? links::Parity::even : links::Parity::none;
  try {
    auto link = links::open_link(settings_.port, line);
    std::lock_guard lock(link_mutex_);
    link_ = std::move(link);
    install_trace();
  } catch (const links::LinkError& e) {
    throw core::DriverError(e.what());
  }
  stop_token_ = {};
  session_ = std::make_unique<SickSession>(*link_, [this] { return stop_token_.stop_requested(); });
  // A laser powered through the port needs this long to boot (1.5's `delay`).
  if (settings_.delay.count() > 0) std::this_thread::sleep_for(settings_.delay);

  scan_ = settings_.scan;
  try {
    bring_up(probe_rates(false));
  } catch (const std::exception& e) {
    release_link();
    throw core::DriverError(e.what());
  }
  lost_ = false;
  port_gone_ = false;
  last_scan_ = SteadyClock::now();
  std::string type = state_.type.empty() ? "" : " (" + state_.type + ")";
  std::string speed = state_.baud > 0 ? " at " + std::to_string(state_.baud) + " baud" : "";
  device().logger().info(where() + ": " + model_name(settings_.model) + type + " on " + settings_.port +
                         speed + ": " + describe(scan_, settings_.model));
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

void SickLaserDriver::run(std::stop_token stop) {
  stop_token_ = stop;
  while (!stop.stop_requested()) {
    try {
      if (lost_) {
        try_to_recover(stop);
        continue;
      }
      if (auto reply = session_->next_reply(SteadyClock::now() + kPollInterval)) take_telegram(*reply);
      device().service_requests();
      const auto silence = SteadyClock::now() - last_scan_;
      if (!lost_ && silence > data_timeout()) lose_laser("no scan for " + milliseconds(silence), false);
    } catch (const SickExchangeError& e) {
      if (e.kind() == SickExchangeError::Kind::stopped) break;
      lose_laser(e.what(), false);
    } catch (const links::LinkError& e) {
      lose_laser(e.what(), true);
    }
  }
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

void SickLaserDriver::lose_laser(const std::string& reason, bool port_gone) {
  port_gone_ = port_gone_ || port_gone;
  if (lost_) return;
  lost_ = true;
  const std::string what = "lost the " + model_name(settings_.model) + " on " + settings_.port + ": " + reason;
  device().set_available(false, what);
  device().logger().error(where() + ": " + what + "; data stops, new subscriptions get 'e'; trying again every " +
                          milliseconds(settings_.retry_interval));
  next_attempt_ = SteadyClock::now() + settings_.retry_interval;
}

void SickLaserDriver::try_to_recover(const std::stop_token& stop) {
  // Requests are answered from what the driver knows meanwhile.
  device().service_requests();
  const auto now = SteadyClock::now();
  if (now < next_attempt_) {
    sleep_for(stop, std::min<SteadyClock::duration>(next_attempt_ - now, 50ms));
    return;
  }
  session_->set_idle_callback([this] { device().service_requests(); });
  try {
    if (port_gone_) {
      link_->reopen(links::deadline_in(settings_.reply_timeout));
      port_gone_ = false;
    }
    bring_up(probe_rates(true));
    lost_ = false;
    last_scan_ = SteadyClock::now();
    ++reconnects_;
    device().set_available(true);
    device().logger().info(where() + ": the " + model_name(settings_.model) + " on " + settings_.port +
                           " answers again" +
                           (state_.baud > 0 ? " at " + std::to_string(state_.baud) + " baud" : "") +
                           "; data resumes");
  } catch (const SickExchangeError& e) {
    session_->set_idle_callback({});
    if (e.kind() == SickExchangeError::Kind::stopped) return;
    device().logger().debug(where() + ": still lost: " + e.what());
  } catch (const links::LinkError& e) {
    port_gone_ = true;
    device().logger().debug(where() + ": still lost: " + e.what());
  } catch (const SickSetupError& e) {
    device().logger().debug(where() + ": still lost: " + e.what());
  }
  session_->set_idle_callback({});
  next_attempt_ = SteadyClock::now() + settings_.retry_interval;
}

void SickLaserDriver::close() {
  stop_token_ = {};  // the thread is gone; the last telegrams must not see its stop
  if (session_ && !lost_) stop_laser();
  release_link();
}

void SickLaserDriver::stop_laser() noexcept {
  // 1.5 left the laser streaming: the next program to open the port found
  // a stream where it expected replies.
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

void SickLaserDriver::release_link() noexcept {
  session_.reset();
  std::lock_guard lock(link_mutex_);
  if (link_) retired_ = sum(retired_, link_->counters().snapshot());
  link_.reset();
}

void SickLaserDriver::install_trace() {
  if (!link_) return;
  if (!trace_) {
    link_->set_trace_hook({});
    return;
  }
  link_->set_trace_hook([trace = trace_](links::Direction direction, std::span<const std::uint8_t> bytes,
                                         links::LinkClock::time_point when) {
    trace(direction == links::Direction::out, bytes, when);
  });
}

bool SickLaserDriver::set_byte_trace(core::ByteTrace trace) {
  std::lock_guard lock(link_mutex_);
  trace_ = std::move(trace);
  install_trace();
  return true;
}

std::vector<core::DriverCounter> SickLaserDriver::counters() const {
  links::LinkCounterSnapshot total;
  {
    std::lock_guard lock(link_mutex_);
    total = link_ ? sum(retired_, link_->counters().snapshot()) : retired_;
  }
  return {{"bytes_in", total.bytes_in},
          {"bytes_out", total.bytes_out},
          {"telegrams", total.telegrams},
          {"checksum_errors", total.checksum_errors},
          {"resyncs", total.resyncs},
          {"bytes_dropped", total.bytes_dropped},
          {"timeouts", total.timeouts},
          {"reconnects", reconnects_.load()},
          {"scans", scans_.load()}};
}

}  // namespace playerkit::drivers::sick_laser
