#include "families/segwayrmp/driver/rmp_connection.hpp"

#include <algorithm>
#include <cmath>
#include <sstream>
#include <utility>

#include "families/segwayrmp/driver/rmp_mapping.hpp"
#include "links/can/socketcan_link.hpp"
#include "links/exchange.hpp"
#include "links/link_error.hpp"
#include "links/open_link.hpp"
#include "protocol/binary_codec.hpp"
#include "protocol/messages/position3d.hpp"

namespace playerkit::drivers::segwayrmp {

namespace rmp = hardware::segwayrmp;
using namespace std::chrono_literals;

namespace {

constexpr auto kRetryInterval = 1s;
constexpr auto kAdapterReplyTimeout = 500ms;
constexpr auto kWriteTimeout = 100ms;
// GET_GEOM (segwayrmp.md §3): the body's centre at the origin, 508 x 610 mm.
constexpr double kBodyLength = 0.508;
constexpr double kBodyWidth = 0.610;

// Player's position request subtypes 51-55 and the status command each sends.
std::optional<rmp::StatusCommand> status_command_of(std::uint8_t subtype) {
  switch (subtype) {
    case protocol::kPositionRmpVelocityScale:
      return rmp::StatusCommand::velocity_scale;
    case protocol::kPositionRmpAccelScale:
      return rmp::StatusCommand::acceleration_scale;
    case protocol::kPositionRmpTurnScale:
      return rmp::StatusCommand::turn_scale;
    case protocol::kPositionRmpGainSchedule:
      return rmp::StatusCommand::gain_schedule;
    case protocol::kPositionRmpCurrentLimit:
      return rmp::StatusCommand::current_limit;
    default:
      return std::nullopt;
  }
}

double seconds(std::chrono::steady_clock::duration duration) { return std::chrono::duration<double>(duration).count(); }

std::string seconds_text(std::chrono::steady_clock::duration duration) {
  std::ostringstream out;
  out.precision(2);
  out << std::fixed << seconds(duration) << " s";
  return out.str();
}

// `from` moved toward `to` by at most `rate` a second over `dt` (no ramp when rate is 0).
double ramp(double from, double to, double rate, double dt) {
  if (rate <= 0) return to;
  const double step = rate * dt;
  return std::clamp(to, from - step, from + step);
}

links::LinkCounterSnapshot added(const links::LinkCounterSnapshot& a, const links::LinkCounterSnapshot& b) {
  links::LinkCounterSnapshot total = a;
  total.bytes_in += b.bytes_in;
  total.bytes_out += b.bytes_out;
  total.telegrams += b.telegrams;
  total.checksum_errors += b.checksum_errors;
  total.resyncs += b.resyncs;
  total.bytes_dropped += b.bytes_dropped;
  total.timeouts += b.timeouts;
  total.reconnects += b.reconnects;
  total.retries += b.retries;
  return total;
}

}  // namespace

std::string connection_key(const RmpSettings& settings) { return "segwayrmp " + settings.bus_name(); }

RmpConnection::RmpConnection(RmpSettings settings, core::Logger& logger)
    : settings_(std::move(settings)), logger_(logger), label_("segwayrmp " + settings_.bus_name()) {}

RmpConnection::~RmpConnection() {
  thread_.request_stop();
  if (thread_.joinable()) thread_.join();
}

// ---------------------------------------------------------------- devices

void RmpConnection::add_device(RmpRole role, core::Device& device) {
  if (!answering_) throw core::DriverError(label_ + ": the robot is not answering (reconnecting in the background)");
  {
    std::lock_guard lock(views_mutex_);
    views_.push_back({role, &device});
  }
  device.set_wakeup(wakeup_);
  wakeup_->notify();
}

void RmpConnection::remove_device(core::Device& device) {
  {
    std::lock_guard lock(views_mutex_);
    std::erase_if(views_, [&](const View& view) { return view.device == &device; });
  }
  device.set_wakeup(nullptr);
  wakeup_->notify();
}

// ---------------------------------------------------------------- the bus

void RmpConnection::connect(const std::stop_token* stop) {
  std::unique_ptr<links::ByteLink> link;
  if (settings_.canio == CanIo::slcan) {
    link = links::open_link(settings_.port, {.baud = settings_.baudrate});
  } else {
    // The status messages only: 0x400-0x407 (segwayrmp.md §1 on 1.5's filter).
    link = std::make_unique<links::can::SocketCanLink>(settings_.device,
                                                       std::vector<links::can::CanIdFilter>{{0x400, 0x7F8}});
  }
  {
    std::lock_guard lock(link_mutex_);
    link_ = std::move(link);
    install_trace();
  }
  bus_ = std::make_unique<links::can::CanBus>(*link_, settings_.canio == CanIo::slcan
                                                          ? links::can::CanTransport::slcan
                                                          : links::can::CanTransport::socketcan);
  const auto stopping = [stop] { return stop != nullptr && stop->stop_requested(); };
  bus_->start(settings_.bitrate, kAdapterReplyTimeout, stopping);
  // The robot is there when a whole status set has come.
  assembler_.clear();
  const auto give_up = Clock::now() + settings_.status_timeout;
  for (;;) {
    if (stopping()) throw links::ExchangeError(links::ExchangeFailure::stopped, "stopping");
    const auto frame = bus_->receive(std::min(give_up, Clock::now() + 50ms));
    if (frame && assembler_.add(*frame)) break;
    if (!frame && Clock::now() >= give_up) {
      throw std::runtime_error("the Segway RMP sends no status on " + settings_.bus_name() + " (within " +
                               seconds_text(settings_.status_timeout) + "; is it powered, the bus at " +
                               std::to_string(settings_.bitrate) + " bit/s?)");
    }
  }
  status_ = assembler_.status();
  odometry_.forget_counters();
  odometry_.update(status_.fore_aft_displacement, status_.yaw_displacement);
  last_status_ = Clock::now();
  last_sent_ = last_status_;
  timed_out_ = true;
  wanted_xspeed_ = wanted_yawspeed_ = sent_xspeed_ = sent_yawspeed_ = 0;
  last_command_sent_ = {};
}

void RmpConnection::drop_bus() noexcept {
  if (bus_) bus_->stop();
  bus_.reset();
  std::lock_guard lock(link_mutex_);
  if (link_) {
    released_ = added(released_, link_->counters().snapshot());
    link_->close();
    link_.reset();
  }
}

void RmpConnection::install_trace() {
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

void RmpConnection::set_byte_trace(core::ByteTrace trace) {
  std::lock_guard lock(link_mutex_);
  trace_ = std::move(trace);
  install_trace();
}

std::vector<core::DriverCounter> RmpConnection::counters() const {
  links::LinkCounterSnapshot total;
  {
    std::lock_guard lock(link_mutex_);
    total = link_ ? added(released_, link_->counters().snapshot()) : released_;
  }
  const std::uint64_t own = own_looks_.load();
  return {{"bytes_in", total.bytes_in},
          {"bytes_out", total.bytes_out},
          {"telegrams", total.telegrams},
          {"checksum_errors", total.checksum_errors},
          {"resyncs", total.resyncs},
          {"bytes_dropped", total.bytes_dropped},
          {"timeouts", total.timeouts > own ? total.timeouts - own : 0},
          {"reconnects", reconnects_.load()},
          {"retries", total.retries},
          {"status_sets", status_sets_.load()},
          {"velocity_commands", commands_sent_.load()},
          {"command_timeouts", command_timeouts_.load()},
          {"robot_lost", losses_.load()}};
}

void RmpConnection::write(const framing::CanFrame& frame) { bus_->send(frame, links::deadline_in(kWriteTimeout)); }

// ---------------------------------------------------------------- open / close

void RmpConnection::open() {
  try {
    connect(nullptr);
  } catch (const std::exception& e) {
    drop_bus();
    throw core::DriverError(label_ + ": " + e.what());
  }
  motors_enabled_ = false;  // as in 1.5: MOTOR_POWER first
  odometry_.reset();
  odometry_.update(status_.fore_aft_displacement, status_.yaw_displacement);
  answering_ = true;
  logger_.info(label_ + ": the Segway RMP answers");
  thread_ = std::jthread([this](std::stop_token stop) { run(stop); });
}

void RmpConnection::close() noexcept {
  thread_.request_stop();
  if (thread_.joinable()) thread_.join();
  if (bus_ && answering_) {
    try {
      write(rmp::command_frame({}));
    } catch (const std::exception& e) {
      logger_.warning(label_ + ": could not send the last stop: " + std::string(e.what()));
    }
  }
  drop_bus();
  answering_ = false;
  logger_.info(label_ + ": closed (the last device left)");
}

// ---------------------------------------------------------------- the I/O thread

void RmpConnection::run(const std::stop_token& stop) {
  const std::stop_callback wake_on_stop(stop, [this] { wakeup_->notify(); });
  core::Wakeup::Woken woke{.notified = true, .readable = true};
  while (!stop.stop_requested()) {
    if (!answering_) {
      try_to_reconnect(stop);
      woke = {.notified = true, .readable = true};
      continue;
    }
    try {
      serve(woke);
    } catch (const std::runtime_error& e) {  // a links::LinkError, or the robot's silence
      lose(e.what());
      continue;
    }
    int handle = -1;
    {
      std::lock_guard lock(link_mutex_);
      if (link_) handle = link_->native_handle();
    }
    woke = wakeup_->wait(next_deadline(), handle);
  }
}

RmpConnection::Clock::time_point RmpConnection::next_deadline() const {
  return last_status_ + settings_.status_timeout;
}

void RmpConnection::serve(const core::Wakeup::Woken& woke) {
  if (woke.notified) serve_requests();
  if (failed_write_) throw std::runtime_error(*std::exchange(failed_write_, std::nullopt));
  if (woke.readable) {
    while (const auto frame = bus_->receive(Clock::now())) {
      if (assembler_.add(*frame)) cycle(assembler_.status());
    }
    ++own_looks_;
  }
  if (Clock::now() - last_status_ > settings_.status_timeout) {
    throw std::runtime_error("no status for " + seconds_text(Clock::now() - last_status_));
  }
}

void RmpConnection::serve_requests() {
  std::lock_guard lock(views_mutex_);
  for (const View& view : views_) {
    if (view.device->pending_requests() > 0) view.device->service_requests();
  }
}

void RmpConnection::cycle(const rmp::Status& status) {
  const auto now = Clock::now();
  status_ = status;
  last_status_ = now;
  ++status_sets_;
  const auto& pose = odometry_.update(status.fore_aft_displacement, status.yaw_displacement);
  {
    std::lock_guard lock(views_mutex_);
    for (const View& view : views_) {
      switch (view.role) {
        case RmpRole::position:
          view.device->publish(protocol::encode(position_data(status, pose)));
          break;
        case RmpRole::position3d:
          view.device->publish(protocol::encode(position3d_data(status, pose)));
          break;
        case RmpRole::power:
          view.device->publish(protocol::encode(power_data(status)));
          break;
      }
    }
  }
  take_commands(now);
  send_velocity(now);
}

void RmpConnection::take_commands(Clock::time_point now) {
  std::optional<std::pair<double, double>> newest;  // mm/s, deg/s
  {
    std::lock_guard lock(views_mutex_);
    for (const View& view : views_) {
      if (view.role == RmpRole::power) continue;
      auto command = view.device->take_command();
      if (!command) continue;
      try {
        if (view.role == RmpRole::position) {
          const auto decoded = protocol::decode<protocol::PositionCommand>(command->payload);
          newest = {decoded.xspeed, decoded.yawspeed};
        } else {
          // position3d's yaw rate is in arc-seconds/s, as its interface says.
          const auto decoded = protocol::decode<protocol::Position3dCommand>(command->payload);
          newest = {decoded.xspeed, decoded.yawspeed / kArcSecondsPerDegree};
        }
      } catch (const protocol::DecodeError&) {
        // The device checked the size; nothing else can be wrong.
      }
    }
  }
  if (newest) {
    wanted_xspeed_ = std::clamp(newest->first, -settings_.max_xspeed, settings_.max_xspeed);
    wanted_yawspeed_ = std::clamp(newest->second, -settings_.max_yawspeed, settings_.max_yawspeed);
    last_command_ = now;
    timed_out_ = false;
  } else if (!timed_out_ && now - last_command_ > settings_.command_timeout) {
    // A client that stopped sending must not leave the robot running.
    timed_out_ = true;
    ++command_timeouts_;
    logger_.debug(label_ + ": no command for " + seconds_text(now - last_command_) + ": stopping");
  }
}

void RmpConnection::send_velocity(Clock::time_point now) {
  const bool moving = motors_enabled_ && !timed_out_;
  const double dt = seconds(now - last_sent_);
  last_sent_ = now;
  // Stopping is never ramped: the limits soften starts and changes, not a halt.
  sent_xspeed_ = moving ? ramp(sent_xspeed_, wanted_xspeed_, settings_.max_xaccel, dt) : 0;
  sent_yawspeed_ = moving ? ramp(sent_yawspeed_, wanted_yawspeed_, settings_.max_yawaccel, dt) : 0;
  last_command_sent_ = {.trans = rmp::trans_counts(sent_xspeed_), .rot = rmp::rot_counts(sent_yawspeed_)};
  write(rmp::command_frame(last_command_sent_));
  ++commands_sent_;
}

void RmpConnection::lose(const std::string& reason) {
  answering_ = false;
  ++losses_;
  lost_at_ = Clock::now();
  next_attempt_ = lost_at_ + kRetryInterval;
  drop_bus();
  logger_.warning(label_ + ": lost the robot (" + reason + "); its devices are unavailable until it answers again");
  std::lock_guard lock(views_mutex_);
  for (const View& view : views_) {
    view.device->set_available(false, label_ + ": the robot is not answering (" + reason + ")");
  }
}

void RmpConnection::try_to_reconnect(const std::stop_token& stop) {
  serve_requests();  // answered meanwhile; what needs the bus is declined
  if (Clock::now() < next_attempt_) {
    (void)wakeup_->wait(next_attempt_);
    return;
  }
  try {
    connect(&stop);
  } catch (const std::exception& e) {
    logger_.debug(label_ + ": still no robot: " + e.what());
    drop_bus();
    next_attempt_ = Clock::now() + kRetryInterval;
    return;
  }
  ++reconnects_;
  answering_ = true;
  logger_.warning(label_ + ": the robot is back after " + seconds_text(Clock::now() - lost_at_));
  std::lock_guard lock(views_mutex_);
  for (const View& view : views_) view.device->set_available(true);
}

// ---------------------------------------------------------------- requests

core::RequestResult RmpConnection::handle_request(RmpRole role, const core::Request& request) {
  if (role == RmpRole::position) return interfaces::answer_position_request(*this, request);
  if (role == RmpRole::position3d) {
    try {
      const auto power = protocol::decode<protocol::Position3dPowerConfig>(request.payload);
      if (power.request == protocol::kPosition3dMotorPowerReq && set_motor_power(power.value != 0)) {
        return core::RequestResult::ack();
      }
    } catch (const protocol::DecodeError&) {
    }
  }
  return core::RequestResult::nack();
}

std::optional<interfaces::BaseGeometry> RmpConnection::geometry() {
  return interfaces::BaseGeometry{.pose = {}, .length = kBodyLength, .width = kBodyWidth};
}

bool RmpConnection::set_motor_power(bool on) {
  motors_enabled_ = on;
  logger_.info(label_ + (on ? ": motors enabled" : ": motors disabled"));
  return true;
}

bool RmpConnection::write_status(rmp::StatusCommand command, std::uint8_t value, int times) {
  if (!bus_ || !answering_) return false;
  rmp::Command frame = last_command_sent_;
  frame.status = command;
  frame.status_value = value;
  try {
    for (int i = 0; i < times; ++i) write(rmp::command_frame(frame));
  } catch (const links::LinkError& e) {
    failed_write_ = e.what();
    return false;
  }
  return true;
}

bool RmpConnection::reset_odometry() {
  // Twice, as 1.5 and Segway's demo code did.
  if (!write_status(rmp::StatusCommand::reset_integrators, rmp::kResetAll, 2)) return false;
  odometry_.reset();
  return true;
}

bool RmpConnection::rmp_setting(std::uint8_t subtype, std::uint16_t value) {
  // Only the low byte of a value travels (segwayrmp.md §5.5).
  const auto low = static_cast<std::uint8_t>(value & 0xFF);
  if (const auto command = status_command_of(subtype)) return write_status(*command, low, 1);
  if (subtype == protocol::kPositionRmpRstIntegrators) {
    if (!write_status(rmp::StatusCommand::reset_integrators, low, 2)) return false;
    // The robot's counters restart where it zeroed them: the odometry goes on from the next set.
    odometry_.forget_counters();
    return true;
  }
  if (subtype == protocol::kPositionRmpShutdown) {
    if (!bus_ || !answering_) return false;
    try {
      write(rmp::shutdown_frame());
    } catch (const links::LinkError& e) {
      failed_write_ = e.what();
      return false;
    }
    logger_.warning(label_ + ": the robot was told to shut down (RMP_SHUTDOWN)");
    return true;
  }
  return false;
}

}  // namespace playerkit::drivers::segwayrmp
