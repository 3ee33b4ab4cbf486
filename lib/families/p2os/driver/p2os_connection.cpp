#include "families/p2os/driver/p2os_connection.hpp"

#include <pthread.h>
#include <time.h>

#include <algorithm>
#include <condition_variable>
#include <sstream>
#include <utility>

#include "families/p2os/driver/cmucam_commands.hpp"
#include "families/p2os/protocol/errors.hpp"
#include "families/p2os/protocol/frame.hpp"
#include "families/p2os/protocol/gyro_packet.hpp"
#include "families/p2os/protocol/aux_serial.hpp"
#include "families/p2os/protocol/packet_types.hpp"
#include "families/p2os/protocol/sip.hpp"
#include "links/link_error.hpp"
#include "links/open_link.hpp"

namespace playerkit::drivers::p2os {

namespace hw = hardware::p2os;
using namespace std::chrono_literals;
using Clock = std::chrono::steady_clock;

namespace {

// How long the loop waits for a packet before looking at the devices'
// commands and requests again: the most a velocity command waits.
constexpr auto kPollSlice = 5ms;
// The longest frame the robot can send: FA FB N and N bytes.
constexpr std::size_t kMaxTelegram = hw::kHeaderSize + hw::kMaxLengthByteFromRobot;
// Between attempts to reopen a port that went away.
constexpr auto kReopenPause = 500ms;

links::LinkCounterSnapshot sum(const links::LinkCounterSnapshot& a, const links::LinkCounterSnapshot& b) {
  return {a.bytes_in + b.bytes_in,       a.bytes_out + b.bytes_out, a.telegrams + b.telegrams,
          a.checksum_errors + b.checksum_errors, a.resyncs + b.resyncs,
          a.bytes_dropped + b.bytes_dropped, a.timeouts + b.timeouts, a.reconnects + b.reconnects};
}

links::TraceHook link_hook(const core::ByteTrace& trace) {
  if (!trace) return {};
  return [trace](links::Direction direction, std::span<const std::uint8_t> bytes,
                 links::LinkClock::time_point when) { trace(direction == links::Direction::out, bytes, when); };
}

std::string seconds_text(Clock::duration duration) {
  std::ostringstream out;
  out.precision(2);
  out << std::fixed << std::chrono::duration<double>(duration).count() << " s";
  return out.str();
}

}  // namespace

P2osConnection::P2osConnection(RobotLinkOptions options, core::Logger& logger)
    : options_(std::move(options)),
      logger_(logger),
      params_(&hw::robot_params_table().front()),
      readings_(*params_),
      odometry_(*params_) {}

P2osConnection::~P2osConnection() {
  // Devices let go of their Use before the pool drops the connection; this
  // only matters if one never did.
  thread_.request_stop();
  if (thread_.joinable()) thread_.join();
}

std::string P2osConnection::label() const { return "p2os " + options_.port; }

std::optional<hw::Sync2Reply> P2osConnection::identity() const {
  std::lock_guard lock(identity_mutex_);
  return identity_;
}

std::optional<std::chrono::nanoseconds> P2osConnection::io_thread_cpu_time() const {
  auto& thread = const_cast<std::jthread&>(thread_);
  if (!thread.joinable()) return std::nullopt;
  clockid_t clock{};
  if (pthread_getcpuclockid(thread.native_handle(), &clock) != 0) return std::nullopt;
  timespec spent{};
  if (clock_gettime(clock, &spent) != 0) return std::nullopt;
  return std::chrono::seconds(spent.tv_sec) + std::chrono::nanoseconds(spent.tv_nsec);
}

// ---------------------------------------------------------------- devices

void P2osConnection::add_device(P2osRole role, core::Device& device, const MotorLimits& limits) {
  if (!session_up_) {
    throw core::DriverError(label() + ": the robot is not answering (reconnecting in the background)");
  }
  std::lock_guard lock(views_mutex_);
  views_.push_back({role, &device, limits});
}

void P2osConnection::remove_device(const core::Device& device) {
  std::lock_guard lock(views_mutex_);
  std::erase_if(views_, [&](const View& view) { return view.device == &device; });
}

// ---------------------------------------------------------------- counters

std::vector<core::DriverCounter> P2osConnection::counters() const {
  links::LinkCounterSnapshot link;
  {
    std::lock_guard lock(link_mutex_);
    link = closed_totals_;
    if (link_) link = sum(link, link_->counters().snapshot());
  }
  const std::uint64_t polls = poll_timeouts_.load();
  return {{"bytes_in", link.bytes_in},
          {"bytes_out", link.bytes_out},
          {"telegrams", link.telegrams},
          {"checksum_errors", link.checksum_errors},
          {"resyncs", link.resyncs},
          {"bytes_dropped", link.bytes_dropped},
          // The I/O loop's own short waits are not timeouts: unanswered SYNCs
          // and stuck writes are.
          {"timeouts", link.timeouts > polls ? link.timeouts - polls : 0},
          {"reconnects", reconnects_.load()},
          {"sips", sips_.load()},
          {"unknown_packets", unknown_packets_.load()},
          {"bad_packets", bad_packets_.load()},
          {"robot_lost", robot_losses_.load()}};
}

void P2osConnection::set_byte_trace(core::ByteTrace trace) {
  std::lock_guard lock(link_mutex_);
  trace_ = std::move(trace);
  if (link_) link_->set_trace_hook(link_hook(trace_));
}

// ---------------------------------------------------------------- open / close

HandshakeSettings P2osConnection::handshake_settings() const {
  HandshakeSettings settings;
  settings.port = options_.port;
  settings.radio = options_.radio;
  return settings;
}

void P2osConnection::open() {
  std::shared_ptr<links::ByteLink> link;
  try {
    link = links::open_link(options_.port, links::SerialSettings{.baud = kP2osBaudRates.front()});
  } catch (const links::LinkError& e) {
    throw core::DriverError(e.what());
  }
  {
    std::lock_guard lock(link_mutex_);
    if (link_) closed_totals_ = sum(closed_totals_, link_->counters().snapshot());
    link_ = link;
    link_->set_trace_hook(link_hook(trace_));
  }
  reader_ = std::make_unique<links::FramedReader>(*link, format_, kMaxTelegram);
  std::optional<HandshakeResult> result;
  try {
    result = run_handshake(*link, *reader_, handshake_settings(),
                           links::deadline_in(options_.connect_timeout));
  } catch (const std::exception& e) {  // HandshakeFailed, links::LinkError
    link->close();
    throw core::DriverError(e.what());
  }
  if (options_.radio && !result->radio_connected) {
    logger_.warning(label() + ": the radio modem did not report a connection; the robot answered anyway");
  }
  // A fresh start: what earlier sessions set no longer holds.
  position_active_ = motors_wanted_ = false;
  velocity_ = {};
  velocity_mode_ = VelocityMode::direct_wheel;
  sonar_views_ = 0;
  sonar_wanted_ = false;
  cmucam_tracking_text_ = std::string(kTrackCurrentColor);
  odometry_ = OdometryTracker(*params_);
  start_session(*result);
  thread_ = std::jthread([this](std::stop_token stop) { run(stop); });
}

void P2osConnection::close() noexcept {
  thread_.request_stop();
  if (thread_.joinable()) thread_.join();
  std::shared_ptr<links::ByteLink> link;
  {
    std::lock_guard lock(link_mutex_);
    link = link_;
  }
  if (link && link->is_open()) {
    try {
      // Stop, motors off, then end the session, as 1.5 did (plus ENABLE 0).
      send_command(*link, hw::Command::plain(hw::command::stop));
      send_command(*link, hw::Command::with_integer(hw::command::enable, 0));
      send_command(*link, hw::Command::plain(hw::command::close));
      link->drain();
    } catch (const std::exception& e) {
      logger_.debug(label() + ": could not say goodbye to the robot: " + e.what());
    }
    link->close();
  }
  session_up_ = false;
  logger_.info(label() + ": closed (the last device left)");
}

// ---------------------------------------------------------------- sessions

void P2osConnection::start_session(const HandshakeResult& result) {
  const hw::RobotParams* row = hw::find_robot_params(result.identity.robot_class, result.identity.subclass);
  if (row == nullptr) {
    logger_.warning(label() + ": unknown robot \"" + result.identity.robot_class + "\" / \"" +
                    result.identity.subclass +
                    "\": using the parameters of row 0 (AmigoBot), as Player 1.5 did");
  }
  params_ = &hw::select_robot_params(result.identity.robot_class, result.identity.subclass);
  {
    std::lock_guard lock(identity_mutex_);
    identity_ = result.identity;
  }
  baud_ = result.baud;
  readings_.start_session(*params_);
  odometry_.start_session(*params_);
  last_sip_ = Clock::now();  // the first SIP is due within one robot cycle
  new_sip_ = false;
  link_error_.reset();
  motors_sent_ = false;  // OPEN leaves the motors disabled
  sonar_sent_.reset();
  gyro_sent_ = false;
  gripper_sent_.reset();
  cmucam_phase_ = CmucamPhase::off;
  unknown_types_logged_.clear();
  if (options_.joystick) send(hw::Command::with_integer(hw::command::joydrive, 1));
  session_up_ = true;
  logger_.info(label() + ": connected to " + result.identity.name + " (" + result.identity.robot_class +
               " " + result.identity.subclass + (result.baud != 0 ? ", " + std::to_string(result.baud) + " baud" : "") +
               ")");
}

void P2osConnection::lose_robot(const std::string& reason) {
  session_up_ = false;
  ++robot_losses_;
  lost_at_ = Clock::now();
  reconnect_attempt_ = 0;
  velocity_ = {};  // never resume an old command after the gap
  logger_.warning(label() + ": lost the robot (" + reason + "); its devices are unavailable until it answers again");
  std::lock_guard lock(views_mutex_);
  for (const View& view : views_) {
    view.device->set_available(false, label() + ": the robot is not answering (" + reason + ")");
  }
}

void P2osConnection::reconnect(const std::stop_token& stop) {
  std::shared_ptr<links::ByteLink> link;
  {
    std::lock_guard lock(link_mutex_);
    link = link_;
  }
  {
    // Requests keep being answered while the robot is away.
    std::lock_guard lock(views_mutex_);
    serve_requests();
    take_commands();
  }
  try {
    if (!link->is_open()) {
      link->reopen(links::deadline_in(1s));
      reader_ = std::make_unique<links::FramedReader>(*link, format_, kMaxTelegram);
    }
    // One speed per attempt, the last good one first, so that requests and
    // stop() are never kept waiting long.
    HandshakeSettings settings = handshake_settings();
    settings.radio = options_.radio && reconnect_attempt_ == 0;
    std::vector<int> order = settings.bauds;
    if (const int good = baud_.load(); good != 0) {
      std::erase(order, good);
      order.insert(order.begin(), good);
    }
    settings.bauds = {order[static_cast<std::size_t>(reconnect_attempt_) % order.size()]};
    ++reconnect_attempt_;
    const auto budget = settings.reply_timeout * settings.tries_per_baud + 50ms +
                        (settings.radio ? std::chrono::milliseconds(3500) : 0ms);
    const std::optional<HandshakeResult> result =
        run_handshake(*link, *reader_, settings, links::deadline_in(budget), stop);
    if (!result) return;  // stopping
    const auto away = Clock::now() - lost_at_;
    start_session(*result);
    ++reconnects_;
    logger_.warning(label() + ": the robot is back after " + seconds_text(away));
    std::lock_guard lock(views_mutex_);
    for (const View& view : views_) view.device->set_available(true);
  } catch (const HandshakeFailed& e) {
    logger_.debug(label() + ": still no robot: " + e.what());
  } catch (const links::LinkError& e) {
    logger_.debug(label() + ": still no robot: " + e.what());
    link->close();
    std::mutex pause_mutex;
    std::unique_lock pause(pause_mutex);
    std::condition_variable_any().wait_for(pause, stop, kReopenPause, [] { return false; });
  }
}

// ---------------------------------------------------------------- the loop

void P2osConnection::run(const std::stop_token& stop) {
  while (!stop.stop_requested()) {
    if (!session_up_) {
      reconnect(stop);
      continue;
    }
    try {
      step();
    } catch (const links::LinkError& e) {
      lose_robot(e.what());
    }
    if (link_error_) {
      const std::string reason = *std::exchange(link_error_, std::nullopt);
      if (session_up_) lose_robot(reason);
    }
  }
}

void P2osConnection::step() {
  if (auto telegram = reader_->next(links::deadline_in(kPollSlice))) {
    handle_telegram(*telegram);
  } else {
    ++poll_timeouts_;
  }
  const auto now = Clock::now();
  if (now - last_sip_ > options_.sip_timeout) {
    lose_robot("no SIP for " + seconds_text(now - last_sip_));
    return;
  }
  std::lock_guard lock(views_mutex_);
  serve_views(now);
}

void P2osConnection::handle_telegram(const std::vector<std::uint8_t>& telegram) {
  const auto payload = hw::frame_payload(telegram);
  const std::uint8_t type = payload.front();
  try {
    if (hw::is_standard_sip(type)) {
      const hw::StandardSip sip = hw::decode_sip(payload);
      readings_.take_sip(sip);
      odometry_.update(sip.x_position, sip.y_position, sip.heading);
      last_sip_ = Clock::now();
      new_sip_ = true;
      ++sips_;
    } else if (type == hw::packet_type::gyro) {
      readings_.take_gyro(hw::decode_gyro_packet(payload));
    } else if (type == hw::packet_type::serial_aux2) {
      if (const auto message = hw::find_cmucam_message(hw::decode_aux_serial(payload).data)) {
        readings_.take_cmucam(*message);
      }
      cmucam_answered_ = true;
    } else if (hw::is_sync_echo(type) || type == hw::packet_type::config ||
               type == hw::packet_type::serial_aux || hw::is_old_vision_packet(type)) {
      // Nothing 1.5 used either.
    } else {
      ++unknown_packets_;
      if (std::find(unknown_types_logged_.begin(), unknown_types_logged_.end(), type) ==
          unknown_types_logged_.end()) {
        unknown_types_logged_.push_back(type);
        std::ostringstream hex;
        hex << std::hex << int{type};
        logger_.warning(label() + ": ignoring packets of unknown type 0x" + hex.str() +
                        " (said once per session)");
      }
    }
  } catch (const hw::DecodeError& e) {
    ++bad_packets_;
    logger_.debug(label() + ": dropped a packet: " + e.what());
  }
}

}  // namespace playerkit::drivers::p2os
