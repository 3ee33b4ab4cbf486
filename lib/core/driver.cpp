#include "core/driver.hpp"

#include <cassert>
#include <exception>
#include <string>

#include "core/device.hpp"

namespace playerkit::core {

RequestResult Driver::handle_request(const Request& /*request*/) { return RequestResult::nack(); }

std::vector<DeviceKey> Driver::source_devices() const { return {}; }

Device& Driver::device() const {
  assert(device_ != nullptr && "the driver is not attached to a device yet");
  return *device_;
}

ThreadedDriver::~ThreadedDriver() {
  // The Device shuts its driver down before destroying it; this is a last
  // resort so that a forgotten thread never outlives the object it runs on.
  stop_thread();
}

void ThreadedDriver::setup() {
  open();
  thread_ = std::jthread([this](std::stop_token stop) {
    try {
      run(stop);
    } catch (const std::exception& e) {
      device().logger().error(device().name() + ": driver thread stopped: " + e.what());
    }
  });
}

void ThreadedDriver::shutdown() {
  stop_thread();
  close();
}

void ThreadedDriver::stop_thread() {
  if (!thread_.joinable()) return;
  thread_.request_stop();  // also wakes sleep_for(): the wait is tied to the stop token
  thread_.join();
}

bool ThreadedDriver::sleep_for(const std::stop_token& stop, std::chrono::nanoseconds duration) {
  std::unique_lock lock(sleep_mutex_);
  sleep_wakeup_.wait_for(lock, stop, duration, [] { return false; });
  return !stop.stop_requested();
}

}  // namespace playerkit::core
