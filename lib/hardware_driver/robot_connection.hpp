#pragma once
// The base of a robot shared by many devices on one serial line (a Pioneer's
// eleven p2os devices): what every such connection does the same way, so
// that a robot family writes only its protocol and its mapping to Player
// structs. Over core::SharedConnection:
//
//  * open (the first device's setup, on the thread the server gives a setup
//    that may block, never its event loop): the `port` opened with the
//    settings, connect() (the handshake: its exception refuses the
//    subscription), then one I/O thread for everything else;
//  * the I/O thread sleeps on the line and on a core::Wakeup until bytes
//    come, a device gets a command or a request, a device is added or
//    removed, or the protocol's next timer is due (next_deadline()), and
//    calls serve() for each: no polling;
//  * a robot that stops answering (serve() throws RobotLost) or a line that
//    fails (links::LinkError): one log line, every served device
//    unavailable, then reconnect() attempts (the port reopened first if it
//    had gone), requests and commands served between them; one log line
//    when the robot is back, the devices available again;
//  * close (after the last device): the thread stopped, stop_motion() while
//    the line is open (the motors stopped, the session ended), the port
//    closed;
//  * counters() (--stats): the link's, summed over every reopening, then the
//    protocol's and robot_lost; set_byte_trace() follows the link.

#include <atomic>
#include <chrono>
#include <cstdint>
#include <memory>
#include <mutex>
#include <optional>
#include <stdexcept>
#include <stop_token>
#include <string>
#include <thread>
#include <vector>

#include "core/device.hpp"
#include "core/driver.hpp"
#include "core/logger.hpp"
#include "core/shared_connection.hpp"
#include "core/wakeup.hpp"
#include "hardware_driver/link_slot.hpp"
#include "links/byte_link.hpp"
#include "links/serial_settings.hpp"

namespace playerkit::hardware_driver {

// Thrown by serve() when the robot stopped answering on a line that still
// works (no status packet for too long).
class RobotLost : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

class RobotConnection : public core::SharedConnection {
 public:
  using Clock = std::chrono::steady_clock;

  ~RobotConnection() override;

  // The link's figures, reconnects, the protocol's, robot_lost.
  [[nodiscard]] std::vector<core::DriverCounter> counters() const;
  // Every byte of the line from now on (also across reopening).
  void set_byte_trace(core::ByteTrace trace);
  // Connected, and not lost since.
  [[nodiscard]] bool robot_answering() const { return answering_.load(); }
  // CPU time the I/O thread has used, while it runs.
  [[nodiscard]] std::optional<std::chrono::nanoseconds> io_thread_cpu_time() const;

 protected:
  // `label` begins every log line: "p2os /dev/ttyS0".
  RobotConnection(std::string port, links::SerialSettings settings, core::Logger& logger, std::string label);

  // --- the protocol
  // On the line just opened: the handshake and the start of a session,
  // within the protocol's connect timeout. Throws to refuse.
  virtual void connect(links::ByteLink& link) = 0;
  // One attempt to find the lost robot again; true when it answers, false
  // when `stop` ended it. Throws when it did not answer (links::LinkError:
  // the port is reopened first next time). Keep an attempt short: requests
  // wait for it.
  struct Attempt {
    int number = 0;         // from 0 since the loss
    bool reopened = false;  // the port was reopened for it: nothing read before holds
  };
  virtual bool reconnect(links::ByteLink& link, Attempt attempt, const std::stop_token& stop) = 0;
  // One pass while the robot answers, after every wake-up: input on the
  // line (woke.readable), work from the devices (woke.notified), or the
  // time from next_deadline(). Throws RobotLost or links::LinkError.
  virtual void serve(links::ByteLink& link, const core::Wakeup::Woken& woke) = 0;
  [[nodiscard]] virtual Clock::time_point next_deadline() const = 0;
  // Between reconnection attempts: the requests (and commands) that need
  // no robot.
  virtual void serve_while_away() {}
  // The robot was just lost (forget what must not be replayed).
  virtual void robot_lost() {}
  // After the last device, the I/O thread stopped, the line open: stop
  // whatever moves and end the session. Failures are the protocol's to log.
  virtual void stop_motion(links::ByteLink& link) noexcept = 0;
  [[nodiscard]] virtual std::vector<core::DriverCounter> protocol_counters() const { return {}; }
  // The link's timeouts that were the I/O thread's own looks at the line.
  [[nodiscard]] virtual std::uint64_t own_timeouts() const { return 0; }

  // --- for the protocol
  // A device's driver, from its setup(): it is made unavailable and
  // available with the robot, and its commands and requests wake the I/O
  // thread. Throws core::DriverError while the robot is not answering.
  void serve_device(core::Device& device);
  // From its shutdown(); afterwards the base no longer touches it.
  void stop_serving(core::Device& device);
  // Wakes the I/O thread (a device came or went).
  void wake() { wakeup_->notify(); }
  // For the destructor of a protocol whose devices never let go: the
  // thread must end before the protocol's members do.
  void stop_io_thread() noexcept;
  [[nodiscard]] const std::string& label() const { return label_; }
  [[nodiscard]] core::Logger& logger() const { return logger_; }
  // The current link, for the I/O thread (and connect()/stop_motion()).
  [[nodiscard]] links::ByteLink& link() const { return *link_.get(); }

 private:
  void open() final;
  void close() noexcept final;
  void run(const std::stop_token& stop);
  void lose(const std::string& reason);
  void try_to_reconnect(const std::stop_token& stop);

  LinkSlot link_;
  core::Logger& logger_;
  const std::string label_;
  const std::shared_ptr<core::Wakeup> wakeup_ = std::make_shared<core::Wakeup>();

  mutable std::mutex devices_mutex_;
  std::vector<core::Device*> devices_;

  std::jthread thread_;
  std::atomic<bool> answering_{false};
  std::atomic<std::uint64_t> losses_{0};
  std::atomic<std::uint64_t> reconnects_{0};

  // The I/O thread's.
  Clock::time_point lost_at_{};
  Clock::time_point next_attempt_{};
  int attempt_ = 0;
};

}  // namespace playerkit::hardware_driver
