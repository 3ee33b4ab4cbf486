#include "families/rflex/driver/rflex_connection.hpp"

#include <sstream>
#include <stdexcept>
#include <utility>

#include "families/rflex/driver/rflex_motion.hpp"
#include "families/rflex/protocol/rflex_messages.hpp"
#include "links/link_error.hpp"

namespace playerkit::drivers::rflex {

namespace hw = hardware::rflex;
using namespace std::chrono_literals;

namespace {

// 1.5's report period: 100000 µs, both axes.
constexpr std::uint32_t kReportPeriod = 100000;
constexpr std::uint32_t kBothAxes = 3;
// What one reconnection attempt waits for an answer: requests wait for it.
constexpr auto kAttemptBudget = 300ms;
constexpr auto kAskAgainEvery = 500ms;  // the start-up requests, until the controller answers

std::string seconds_text(std::chrono::steady_clock::duration duration) {
  std::ostringstream out;
  out.precision(1);
  out << std::fixed << std::chrono::duration<double>(duration).count() << " s";
  return out.str();
}

}  // namespace

RflexConnection::RflexConnection(RflexSettings settings, core::Logger& logger)
    : RobotConnection(settings.port, links::SerialSettings{.baud = 115200}, logger, "rflex " + settings.port),
      settings_(std::move(settings)),
      readings_(settings_) {}

RflexConnection::~RflexConnection() { stop_io_thread(); }

void RflexConnection::add_device(RflexRole role, core::Device& device) {
  serve_device(device);
  std::lock_guard lock(views_mutex_);
  views_.push_back({role, &device});
}

void RflexConnection::remove_device(core::Device& device) {
  {
    std::lock_guard lock(views_mutex_);
    std::erase_if(views_, [&](const View& view) { return view.device == &device; });
  }
  stop_serving(device);
}

std::vector<core::DriverCounter> RflexConnection::protocol_counters() const {
  return {{"motion_reports", motion_reports_.load()},
          {"bad_packets", bad_packets_.load()},
          {"unknown_packets", unknown_packets_.load()}};
}

// ---------------------------------------------------------------- sessions

bool RflexConnection::start_session(links::ByteLink& link, Clock::time_point deadline, const std::stop_token* stop) {
  link_error_.reset();
  reader_->flush();
  const auto [translation, rotation] = rest_commands(settings_);
  // The controller reports only what it was asked for; one still booting
  // (deaf when the requests went out) would never answer, so they are sent
  // again every half second until it does.
  Clock::time_point ask_again_at = Clock::now();
  while (Clock::now() < deadline) {
    if (stop != nullptr && stop->stop_requested()) return false;
    if (Clock::now() >= ask_again_at) {
      for (const hw::Packet& packet : {hw::motion_report_request(kReportPeriod, kBothAxes),
                                       hw::dio_reports_request(kReportPeriod), hw::set_defaults(),
                                       hw::axis_set_direction(translation), hw::axis_set_direction(rotation),
                                       hw::system_status_request()}) {
        link.write_all(hw::encode_packet(packet), links::deadline_in(500ms));
      }
      ask_again_at = Clock::now() + kAskAgainEvery;
    }
    // Any whole packet is the controller answering.
    if (auto telegram = reader_->next(std::min({deadline, ask_again_at, links::deadline_in(100ms)}))) {
      if (const auto packet = hw::decode_packet(*telegram)) {
        readings_.restart_counters();
        odometry_was_ready_ = false;
        handle_packet(*packet);
        last_packet_ = Clock::now();
        next_cycle_ = last_packet_;
        // What the robot had on before this session is unknown.
        sonar_sent_.reset();
        ir_sent_.reset();
        session_up_ = true;
        return true;
      }
    }
  }
  return false;
}

void RflexConnection::connect(links::ByteLink& link) {
  reader_ = std::make_unique<links::FramedReader>(link, format_, hw::kLongestPacket);
  position_active_ = false;
  xspeed_ = yawspeed_ = 0.0;
  sonar_views_ = ir_views_ = 0;
  sonar_wanted_ = ir_wanted_ = false;
  readings_ = RflexReadings(settings_);
  if (!start_session(link, Clock::now() + settings_.connect_timeout, nullptr)) {
    throw std::runtime_error(label() + ": no RFLEX controller answered within " +
                             seconds_text(settings_.connect_timeout) +
                             " (115200 baud): is the robot on, and is this its port?");
  }
  logger().info(label() + ": the RFLEX controller answers");
}

bool RflexConnection::reconnect(links::ByteLink& link, Attempt attempt, const std::stop_token& stop) {
  if (attempt.reopened || !reader_) reader_ = std::make_unique<links::FramedReader>(link, format_, hw::kLongestPacket);
  if (start_session(link, Clock::now() + kAttemptBudget, &stop)) return true;
  if (stop.stop_requested()) return false;
  throw std::runtime_error("no answer from the RFLEX controller");
}

void RflexConnection::robot_lost() {
  session_up_ = false;
  xspeed_ = yawspeed_ = 0.0;  // never resume an old command after the gap
}

void RflexConnection::serve_while_away() {
  std::lock_guard lock(views_mutex_);
  serve_requests();
  take_commands();
}

void RflexConnection::stop_motion(links::ByteLink& link) noexcept {
  try {
    const auto [translation, rotation] = velocity_commands(0, 0, settings_);
    for (const hw::Packet& packet :
         {hw::axis_set_direction(translation), hw::axis_set_direction(rotation), hw::brake_set(),
          hw::sonar_run({0, 0, 0, 0}), hw::ir_run(false), hw::motion_report_request(0, 0), hw::dio_reports_request(0)}) {
      link.write_all(hw::encode_packet(packet), links::deadline_in(200ms));
    }
    link.drain();
  } catch (const std::exception& e) {
    logger().debug(label() + ": could not stop the robot: " + e.what());
  }
  session_up_ = false;
}

// ---------------------------------------------------------------- the loop

void RflexConnection::serve(links::ByteLink& /*link*/, const core::Wakeup::Woken& woke) {
  if (woke.readable) read_packets();
  const auto now = Clock::now();
  if (now - last_packet_ > settings_.report_timeout) {
    throw hardware_driver::RobotLost("no packet from the RFLEX controller for " + seconds_text(now - last_packet_));
  }
  {
    std::lock_guard lock(views_mutex_);
    reconcile_subscriptions();
    serve_requests();
    take_commands();
    if (now >= next_cycle_) {
      cycle();
      // Never a burst of cycles to catch up after a stall.
      next_cycle_ = std::max(next_cycle_ + kCycle, now);
    }
    if (new_pair_) {
      if (!odometry_was_ready_ && readings_.odometry_ready()) send_velocity();  // what waited for it
      odometry_was_ready_ = readings_.odometry_ready();
      publish();
      new_pair_ = false;
    }
  }
  if (link_error_) throw hardware_driver::RobotLost(*std::exchange(link_error_, std::nullopt));
}

RflexConnection::Clock::time_point RflexConnection::next_deadline() const {
  return std::min(next_cycle_, last_packet_ + settings_.report_timeout + 1ms);
}

void RflexConnection::read_packets() {
  while (auto telegram = reader_->next(links::Deadline{})) {
    if (const auto packet = hw::decode_packet(*telegram)) {
      last_packet_ = Clock::now();
      handle_packet(*packet);
    } else {
      ++bad_packets_;
    }
  }
  ++line_looks_;
}

void RflexConnection::handle_packet(const hw::Packet& packet) {
  try {
    if (const auto motion = hw::read_motion_report(packet)) {
      ++motion_reports_;
      if (readings_.take_motion(*motion)) new_pair_ = true;
    } else if (const auto status = hw::read_system_status(packet)) {
      readings_.take_status(*status);
    } else if (const auto echoes = hw::read_sonar_report(packet)) {
      if (sonar_views_ > 0) readings_.take_sonar(*echoes);
    } else if (const auto dio = hw::read_dio_report(packet)) {
      if (!readings_.take_dio(*dio)) {
        logger().debug(label() + ": a DIO report of address " + std::to_string(dio->address) + ", no bumper panel");
      }
    } else if (const auto banks = hw::read_ir_report(packet)) {
      if (ir_views_ > 0) readings_.take_ir(*banks);
    } else if (const auto joystick = hw::read_joystick_state(packet)) {
      if (settings_.joystick && (joystick->buttons & 1) != 0 && position_active_) {
        // The robot's own joystick drives while its button is held.
        xspeed_ = joystick->y * settings_.joy_pos_ratio;
        yawspeed_ = joystick->x * settings_.joy_ang_ratio * 180.0 / 3.14159265358979323846;
        joystick_holds_ = 5;
        std::lock_guard lock(views_mutex_);
        send_velocity();
      }
    } else if (packet.port == hw::port::system && packet.opcode == hw::opcode::sys_lcd_dump) {
      // The LCD's picture: nothing Player shows.
    } else if (packet.port == hw::port::sonar || packet.port == hw::port::dio ||
               (packet.port == hw::port::motion && packet.opcode != hw::opcode::mot_system_report)) {
      // Acknowledgements of commands (retval, timestamp): nothing to use.
    } else {
      ++unknown_packets_;
    }
  } catch (const std::out_of_range&) {
    ++bad_packets_;
  }
}

}  // namespace playerkit::drivers::rflex
