#include "families/reb/driver/reb_connection.hpp"

#include <algorithm>
#include <utility>

#include "links/link_error.hpp"

namespace playerkit::drivers::reb {

namespace hw = hardware::reb;
using namespace std::chrono_literals;

namespace {

// 1.5 gave the board 500 ms a character in velocity mode; a reply line is
// back within a few milliseconds.
constexpr auto kReplyTimeout = 500ms;
// The prompt follows its reply at once.
constexpr auto kPromptTimeout = 100ms;
// 38400 baud, 8 data bits and 2 stop bits (reb.md §1).
const links::SerialSettings kRebLine{.baud = 38400, .stop_bits = 2};

std::string command_name(const hw::Command& command) {
  const auto bytes = hw::encode(command);
  return std::string(bytes.begin(), bytes.end() - 1);  // without its CR
}

}  // namespace

RebConnection::RebConnection(RebLinkOptions options, core::Logger& logger)
    : RobotConnection(options.port, kRebLine, logger, "reb " + options.port),
      options_(std::move(options)),
      params_(hw::params_for(options_.subclass)),
      format_(hw::reply_line_options()) {}

RebConnection::~RebConnection() { stop_io_thread(); }

void RebConnection::add_device(RebRole role, core::Device& device, bool heading_control) {
  serve_device(device);  // throws while the board is away
  {
    std::lock_guard lock(views_mutex_);
    views_.push_back({role, &device});
    if (role == RebRole::position) heading_default_ = heading_control;
  }
  wake();
}

void RebConnection::remove_device(core::Device& device) {
  {
    std::lock_guard lock(views_mutex_);
    std::erase_if(views_, [&](const View& view) { return view.device == &device; });
  }
  stop_serving(device);
  wake();
}

std::vector<core::DriverCounter> RebConnection::protocol_counters() const {
  return {{"cycles", cycles_.load()}, {"missing_prompts", missing_prompts_.load()},
          {"stray_lines", stray_lines_.load()}, {"noisy_lines", noisy_lines_.load()}};
}

// ---------------------------------------------------------------- the board

hw::Reply RebConnection::exchange(const hw::Command& command) {
  const char letter = hw::reply_letter(command.letter);
  std::optional<hw::Reply> reply;
  exchanger_->exchange({.name = command_name(command),
                        .bytes = hw::encode(command),
                        .matcher =
                            [&](std::span<const std::uint8_t> telegram) {
                              const std::string_view line = framing::line_text(telegram);
                              auto parsed = hw::find_reply(line, letter);
                              if (!parsed) return links::ReplyMatch::not_mine;
                              if (line.front() != letter) ++noisy_lines_;  // found behind line noise
                              reply = std::move(parsed);
                              return links::ReplyMatch::mine;
                            },
                        .timeout = kReplyTimeout,
                        .attempts = 2});
  await_prompt();
  return *reply;
}

void RebConnection::exchange_both(hw::Command (*make)(hw::Motor, std::int32_t), std::int32_t left,
                                  std::int32_t right) {
  exchange(make(hw::Motor::left, left));
  exchange(make(hw::Motor::right, right));
}

void RebConnection::await_prompt() {
  // The board takes the next command after its prompt (1.5 waited for it).
  const auto deadline = links::deadline_in(kPromptTimeout);
  while (auto telegram = exchanger_->next(deadline)) {
    const std::string_view line = framing::line_text(*telegram);
    if (hw::is_prompt(line)) {
      if (line.size() > 1) ++noisy_lines_;
      return;
    }
    ++stray_lines_;
  }
  ++missing_prompts_;
}

void RebConnection::drain_input() {
  while (auto telegram = exchanger_->next(links::Deadline{})) {
    if (!hw::is_prompt(framing::line_text(*telegram))) ++stray_lines_;
  }
}

void RebConnection::start_session(links::ByteLink& link) {
  reader_ = std::make_unique<links::FramedReader>(link, format_, hw::kLongestLine);
  exchanger_ = std::make_unique<links::Exchanger>(*reader_, std::function<bool()>{}, "the REB");
  // A lone CR ends whatever half a line the board holds, as 1.5's restart did.
  const std::uint8_t cr = '\r';
  link.write_all(std::span(&cr, 1), links::deadline_in(kReplyTimeout));
  exchange(hw::ir_power(false));
  ir_sent_ = false;
  ir_attached_ = false;
  speeds_sent_.reset();
  position_started_ = false;
  position_resumed_ = false;
  lost_.reset();
  next_cycle_ = Clock::now();
  session_up_ = true;
}

void RebConnection::connect(links::ByteLink& link) {
  try {
    start_session(link);
  } catch (const links::ExchangeError& e) {
    throw core::DriverError(label() + ": the board does not answer (LPRSerCom at 38400 baud 8N2?): " + e.what());
  }
  // A fresh start: what earlier subscriptions set no longer holds.
  left_counter_.reset();
  right_counter_.reset();
  motors_enabled_ = false;
  command_ = {};
  odometry_ = {};
  velocity_ = {};
  mode_ = ControlMode::direct_velocity;
  logger().info(label() + ": connected to the REB (UBot " + std::string(params_.subclass) + ")");
}

bool RebConnection::reconnect(links::ByteLink& link, Attempt /*attempt*/, const std::stop_token& stop) {
  if (stop.stop_requested()) return false;
  try {
    start_session(link);
  } catch (const links::ExchangeError& e) {
    throw links::LinkError(links::LinkErrorKind::timed_out, options_.port, e.what());
  }
  // The board may have been reset: the set-up again for a position device
  // still there, keeping its mode and the pose it reported.
  std::lock_guard lock(views_mutex_);
  position_resumed_ = has(RebRole::position);
  return true;
}

void RebConnection::robot_lost() {
  session_up_ = false;
  command_.xspeed = command_.yawspeed = 0;  // never resume an old command after the gap
}

void RebConnection::serve_while_away() {
  std::lock_guard lock(views_mutex_);
  serve_requests();
  for (const View& view : views_) {
    if (view.role == RebRole::position) (void)view.device->take_command();  // dropped, not replayed
  }
}

void RebConnection::serve(links::ByteLink& /*link*/, const core::Wakeup::Woken& woke) {
  try {
    if (woke.readable) drain_input();
    std::lock_guard lock(views_mutex_);
    reconcile_subscriptions();
    serve_requests();
    take_commands();
    if (Clock::now() >= next_cycle_) {
      poll();
      publish();
      ++cycles_;
    }
  } catch (const links::ExchangeError& e) {
    throw hardware_driver::RobotLost(e.what());
  }
  if (lost_) throw hardware_driver::RobotLost(*std::exchange(lost_, std::nullopt));
}

void RebConnection::stop_motion(links::ByteLink& /*link*/) noexcept {
  if (!exchanger_ || !session_up_) return;
  try {
    // Motors stopped, IR emitters off, as 1.5's shutdown.
    exchange_both(hw::set_speed, 0, 0);
    exchange(hw::ir_power(false));
  } catch (const std::exception& e) {
    logger().debug(label() + ": could not stop the board: " + e.what());
  }
  session_up_ = false;
}

}  // namespace playerkit::drivers::reb
