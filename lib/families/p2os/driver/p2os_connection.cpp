#include "families/p2os/driver/p2os_connection.hpp"

#include <algorithm>
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

namespace playerkit::drivers::p2os {

namespace hw = hardware::p2os;
using namespace std::chrono_literals;
using Clock = std::chrono::steady_clock;

namespace {

// The longest frame the robot can send: FA FB N and N bytes.
constexpr std::size_t kMaxTelegram = hw::kHeaderSize + hw::kMaxLengthByteFromRobot;

std::string seconds_text(Clock::duration duration) {
  std::ostringstream out;
  out.precision(2);
  out << std::fixed << std::chrono::duration<double>(duration).count() << " s";
  return out.str();
}

}  // namespace

P2osConnection::P2osConnection(RobotLinkOptions options, core::Logger& logger)
    : RobotConnection(options.port, links::SerialSettings{.baud = kP2osBaudRates.front()}, logger,
                      "p2os " + options.port),
      options_(std::move(options)),
      params_(&hw::robot_params_table().front()),
      readings_(*params_),
      odometry_(*params_) {}

P2osConnection::~P2osConnection() {
  // Devices let go of their Use before the pool drops the connection; this
  // only matters if one never did.
  stop_io_thread();
}

std::optional<hw::Sync2Reply> P2osConnection::identity() const {
  std::lock_guard lock(identity_mutex_);
  return identity_;
}

// ---------------------------------------------------------------- devices

void P2osConnection::add_device(P2osRole role, core::Device& device, const MotorLimits& limits) {
  serve_device(device);  // throws while the robot is away
  std::lock_guard lock(views_mutex_);
  views_.push_back({role, &device, limits});
}

void P2osConnection::remove_device(core::Device& device) {
  {
    std::lock_guard lock(views_mutex_);
    std::erase_if(views_, [&](const View& view) { return view.device == &device; });
  }
  stop_serving(device);
}

// ---------------------------------------------------------------- counters

std::vector<core::DriverCounter> P2osConnection::protocol_counters() const {
  return {{"sips", sips_.load()}, {"unknown_packets", unknown_packets_.load()}, {"bad_packets", bad_packets_.load()}};
}

// ---------------------------------------------------------------- open / close

HandshakeSettings P2osConnection::handshake_settings() const {
  HandshakeSettings settings;
  settings.port = options_.port;
  settings.radio = options_.radio;
  return settings;
}

void P2osConnection::connect(links::ByteLink& link) {
  reader_ = std::make_unique<links::FramedReader>(link, format_, kMaxTelegram);
  const std::optional<HandshakeResult> result =
      run_handshake(link, *reader_, handshake_settings(), links::deadline_in(options_.connect_timeout));
  if (options_.radio && !result->radio_connected) {
    logger().warning(label() + ": the radio modem did not report a connection; the robot answered anyway");
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
}

void P2osConnection::stop_motion(links::ByteLink& link) noexcept {
  try {
    // Stop, motors off, then end the session, as 1.5 did (plus ENABLE 0).
    send_command(link, hw::Command::plain(hw::command::stop));
    send_command(link, hw::Command::with_integer(hw::command::enable, 0));
    send_command(link, hw::Command::plain(hw::command::close));
    link.drain();
  } catch (const std::exception& e) {
    logger().debug(label() + ": could not say goodbye to the robot: " + e.what());
  }
  session_up_ = false;
}

// ---------------------------------------------------------------- sessions

void P2osConnection::start_session(const HandshakeResult& result) {
  const hw::RobotParams* row = hw::find_robot_params(result.identity.robot_class, result.identity.subclass);
  if (row == nullptr) {
    logger().warning(label() + ": unknown robot \"" + result.identity.robot_class + "\" / \"" +
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
  logger().info(label() + ": connected to " + result.identity.name + " (" + result.identity.robot_class +
               " " + result.identity.subclass + (result.baud != 0 ? ", " + std::to_string(result.baud) + " baud" : "") +
               ")");
}

void P2osConnection::robot_lost() {
  session_up_ = false;
  velocity_ = {};  // never resume an old command after the gap
}

void P2osConnection::serve_while_away() {
  std::lock_guard lock(views_mutex_);
  serve_requests();
  take_commands();
}

bool P2osConnection::reconnect(links::ByteLink& link, Attempt attempt, const std::stop_token& stop) {
  if (attempt.reopened || !reader_) reader_ = std::make_unique<links::FramedReader>(link, format_, kMaxTelegram);
  // One speed per attempt, the last good one first, so that requests and
  // stop() are never kept waiting long.
  HandshakeSettings settings = handshake_settings();
  settings.radio = options_.radio && attempt.number == 0;
  std::vector<int> order = settings.bauds;
  if (const int good = baud_.load(); good != 0) {
    std::erase(order, good);
    order.insert(order.begin(), good);
  }
  settings.bauds = {order[static_cast<std::size_t>(attempt.number) % order.size()]};
  const auto budget = settings.reply_timeout * settings.tries_per_baud + 50ms +
                      (settings.radio ? std::chrono::milliseconds(3500) : 0ms);
  const std::optional<HandshakeResult> result =
      run_handshake(link, *reader_, settings, links::deadline_in(budget), stop);
  if (!result) return false;  // stopping
  start_session(*result);
  return true;
}

// ---------------------------------------------------------------- the loop

void P2osConnection::serve(links::ByteLink& /*link*/, const core::Wakeup::Woken& woke) {
  if (woke.readable) read_packets();
  const auto now = Clock::now();
  if (now - last_sip_ > options_.sip_timeout) {
    throw hardware_driver::RobotLost("no SIP for " + seconds_text(now - last_sip_));
  }
  {
    std::lock_guard lock(views_mutex_);
    serve_views(now);
  }
  if (link_error_) throw hardware_driver::RobotLost(*std::exchange(link_error_, std::nullopt));
}

void P2osConnection::read_packets() {
  // The line said it has bytes: take every whole packet they make, never
  // waiting for the rest of one (it wakes the thread again when it comes).
  while (auto telegram = reader_->next(links::Deadline{})) handle_telegram(*telegram);
  ++line_looks_;
}

P2osConnection::Clock::time_point P2osConnection::next_deadline() const {
  // Just past the SIP timeout, so that serve() finds it passed.
  Clock::time_point due = last_sip_ + options_.sip_timeout + 1ms;
  if (cmucam_phase_ == CmucamPhase::resetting) due = std::min(due, cmucam_track_at_);
  return due;
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
        logger().warning(label() + ": ignoring packets of unknown type 0x" + hex.str() +
                        " (said once per session)");
      }
    }
  } catch (const hw::DecodeError& e) {
    ++bad_packets_;
    logger().debug(label() + ": dropped a packet: " + e.what());
  }
}

}  // namespace playerkit::drivers::p2os
