#pragma once
// The base of a driver that serves one device on one serial line (or a
// tcp: bridge to one): what every such driver does the same way, so that a
// new one writes only its protocol and its mapping to Player structs.
//
//  * setup: the `port` opened with the driver's settings, then
//    start_device() (the handshake; its exception refuses the subscription,
//    naming the port), then the driver's thread;
//  * the thread sleeps on the line and on a core::Wakeup until bytes come,
//    a client's command or request arrives, or the driver's next timer is
//    due (next_deadline()), and calls serve() for each of those: no polling;
//  * a device that stops answering (serve() throws DeviceLost) or a port
//    that goes away (a links::LinkError): one log line, the device
//    unavailable, then every retry_interval the port reopened if it had gone
//    and start_device() again, requests answered meanwhile; one log line
//    when it answers again;
//  * shutdown: stop_device() (the stream stopped, the motors off) while the
//    device still answers, then the port closed;
//  * counters() (--stats): the link's, summed over every reopening, plus the
//    driver's own; set_byte_trace() (--trace) follows the link across them.
//
//   class Sonar final : public hardware_driver::SerialDeviceDriver {
//     void start_device(links::ByteLink& link, bool recovering) override { handshake(link); }
//     void serve(links::ByteLink& link, const core::Wakeup::Woken& woke) override {
//       if (woke.readable) ... publish telegrams ...;
//       device().service_requests();
//     }
//   };

#include <atomic>
#include <chrono>
#include <cstdint>
#include <memory>
#include <stdexcept>
#include <stop_token>
#include <string>
#include <vector>

#include "core/driver.hpp"
#include "core/wakeup.hpp"
#include "hardware_driver/link_slot.hpp"
#include "links/byte_link.hpp"
#include "links/serial_settings.hpp"

namespace playerkit::hardware_driver {

// Thrown by serve() when the device stopped answering on a link that still
// works (no data for too long): the device is lost, the port kept open.
class DeviceLost : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

// Thrown by start_device() or serve() when the driver's thread is asked to
// stop in the middle of an exchange: not a failure.
class Stopping : public std::runtime_error {
 public:
  Stopping() : std::runtime_error("the driver is stopping") {}
};

// How a lost device is looked for.
struct RetryPolicy {
  std::chrono::milliseconds interval{1000};        // between attempts
  std::chrono::milliseconds reopen_timeout{1000};  // to reopen a port that went away
};

class SerialDeviceDriver : public core::ThreadedDriver {
 public:
  using Clock = std::chrono::steady_clock;

  ~SerialDeviceDriver() override;

  // Opening runs a handshake: seconds, off the server's event loop.
  [[nodiscard]] bool setup_may_block() const override { return true; }
  // The link's figures (bytes_in, bytes_out, telegrams, checksum_errors,
  // resyncs, bytes_dropped, timeouts), reconnects (devices found again),
  // then protocol_counters().
  [[nodiscard]] std::vector<core::DriverCounter> counters() const final;
  bool set_byte_trace(core::ByteTrace trace) final;

 protected:
  SerialDeviceDriver(std::string port, links::SerialSettings settings, RetryPolicy retry);

  // --- the protocol
  // Brings the device up on a link just opened (or reopened, `recovering`):
  // find it, configure it, start it. Throws to fail: at setup the message
  // refuses the subscription; when recovering, it is tried again later.
  virtual void start_device(links::ByteLink& link, bool recovering) = 0;
  // One pass of the running device, after every wake-up: input on the line
  // (woke.readable), a command or request (woke.notified), or the time from
  // next_deadline(). Throws DeviceLost, links::LinkError or a
  // links::ExchangeError (no reply, refused) when the device has gone; an
  // exchange stopped by the driver's stop ends the thread quietly.
  virtual void serve(links::ByteLink& link, const core::Wakeup::Woken& woke) = 0;
  // When serve() must run next even with nothing arriving (a data timeout).
  [[nodiscard]] virtual Clock::time_point next_deadline() const = 0;
  // At shutdown while the device still answers: leave it quiet (stop its
  // stream, its motors). Failures are the driver's to log.
  virtual void stop_device(links::ByteLink& /*link*/) noexcept {}
  // The link is about to be destroyed: drop whatever refers to it.
  virtual void link_closing() noexcept {}
  // For log lines: "the SICK LMS 200 on /dev/ttyS0".
  [[nodiscard]] virtual std::string subject() const { return "the device on " + port(); }
  // Said after "... answers again" when it does (" at 38400 baud").
  [[nodiscard]] virtual std::string recovery_detail() const { return {}; }
  // The driver's figures after the link's.
  [[nodiscard]] virtual std::vector<core::DriverCounter> protocol_counters() const { return {}; }
  // How many of the link's timeouts were the driver's own looks at the line
  // (a read with a past deadline), not a device failing to answer.
  [[nodiscard]] virtual std::uint64_t own_timeouts() const { return 0; }

  // --- for the protocol
  [[nodiscard]] const std::string& port() const { return link_.port(); }
  // True from the moment the thread is asked to stop (and outside the thread).
  [[nodiscard]] bool stopping() const { return stop_.stop_requested(); }
  [[nodiscard]] bool lost() const { return lost_; }
  [[nodiscard]] const RetryPolicy& retry() const { return retry_; }

 private:
  void open() final;
  void close() final;
  void run(std::stop_token stop) final;
  void lose(const std::string& reason, bool port_gone);
  void try_to_recover();

  LinkSlot link_;
  const RetryPolicy retry_;
  const std::shared_ptr<core::Wakeup> wakeup_ = std::make_shared<core::Wakeup>();
  std::stop_token stop_;  // the thread's while it runs
  bool lost_ = false;
  bool port_gone_ = false;  // the link failed: reopen it before trying again
  Clock::time_point next_attempt_{};
  std::atomic<std::uint64_t> reconnects_{0};
};

}  // namespace playerkit::hardware_driver
