#pragma once
// One served device: a driver plus the buffers between it and the clients.
//
//  * data: the latest sample the driver published (clients get the newest,
//    never a backlog);
//  * command: the latest command written by any client with write access
//    (commands overwrite each other, by design: no locking between clients);
//  * requests: a bounded FIFO; a full queue is refused (the server answers ERR);
//  * replies: answers on their way back to the client that asked.
//
// Subscriptions are counted across all clients and drivers: the first runs the
// driver's setup(), the last its shutdown(). A client with 'a' access holds two.
// All members are thread-safe unless noted.

#include <atomic>
#include <chrono>
#include <condition_variable>
#include <cstddef>
#include <cstdint>
#include <deque>
#include <memory>
#include <mutex>
#include <optional>
#include <span>
#include <string>
#include <thread>
#include <vector>

#include "core/clock.hpp"
#include "core/driver.hpp"
#include "core/exchange.hpp"
#include "core/logger.hpp"
#include "core/reader_progress.hpp"
#include "core/wakeup.hpp"
#include "protocol/constants.hpp"

namespace playerkit::core {

// A device is known by the port it is served on and its interface and index.
struct DeviceKey {
  std::uint16_t port = protocol::kDefaultPort;
  DeviceAddress address;

  friend auto operator<=>(const DeviceKey&, const DeviceKey&) = default;
};

// "laser:0@6665"
std::string to_string(const DeviceKey& key);

struct DeviceLimits {
  // Requests waiting for the driver. 1.5 drivers mostly used 1; a few more lets
  // several clients configure the same device without spurious ERRs.
  std::size_t request_queue = 8;
  // 0: clients get the latest sample only (sensors). N > 0: the device keeps
  // its last N samples and every client gets each one once, in order
  // (messages: comms, where a burst must not collapse into its last packet).
  std::size_t data_queue = 0;
  // 0: a command replaces the previous one (actuators: only the newest
  // matters). N > 0: up to N commands wait and take_command() hands them out
  // oldest first (messages to send); when full, the oldest is dropped.
  std::size_t command_queue = 0;
};

struct DeviceInfo {
  std::string driver_name;
  std::string robot_name;  // from robot:<port>:<name>; what NAMESERVICE matches
  protocol::Access access = protocol::Access::kAll;  // as the driver registered it
  DeviceLimits limits;
  bool alwayson = false;
};

// Told when a device has something for the server. Called from whichever
// thread published, after the device's lock is released; keep it short (post
// to an event loop).
class DeviceListener {
 public:
  virtual ~DeviceListener() = default;
  virtual void data_published(const Device& device) = 0;
  virtual void replies_ready(const Device& device) = 0;
};

class Device {
 public:
  Device(DeviceKey key, DeviceInfo info, std::unique_ptr<Driver> driver, const Clock& clock,
         Logger& logger);
  ~Device();
  Device(const Device&) = delete;
  Device& operator=(const Device&) = delete;

  [[nodiscard]] const DeviceKey& key() const { return key_; }
  [[nodiscard]] DeviceAddress address() const { return key_.address; }
  [[nodiscard]] const DeviceInfo& info() const { return info_; }
  // "laser:0@6665 (sicklms200)" for log lines.
  [[nodiscard]] std::string name() const;
  [[nodiscard]] bool readable() const;  // registered access r or a
  [[nodiscard]] bool writable() const;  // registered access w or a
  [[nodiscard]] const Clock& clock() const { return clock_; }
  [[nodiscard]] Logger& logger() const { return logger_; }
  [[nodiscard]] Driver& driver() const { return *driver_; }

  // --- subscriptions (from the server's thread or a driver's setup/shutdown)
  // Runs setup() on the first subscription. False if setup refused (logged).
  // Waits for a shutdown still under way (unsubscribe_from_event_loop()).
  bool subscribe();
  // Runs shutdown() when the last subscription goes. Extra calls are ignored.
  void unsubscribe();
  // For the server's event loop: as unsubscribe(), but when the last
  // subscription of a driver whose setup may block goes, its shutdown() runs
  // on a thread of its own (stopping a thread that waits on a remote can take
  // seconds) and this returns at once, the device counted unsubscribed.
  void unsubscribe_from_event_loop();
  // Never waits, not even for a setup() under way on another thread.
  [[nodiscard]] int subscriptions() const;
  // Shuts the driver down whatever the count (server exit).
  void force_shutdown();
  // For drivers whose resource can go away while they are set up (a remote
  // server, an unplugged port): while unavailable, further subscriptions are
  // refused (the client is granted 'e', as for a failed setup) and the ones
  // already held are kept. Every setup starts available.
  void set_available(bool available, std::string reason = {});
  [[nodiscard]] bool available() const;
  // Driver::check(): once every device exists, before anything is opened.
  void check();
  // Once before serving.
  void prepare();
  // One event-loop step for subscribed drivers without a thread of their own:
  // update(), then answer queued requests.
  void update();

