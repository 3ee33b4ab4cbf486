#include "hardware_driver/robot_connection.hpp"

#include <pthread.h>
#include <time.h>

#include <algorithm>
#include <exception>
#include <sstream>
#include <utility>

#include "links/exchange.hpp"
#include "links/link_error.hpp"

namespace playerkit::hardware_driver {

using namespace std::chrono_literals;

namespace {

// Between attempts to reopen a port that went away.
constexpr auto kReopenPause = 500ms;
constexpr auto kReopenTimeout = 1s;

std::string seconds_text(RobotConnection::Clock::duration duration) {
  std::ostringstream out;
  out.precision(2);
  out << std::fixed << std::chrono::duration<double>(duration).count() << " s";
  return out.str();
}

}  // namespace

RobotConnection::RobotConnection(std::string port, links::SerialSettings settings, core::Logger& logger,
                                 std::string label)
    : link_(std::move(port), settings), logger_(logger), label_(std::move(label)) {}

RobotConnection::~RobotConnection() { stop_io_thread(); }

void RobotConnection::stop_io_thread() noexcept {
  thread_.request_stop();
  if (thread_.joinable()) thread_.join();
}

std::vector<core::DriverCounter> RobotConnection::counters() const {
  std::vector<core::DriverCounter> extra = protocol_counters();
  extra.push_back({"robot_lost", losses_.load()});
  return link_.counters(reconnects_.load(), std::move(extra), own_timeouts());
}

void RobotConnection::set_byte_trace(core::ByteTrace trace) { link_.set_trace(std::move(trace)); }

std::optional<std::chrono::nanoseconds> RobotConnection::io_thread_cpu_time() const {
  auto& thread = const_cast<std::jthread&>(thread_);
  if (!thread.joinable()) return std::nullopt;
  clockid_t clock{};
  if (pthread_getcpuclockid(thread.native_handle(), &clock) != 0) return std::nullopt;
  timespec spent{};
  if (clock_gettime(clock, &spent) != 0) return std::nullopt;
  return std::chrono::seconds(spent.tv_sec) + std::chrono::nanoseconds(spent.tv_nsec);
}

// ---------------------------------------------------------------- devices

void RobotConnection::serve_device(core::Device& device) {
  if (!answering_) {
    throw core::DriverError(label_ + ": the robot is not answering (reconnecting in the background)");
  }
  {
    std::lock_guard lock(devices_mutex_);
    devices_.push_back(&device);
  }
  device.set_wakeup(wakeup_);
  wake();
}

void RobotConnection::stop_serving(core::Device& device) {
  {
    std::lock_guard lock(devices_mutex_);
    std::erase(devices_, &device);
  }
  device.set_wakeup(nullptr);
  wake();
}

// ---------------------------------------------------------------- open / close

void RobotConnection::open() {
  links::ByteLink& link = link_.open();
  try {
    connect(link);
  } catch (const std::exception& e) {
    link.close();
    throw core::DriverError(e.what());
  }
  answering_ = true;
  thread_ = std::jthread([this](std::stop_token stop) { run(stop); });
}

void RobotConnection::close() noexcept {
  stop_io_thread();
  if (links::ByteLink* link = link_.get(); link != nullptr && link->is_open()) {
    stop_motion(*link);
    link->close();
  }
  answering_ = false;
  logger_.info(label_ + ": closed (the last device left)");
}

// ---------------------------------------------------------------- the I/O thread

void RobotConnection::run(const std::stop_token& stop) {
  // A stop must end the wait on the line, as a command does.
  const std::stop_callback wake_on_stop(stop, [this] { wake(); });
  core::Wakeup::Woken woke{.notified = true, .readable = true};  // look at everything once
  while (!stop.stop_requested()) {
    if (!answering_) {
      try_to_reconnect(stop);
      woke = {.notified = true, .readable = true};
      continue;
    }
    try {
      serve(*link_.get(), woke);
    } catch (const RobotLost& e) {
      lose(e.what());
      continue;
    } catch (const links::LinkError& e) {
      lose(e.what());
      continue;
    } catch (const links::ExchangeError& e) {
      // As in SerialDeviceDriver: silence in an exchange loses the robot.
      if (e.kind() == links::ExchangeError::Kind::stopped) break;
      lose(e.what());
      continue;
    }
    woke = wakeup_->wait(next_deadline(), link_.get()->native_handle());
  }
}

void RobotConnection::lose(const std::string& reason) {
  answering_ = false;
  ++losses_;
  lost_at_ = Clock::now();
  next_attempt_ = lost_at_;
  attempt_ = 0;
  robot_lost();
  logger_.warning(label_ + ": lost the robot (" + reason + "); its devices are unavailable until it answers again");
  std::lock_guard lock(devices_mutex_);
  for (core::Device* device : devices_) {
    device->set_available(false, label_ + ": the robot is not answering (" + reason + ")");
  }
}

void RobotConnection::try_to_reconnect(const std::stop_token& stop) {
  // Requests keep being answered while the robot is away.
  serve_while_away();
  if (Clock::now() < next_attempt_) {
    (void)wakeup_->wait(next_attempt_);
    return;
  }
  links::ByteLink& link = *link_.get();
  try {
    Attempt attempt{.number = attempt_++, .reopened = !link.is_open()};
    if (attempt.reopened) link_.reopen(links::deadline_in(kReopenTimeout));
    const bool back = reconnect(link, attempt, stop);
    if (!back) return;  // stopping
    ++reconnects_;
    answering_ = true;
    logger_.warning(label_ + ": the robot is back after " + seconds_text(Clock::now() - lost_at_));
    std::lock_guard lock(devices_mutex_);
    for (core::Device* device : devices_) device->set_available(true);
  } catch (const links::LinkError& e) {
    logger_.debug(label_ + ": still no robot: " + e.what());
    link.close();
    next_attempt_ = Clock::now() + kReopenPause;
  } catch (const std::exception& e) {
    logger_.debug(label_ + ": still no robot: " + e.what());
  }
}

}  // namespace playerkit::hardware_driver
