#include "server/server.hpp"

#include <boost/asio/post.hpp>

namespace playerkit::server {

namespace asio = boost::asio;
using asio::ip::tcp;

Server::Server(core::DeviceTable& devices, const core::Clock& clock, core::Logger& logger,
               ServerOptions options)
    : devices_(devices),
      clock_(clock),
      logger_(logger),
      options_(std::move(options)),
      update_timer_(io_),
      stall_timer_(io_) {}

Server::~Server() {
  for (core::Device* device : listened_devices_) device->remove_listener(this);
}

std::uint16_t Server::listen(std::uint16_t port) {
  boost::system::error_code ec;
  const auto address = asio::ip::make_address(options_.bind_address, ec);
  if (ec) throw ServerError("cannot listen on '" + options_.bind_address + "': not an IP address");
  auto listener = std::make_unique<Listener>(Listener{port, tcp::acceptor(io_)});
  tcp::acceptor& acceptor = listener->acceptor;
  const tcp::endpoint endpoint(address, port);
  acceptor.open(endpoint.protocol(), ec);
  if (!ec) acceptor.set_option(tcp::acceptor::reuse_address(true), ec);
  if (!ec) acceptor.bind(endpoint, ec);
  if (!ec) acceptor.listen(200, ec);  // 1.5's backlog
  if (ec) {
    const std::string where = options_.bind_address + ":" + std::to_string(port);
    if (ec == asio::error::address_in_use) {
      throw ServerError("port " + std::to_string(port) + " is already in use (" + where + ")");
    }
    throw ServerError("cannot listen on " + where + ": " + ec.message());
  }
  listener->port = acceptor.local_endpoint().port();
  logger_.info("listening on port " + std::to_string(listener->port));
  listeners_.push_back(std::move(listener));
  return listeners_.back()->port;
}

std::vector<std::uint16_t> Server::ports() const {
  std::vector<std::uint16_t> ports;
  for (const auto& listener : listeners_) ports.push_back(listener->port);
  return ports;
}

void Server::stop_on_signals() {
  signals_ = std::make_unique<asio::signal_set>(io_, SIGINT, SIGTERM, SIGHUP);
  signals_->async_wait([this](const boost::system::error_code& ec, int signal) {
    if (ec) return;
    logger_.info(std::string("received ") + (signal == SIGINT    ? "SIGINT"
                                             : signal == SIGTERM ? "SIGTERM"
                                                                 : "SIGHUP") +
                 ", shutting down");
    close_everything("server shutting down");
  });
}

void Server::run() {
  for (core::Device* device : devices_.all()) {
    device->add_listener(this);
    listened_devices_.push_back(device);
  }
  for (auto& listener : listeners_) accept_next(*listener);
  schedule_update();
  schedule_stall_check();
  io_.run();
  // Setups still under way post their results: wait for them and deliver
  // them to their (closed) sessions, which give their subscriptions back.
  setups_.wait_all();
  io_.restart();
  io_.poll();
}

void Server::stop() {
  asio::post(io_, [this] { close_everything("server stopped"); });
}

void Server::close_everything(const std::string& reason) {
  if (stopping_) return;
  stopping_ = true;
  for (auto& listener : listeners_) {
    boost::system::error_code ignored;
    listener->acceptor.close(ignored);
  }
  // Copy: closing a session erases it from the map.
  auto sessions = sessions_;
  for (auto& [id, session] : sessions) session->close(reason);
  update_timer_.cancel();
  stall_timer_.cancel();
  push_schedule_.clear();
  if (signals_) signals_->cancel();
  io_.stop();
}

void Server::accept_next(Listener& listener) {
  listener.acceptor.async_accept([this, &listener](const boost::system::error_code& ec,
                                                   tcp::socket socket) {
    if (stopping_) return;
    if (ec) {
      // Out of descriptors and the like: say so, keep serving the others.
      logger_.warning("accept on port " + std::to_string(listener.port) + " failed: " + ec.message());
    } else {
      const core::ClientId id = next_client_id_++;
      auto session = std::make_shared<ClientSession>(
          std::move(socket), id, listener.port,
          SessionContext{devices_, clock_, logger_, options_, push_schedule_,
                         [this](core::ClientId closed) {
                           sessions_.erase(closed);
                           client_count_.store(sessions_.size());
                         },
                         [this](core::Device& device, std::function<void(bool)> done) {
                           setups_.start(device, std::move(done));
                         }});
      sessions_.emplace(id, session);
      client_count_.store(sessions_.size());
      session->start();
    }
    accept_next(listener);
  });
}

void Server::schedule_update() {
  update_timer_.expires_after(options_.update_period);
  update_timer_.async_wait([this](const boost::system::error_code& ec) {
    if (ec || stopping_) return;
    for (core::Device* device : devices_.all()) {
      if (device->subscriptions() > 0) device->update();
    }
    schedule_update();
  });
}

void Server::schedule_stall_check() {
  stall_timer_.expires_after(std::chrono::milliseconds(100));
  stall_timer_.async_wait([this](const boost::system::error_code& ec) {
    if (ec || stopping_) return;
    const auto now = std::chrono::steady_clock::now();
    auto sessions = sessions_;
    for (auto& [id, session] : sessions) session->check_stalled(now);
    schedule_stall_check();
  });
}

void Server::data_published(const core::Device& /*device*/) {
  // Clients pull data on their own schedule (data rounds); nothing to do.
}

void Server::replies_ready(const core::Device& device) {
  // Any thread: hop onto the event loop. The table outlives run(), so the
  // pointer stays good.
  auto* target = const_cast<core::Device*>(&device);
  asio::post(io_, [this, target] { route_replies(*target); });
}

void Server::route_replies(core::Device& device) {
  for (const core::Reply& reply : device.take_replies()) {
    const auto it = sessions_.find(reply.client);
    if (it == sessions_.end()) {
      logger_.debug(device.name() + ": reply for client " + std::to_string(reply.client) +
                    ", who has gone");
      continue;
    }
    it->second->deliver_reply(reply);
  }
}

}  // namespace playerkit::server
