#pragma once
// Device setups that may block (core::Driver::setup_may_block(): a connect
// timeout, a hardware handshake), run on threads of their own so that the
// event loop never waits on them: one client opening a device whose remote
// hangs must not freeze every other client (1.5 did, for as long as Setup()
// took).
//
// Each setup is a Device::subscribe() on its own thread. The subscription it
// takes, when it succeeds, belongs to whoever started it, who keeps it until
// it has taken its own and then gives it back (Device::unsubscribe_from_event_loop()).
// Several setups of one device queue on the device's lock: the first sets the
// driver up, the others only count themselves in.

#include <functional>
#include <map>
#include <thread>

#include <boost/asio/io_context.hpp>

#include "core/device.hpp"

namespace playerkit::server {

class BackgroundSetups {
 public:
  explicit BackgroundSetups(boost::asio::io_context& io) : io_(io) {}
  // Waits for the setups under way (their `done` is then never called).
  ~BackgroundSetups();
  BackgroundSetups(const BackgroundSetups&) = delete;
  BackgroundSetups& operator=(const BackgroundSetups&) = delete;

  // From the event loop: subscribes to `device` on a thread of its own, then
  // posts `done(subscribed)` to the event loop. The device must outlive it.
  void start(core::Device& device, std::function<void(bool subscribed)> done);
  // From the event loop's thread once it has stopped: waits for every setup
  // under way. Their `done` is posted; run the loop again to deliver them.
  void wait_all();
  [[nodiscard]] std::size_t under_way() const { return threads_.size(); }

 private:
  boost::asio::io_context& io_;
  // Touched by the event loop's thread only. A thread is joined by its own
  // `done` handler (it has nothing left to do but return) or by wait_all().
  std::map<unsigned long, std::thread> threads_;
  unsigned long next_id_ = 0;
};

}  // namespace playerkit::server
