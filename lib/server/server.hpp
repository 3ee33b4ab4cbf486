#pragma once
// The Player 1.5 TCP server: listens on the ports of a device table, greets
// every client with the banner, and serves it the devices of the port it came
// in on (server-behaviour.md). One event-loop thread does all socket work;
// drivers with threads of their own meet it only through core::Device.
//
//   core::DeviceTable devices;              // filled from a config file
//   server::Server server(devices, clock, logger, options);
//   server.listen(6665);                    // before run(); port 0 picks one
//   server.stop_on_signals();               // SIGINT, SIGTERM, SIGHUP
//   server.run();                           // until stop()
//
// Devices may be added to the table after listen() and before run() (a server
// asked for port 0 learns its real port only from listen()).

#include <atomic>
#include <cstdint>
#include <map>
#include <memory>
#include <stdexcept>
#include <vector>

#include <boost/asio/io_context.hpp>
#include <boost/asio/ip/tcp.hpp>
#include <boost/asio/signal_set.hpp>
#include <boost/asio/steady_timer.hpp>

#include "core/clock.hpp"
#include "core/device_table.hpp"
#include "core/logger.hpp"
#include "server/background_setups.hpp"
#include "server/client_session.hpp"
#include "server/push_schedule.hpp"
#include "server/server_options.hpp"

namespace playerkit::server {

class ServerError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

class Server final : private core::DeviceListener {
 public:
  Server(core::DeviceTable& devices, const core::Clock& clock, core::Logger& logger,
         ServerOptions options = {});
  ~Server() override;
  Server(const Server&) = delete;
  Server& operator=(const Server&) = delete;

  // Opens a listening socket; returns the port actually bound. Throws
  // ServerError ("port 6665 is already in use").
  std::uint16_t listen(std::uint16_t port);
  // Ends run() on SIGINT, SIGTERM or SIGHUP, logging which one.
  void stop_on_signals();

  // Serves until stop(). Closing clients releases their devices; shutting down
  // the devices themselves is up to the caller (DeviceTable::shutdown_all()).
  void run();
  // From any thread (or a signal handler via stop_on_signals()).
  void stop();

  [[nodiscard]] std::size_t client_count() const { return client_count_.load(); }
  [[nodiscard]] std::vector<std::uint16_t> ports() const;

 private:
  struct Listener {
    std::uint16_t port;
    boost::asio::ip::tcp::acceptor acceptor;
  };

  void accept_next(Listener& listener);
  void schedule_update();
  void schedule_stall_check();
  void close_everything(const std::string& reason);

  // core::DeviceListener, called from any thread.
  void data_published(const core::Device& device) override;
  void replies_ready(const core::Device& device) override;
  void route_replies(core::Device& device);

  core::DeviceTable& devices_;
  const core::Clock& clock_;
  core::Logger& logger_;
  ServerOptions options_;

  boost::asio::io_context io_;
  BackgroundSetups setups_{io_};  // before the sessions whose DEV replies wait on them
  PushSchedule push_schedule_{io_.get_executor()};  // outlives the sessions it calls
  std::vector<std::unique_ptr<Listener>> listeners_;
  std::map<core::ClientId, std::shared_ptr<ClientSession>> sessions_;
  core::ClientId next_client_id_ = 1;
  std::atomic<std::size_t> client_count_{0};
  boost::asio::steady_timer update_timer_;
  boost::asio::steady_timer stall_timer_;
  std::unique_ptr<boost::asio::signal_set> signals_;
  std::vector<core::Device*> listened_devices_;
  bool stopping_ = false;
};

}  // namespace playerkit::server
