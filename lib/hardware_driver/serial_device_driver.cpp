#include "hardware_driver/serial_device_driver.hpp"

#include <algorithm>
#include <exception>
#include <stop_token>
#include <utility>

#include "core/device.hpp"
#include "links/exchange.hpp"
#include "links/link_error.hpp"

namespace playerkit::hardware_driver {

namespace {

std::string milliseconds_text(std::chrono::milliseconds duration) { return std::to_string(duration.count()) + " ms"; }

}  // namespace

SerialDeviceDriver::SerialDeviceDriver(std::string port, links::SerialSettings settings, RetryPolicy retry)
    : link_(std::move(port), settings), retry_(retry) {}

SerialDeviceDriver::~SerialDeviceDriver() = default;

std::vector<core::DriverCounter> SerialDeviceDriver::counters() const {
  return link_.counters(reconnects_.load(), protocol_counters(), own_timeouts());
}

bool SerialDeviceDriver::set_byte_trace(core::ByteTrace trace) {
  link_.set_trace(std::move(trace));
  return true;
}

void SerialDeviceDriver::open() {
  links::ByteLink& link = link_.open();
  stop_ = {};
  try {
    start_device(link, false);
  } catch (const std::exception& e) {
    link_closing();
    link_.release();
    throw core::DriverError(e.what());
  }
  lost_ = false;
  port_gone_ = false;
  device().set_wakeup(wakeup_);
}

void SerialDeviceDriver::close() {
  device().set_wakeup(nullptr);
  stop_ = {};  // the thread is gone: the goodbye exchanges must not see its stop
  links::ByteLink* link = link_.get();
  if (link != nullptr && !lost_ && link->is_open()) stop_device(*link);
  link_closing();
  link_.release();
}

void SerialDeviceDriver::run(std::stop_token stop) {
  stop_ = stop;
  // A stop must end the wait on the line, as a command does.
  const std::stop_callback wake_on_stop(stop, [this] { wakeup_->notify(); });
  core::Wakeup::Woken woke{.notified = true, .readable = true};  // look at everything once
  while (!stop.stop_requested()) {
    if (lost_) {
      try_to_recover();
      continue;
    }
    try {
      serve(*link_.get(), woke);
    } catch (const Stopping&) {
      break;
    } catch (const DeviceLost& e) {
      lose(e.what(), false);
      continue;
    } catch (const links::LinkError& e) {
      lose(e.what(), true);
      continue;
    } catch (const links::ExchangeError& e) {
      // An exchange that found the device silent (or refusing) is a lost
      // device; one cut short by the stop is the stop.
      if (e.kind() == links::ExchangeError::Kind::stopped) break;
      lose(e.what(), false);
      continue;
    }
    woke = wakeup_->wait(next_deadline(), link_.get()->native_handle());
  }
}

void SerialDeviceDriver::lose(const std::string& reason, bool port_gone) {
  port_gone_ = port_gone_ || port_gone;
  if (lost_) return;
  lost_ = true;
  const std::string what = "lost " + subject() + ": " + reason;
  device().set_available(false, what);
  device().logger().error(device().name() + ": " + what + "; data stops, new subscriptions get 'e'; trying again every " +
                          milliseconds_text(retry_.interval));
  next_attempt_ = Clock::now() + retry_.interval;
}

void SerialDeviceDriver::try_to_recover() {
  // Requests are answered from what the driver knows meanwhile, as they come.
  device().service_requests();
  if (Clock::now() < next_attempt_) {
    (void)wakeup_->wait(next_attempt_);
    return;
  }
  try {
    if (port_gone_) {
      link_.reopen(links::deadline_in(retry_.reopen_timeout));
      port_gone_ = false;
    }
    start_device(*link_.get(), true);
    lost_ = false;
    ++reconnects_;
    device().set_available(true);
    device().logger().info(device().name() + ": " + subject() + " answers again" + recovery_detail() +
                           "; data resumes");
  } catch (const Stopping&) {
    return;
  } catch (const links::LinkError& e) {
    port_gone_ = true;
    device().logger().debug(device().name() + ": still lost: " + e.what());
  } catch (const std::exception& e) {
    device().logger().debug(device().name() + ": still lost: " + e.what());
  }
  next_attempt_ = Clock::now() + retry_.interval;
}

}  // namespace playerkit::hardware_driver
