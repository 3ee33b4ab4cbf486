#include "families/khepera/driver/khepera_connection.hpp"

#include <algorithm>
#include <stdexcept>
#include <utility>

#include "links/link_error.hpp"

namespace playerkit::drivers::khepera {

namespace hw = hardware::khepera;
using namespace std::chrono_literals;

KheperaConnection::KheperaConnection(KheperaRobotOptions options, core::Logger& logger)
    : RobotConnection(options.port, links::SerialSettings{.baud = kKheperaBaud}, logger, "khepera " + options.port),
      options_(std::move(options)) {}

KheperaConnection::~KheperaConnection() { stop_io_thread(); }

// ---------------------------------------------------------------- devices

void KheperaConnection::add_position(core::Device& device, const KheperaPositionOptions& options) {
  serve_device(device);  // throws while the robot is away
  std::lock_guard lock(views_mutex_);
  position_options_ = options;
  views_.push_back({KheperaRole::position, &device});
  wake();
}

void KheperaConnection::add_ir(core::Device& device, const KheperaIrOptions& options) {
  serve_device(device);
  std::lock_guard lock(views_mutex_);
  ir_options_ = options;
  views_.push_back({KheperaRole::ir, &device});
  wake();
}

void KheperaConnection::remove_device(core::Device& device) {
  {
    std::lock_guard lock(views_mutex_);
    std::erase_if(views_, [&](const View& view) { return view.device == &device; });
  }
  stop_serving(device);
  wake();
}

std::vector<core::DriverCounter> KheperaConnection::protocol_counters() const {
  return {{"cycles", cycles_.load()}, {"stray_lines", stray_lines_.load()}};
}

// ---------------------------------------------------------------- the line

hw::Message KheperaConnection::ask(const hw::Message& command, std::optional<std::size_t> count) {
  std::optional<hw::Message> reply;
  const auto outcome = exchanger_->try_exchange(
      {.name = std::string(1, command.letter),
       .bytes = hw::encode_command(command),
       .matcher =
           [&](std::span<const std::uint8_t> telegram) {
             reply = hw::find_reply_to(command.letter, framing::line_text(telegram), count);
             if (!reply) {
               ++stray_lines_;
               return links::ReplyMatch::not_mine;
             }
             return links::ReplyMatch::mine;
           },
       .timeout = options_.reply_timeout,
       .attempts = 3});
  if (!outcome.replied() || !reply) throw hardware_driver::RobotLost(outcome.message);
  return *reply;
}

void KheperaConnection::connect(links::ByteLink& link) {
  reader_ = std::make_unique<links::FramedReader>(link, format_, hw::kLongestLine);
  exchanger_ = std::make_unique<links::Exchanger>(*reader_, std::function<bool()>{}, "the Khepera");
  // CR LF ends whatever an earlier program left half typed; its answer, if
  // any, is dropped by the exchange's flush or is no `e` line.
  link.write_all(framing::line_bytes("", framing::LineEnd::cr_or_lf), links::deadline_in(options_.reply_timeout));
  const auto deadline = links::deadline_in(options_.connect_timeout);
  std::string failure;
  while (true) {
    const auto outcome = exchanger_->try_exchange(
        {.name = "E (wheel speeds)",
         .bytes = hw::encode_command(hw::read_speed()),
         .matcher =
             [](std::span<const std::uint8_t> telegram) {
               return hw::find_reply_to(hw::letter::read_speed, framing::line_text(telegram), 2)
                          ? links::ReplyMatch::mine
                          : links::ReplyMatch::not_mine;
             },
         .timeout = std::min<links::LinkClock::duration>(options_.reply_timeout, links::time_until(deadline)),
         .attempts = 1});
    if (outcome.replied()) break;
    if (links::time_until(deadline) <= 0ms) {
      throw std::runtime_error("no Khepera answered E on " + options_.port + " within " +
                               std::to_string(options_.connect_timeout.count()) +
                               " ms: is it on, at 38400 baud, in its serial (SerCom) mode? (" + outcome.message + ")");
    }
  }
  {
    std::lock_guard lock(views_mutex_);
    position_active_ = ir_active_ = false;
    motors_on_ = false;
    speed_ = turn_rate_ = 0.0;
    odometry_ = {};
  }
  start_session();
}

void KheperaConnection::start_session() {
  last_counters_.reset();
  next_cycle_ = Clock::now();
  session_up_ = true;
  logger().info(label() + ": connected to a Khepera (38400 baud)");
}

bool KheperaConnection::reconnect(links::ByteLink& link, Attempt attempt, const std::stop_token& stop) {
  if (stop.stop_requested()) return false;
  if (attempt.reopened || !reader_) {
    reader_ = std::make_unique<links::FramedReader>(link, format_, hw::kLongestLine);
    exchanger_ = std::make_unique<links::Exchanger>(*reader_, std::function<bool()>{}, "the Khepera");
  }
  (void)ask(hw::read_speed(), 2);  // silence throws: the base tries again
  // The reported pose carries on from where it was: the counters are read
  // afresh (the robot may have been reset meanwhile), and the next cycle
  // sends the wheels the current command, stopped since the loss.
  start_session();
  return true;
}

void KheperaConnection::robot_lost() {
  session_up_ = false;
  lost_reason_.reset();
  speed_ = turn_rate_ = 0.0;  // never resume an old command after the gap
}

void KheperaConnection::serve_while_away() {
  std::lock_guard lock(views_mutex_);
  serve_requests();
  take_commands();
}

void KheperaConnection::stop_motion(links::ByteLink& /*link*/) noexcept {
  try {
    if (exchanger_ && session_up_) (void)ask(hw::set_speed(0, 0), 0);
  } catch (const std::exception& e) {
    logger().debug(label() + ": could not stop the robot: " + e.what());
  }
  session_up_ = false;
}

KheperaConnection::Clock::time_point KheperaConnection::next_deadline() const { return next_cycle_; }

void KheperaConnection::serve(links::ByteLink& /*link*/, const core::Wakeup::Woken& woke) {
  // The robot speaks only when asked: anything between exchanges is noise.
  if (woke.readable) reader_->flush();
  std::lock_guard lock(views_mutex_);
  reconcile_subscriptions();
  serve_requests();
  if (lost_reason_) throw hardware_driver::RobotLost(*std::exchange(lost_reason_, std::nullopt));
  take_commands();
  if (const auto now = Clock::now(); now >= next_cycle_) {
    // Cycles keep their rate; one that fell behind is skipped, not crammed.
    next_cycle_ += options_.cycle;
    if (next_cycle_ <= now) next_cycle_ = now + options_.cycle;
    run_cycle();
    publish();
  }
}

}  // namespace playerkit::drivers::khepera
