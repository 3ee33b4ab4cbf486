#pragma once
// What a driver author writes (manual chapter 8, in modern C++).
//
// A driver serves one device. The framework calls setup() when the first
// client subscribes and shutdown() when the last one leaves; in between the
// driver publishes data, reads the latest command and answers requests through
// device(). Two ways to run:
//
//  * Driver: the server calls update() from its event loop about every 10 ms
//    while the device is subscribed, then answers queued requests through
//    handle_request(). Keep update() short; it shares the loop with all clients.
//  * ThreadedDriver: run() goes in a thread of its own from setup() to
//    shutdown(), for blocking I/O (serial ports, sockets). It calls
//    device().service_requests() when it is ready to answer requests.
//
// Everything on device() is thread-safe. A request the driver does not know
// must still be answered: the default handle_request() says NACK.

#include <chrono>
#include <condition_variable>
#include <cstdint>
#include <functional>
#include <mutex>
#include <span>
#include <stdexcept>
#include <stop_token>
#include <string>
#include <thread>
#include <vector>

#include "core/exchange.hpp"

namespace playerkit::core {

class Device;
struct DeviceKey;

// Throw from setup() to refuse a subscription; the client is granted 'e' and
// the message is logged.
class DriverError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

// One named figure a driver keeps about its hardware link ("bytes_in",
// "checksum_errors", ...), for `player-drivers run --stats`.
struct DriverCounter {
  std::string name;
  std::uint64_t value = 0;
};

// Sees every byte a driver's link moves: `outgoing` is host -> device.
using ByteTrace = std::function<void(bool outgoing, std::span<const std::uint8_t> bytes,
                                     std::chrono::steady_clock::time_point when)>;

class Driver {
 public:
  Driver() = default;
  Driver(const Driver&) = delete;
  Driver& operator=(const Driver&) = delete;
  virtual ~Driver() = default;

  // Once every device is created, before anything is opened (and all that
  // `player-serve --check` runs): verify what can be verified without the
  // hardware, the network or writing anything, such as the other devices this
  // one needs. Throw DriverError; it is reported at the device's declaration.
  virtual void check() {}
  // Once, after every device is created and before the server accepts clients.
  virtual void prepare() {}
  virtual void setup() {}
  virtual void shutdown() {}
  // Event-loop drivers: one step of work, from the server's thread.
  virtual void update() {}
  // One configuration request; the reply goes back to whoever asked.
  virtual RequestResult handle_request(const Request& request);
  // True for drivers that answer requests from their own thread.
  [[nodiscard]] virtual bool runs_own_thread() const { return false; }
  // True when setup() and shutdown() may wait seconds on a link or a remote
  // (a connect timeout, a hardware handshake) and are safe to call from a
  // thread that is not the server's. The server then runs them off its event
  // loop, so that one slow device holds up only the clients that open it, and
  // answers the DEV request when setup() ends. A driver whose setup()
  // subscribes to other devices must not say so (their setup() would run on
  // that thread too): it names them in source_devices() instead.
  [[nodiscard]] virtual bool setup_may_block() const { return false; }
  // The devices setup() subscribes to (amcl's odometry and laser, writelog's
  // sources). Before a client's DEV request sets this driver up, the server
  // sets up off its event loop those of them whose setup may block, so that
  // this setup() finds them running: a passthrough laser whose remote hangs
  // holds up only the client opening amcl, not the server.
  [[nodiscard]] virtual std::vector<DeviceKey> source_devices() const;

  // Hardware drivers: their link's counters (bytes, telegrams, checksum
  // errors, resyncs, timeouts, reconnects); empty for the others.
  [[nodiscard]] virtual std::vector<DriverCounter> counters() const { return {}; }
  // Hardware drivers: report every byte of the link to `trace` (an empty
  // function stops it); false when the driver has no link. May be called
  // before setup() and from another thread.
  virtual bool set_byte_trace(ByteTrace /*trace*/) { return false; }

 protected:
  // The device this driver serves; valid from construction of the Device on.
  [[nodiscard]] Device& device() const;

 private:
  friend class Device;
  Device* device_ = nullptr;
};

class ThreadedDriver : public Driver {
 public:
  ~ThreadedDriver() override;

  void setup() final;
  void shutdown() final;
  [[nodiscard]] bool runs_own_thread() const final { return true; }

 protected:
  // Before the thread starts (open the port here; throw DriverError to refuse).
  virtual void open() {}
  // After the thread has stopped.
  virtual void close() {}
  // The thread body: loop until stop is requested.
  virtual void run(std::stop_token stop) = 0;

  // Waits up to `duration`, returning early (false) when stop is requested.
  bool sleep_for(const std::stop_token& stop, std::chrono::nanoseconds duration);

 private:
  void stop_thread();

  std::jthread thread_;
  std::mutex sleep_mutex_;
  std::condition_variable_any sleep_wakeup_;
};

}  // namespace playerkit::core