  // --- data (driver side publishes, server side reads)
  void publish(std::vector<std::uint8_t> payload, Timestamp timestamp);
  void publish(std::vector<std::uint8_t> payload) { publish(std::move(payload), clock_.now()); }
  // Never null; sequence 0 until the first publish.
  [[nodiscard]] std::shared_ptr<const DataSample> latest_data() const;
  [[nodiscard]] bool queues_data() const { return info_.limits.data_queue > 0; }
  // Queued devices: the kept samples published after `sequence`, oldest first
  // (at most data_queue of them; older ones are gone).
  [[nodiscard]] std::vector<std::shared_ptr<const DataSample>> data_since(std::uint64_t sequence) const;
  // Queued devices: how far each client has taken the samples (the server
  // reports it), for publishers that must not overrun anyone. Shared, so a
  // publisher may wait on it without holding the device.
  [[nodiscard]] ReaderProgress& readers() { return *readers_; }
  [[nodiscard]] std::shared_ptr<ReaderProgress> shared_readers() { return readers_; }

  // --- commands (server side writes, driver side takes)
  enum class CommandStatus { kAccepted, kReadOnly, kWrongSize };
  // Checks the size against the interface's command struct (wire-format.md §6).
  CommandStatus put_command(ClientId client, std::span<const std::uint8_t> payload);
  // The newest command not taken yet; on a command-queue device the oldest.
  std::optional<Command> take_command();
  // The newest command, taken or not.
  [[nodiscard]] std::optional<Command> latest_command() const;

  // --- requests and replies
  enum class RequestStatus { kQueued, kQueueFull };
  RequestStatus enqueue_request(Request request);
  [[nodiscard]] std::size_t pending_requests() const;
  // Answers every queued request through the driver's handle_request(). A
  // driver that throws answers NACK. Call from the thread that owns the driver.
  void service_requests();
  // For drivers that answer later than handle_request() returns.
  void post_reply(Reply reply);
  // The replies for the server's clients (ids below kFirstDriverClient).
  std::vector<Reply> take_replies();

  // --- a driver's requests to this device (core/source_request.hpp)
  // A reply for a driver client is kept for the one awaiting it, from
  // expect_reply() to forget_reply(), and dropped when nobody awaits it.
  void expect_reply(ClientId client);
  std::optional<Reply> await_reply(ClientId client, std::chrono::steady_clock::time_point deadline);
  void forget_reply(ClientId client);

  // --- waking the driver
  // Notified after every accepted command and queued request, so that a
  // driver thread sleeping on its link serves them at once (null: nobody).
  // Set by the driver while it serves the device; the device keeps a share.
  void set_wakeup(std::shared_ptr<Wakeup> wakeup);

  // --- listeners (the server; drivers reading other devices)
  void add_listener(DeviceListener* listener);
  void remove_listener(DeviceListener* listener);

 private:
  // Calls `event` on every listener, outside every lock but the list's own
  // bookkeeping, so that listeners may call back into this device.
  void notify_listeners(void (DeviceListener::*event)(const Device&));
  [[nodiscard]] std::optional<std::string> unavailable_reason() const;
  // With subscription_mutex_ held, or on the background shutdown thread.
  void shut_driver_down();
  void finish_background_shutdown();

  const DeviceKey key_;
  const DeviceInfo info_;
  std::unique_ptr<Driver> driver_;
  const Clock& clock_;
  Logger& logger_;
  std::size_t command_min_size_ = 0;
  std::size_t command_max_size_ = 0;  // 0: the interface has no command

  // Held for the whole of setup() and shutdown(); the count is atomic so that
  // the server can look at it while another thread is in setup().
  mutable std::mutex subscription_mutex_;
  std::atomic<int> subscriptions_ = 0;
  std::thread background_shutdown_;  // unsubscribe_from_event_loop()'s, until joined

  // Not under subscription_mutex_: setup() runs holding that one and may call
  // set_available().
  mutable std::mutex availability_mutex_;
  bool available_ = true;
  std::string unavailable_reason_;

  mutable std::mutex mutex_;  // everything below
  std::shared_ptr<const DataSample> data_;
  std::deque<std::shared_ptr<const DataSample>> history_;  // queued devices only
  std::optional<Command> command_;
  bool command_taken_ = true;
  std::deque<Command> command_queue_;  // command-queue devices only
  std::deque<Request> requests_;
  std::vector<Reply> replies_;
  std::vector<ClientId> awaited_;       // driver clients waiting for a reply
  std::vector<Reply> driver_replies_;   // their replies, until taken
  std::condition_variable driver_reply_arrived_;
  std::shared_ptr<Wakeup> wakeup_;

  const std::shared_ptr<ReaderProgress> readers_ = std::make_shared<ReaderProgress>();

  mutable std::mutex listeners_mutex_;  // the three below
  std::vector<DeviceListener*> listeners_;
  std::vector<std::thread::id> notifying_threads_;  // notifications under way
  std::condition_variable notifications_done_;
};

}  // namespace playerkit::core
