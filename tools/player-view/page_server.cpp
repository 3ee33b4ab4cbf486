#include "page_server.hpp"

#include <atomic>
#include <boost/asio/ip/tcp.hpp>
#include <boost/asio/post.hpp>
#include <boost/beast/core.hpp>
#include <boost/beast/http.hpp>
#include <boost/beast/websocket.hpp>
#include <chrono>
#include <deque>
#include <mutex>
#include <optional>
#include <set>
#include <thread>
#include <utility>

namespace playerkit::player_view {

namespace asio = boost::asio;
namespace beast = boost::beast;
namespace http = beast::http;
namespace websocket = beast::websocket;
using tcp = asio::ip::tcp;

// Not an anonymous namespace: Impl, which has external linkage, holds these.
namespace page_server_detail {

using Shared = std::shared_ptr<const std::string>;

class PageSocket;

}  // namespace page_server_detail

using page_server_detail::PageSocket;

constexpr std::size_t kMaxPageMessageBytes = 4096;
using page_server_detail::Shared;

// Everything below runs on the server's one thread, except publish() and
// add_greeting(), which post their work to it, and take_events(), under its mutex. Connections hold a plain
// pointer to it: the destructor joins the thread first, and handlers still
// queued die with the io_context.
struct PageServer::Impl {
  asio::io_context io;
  tcp::acceptor acceptor{io};
  std::vector<PageAsset> assets;
  std::thread thread;
  std::set<std::shared_ptr<PageSocket>> sockets;
  std::vector<Shared> greetings;
  Shared latest;
  std::atomic<std::size_t> page_count{0};
  std::uint16_t port = 0;  // set before the thread starts, read-only after
  std::uint64_t next_page = 1;
  std::mutex events_mutex;
  std::vector<PageEvent> events;

  void note(PageEvent event) {
    const std::lock_guard lock(events_mutex);
    if (!event.closed && events.size() >= kMaxPageEvents) return;
    events.push_back(std::move(event));
  }

  void accept();
  void forget(const std::shared_ptr<PageSocket>& socket) {
    sockets.erase(socket);
    page_count = sockets.size();
  }
};

namespace page_server_detail {

// One page's WebSocket: messages that must arrive (the greeting) queue up;
// frames replace each other while one is being written.
class PageSocket : public std::enable_shared_from_this<PageSocket> {
 public:
  PageSocket(tcp::socket socket, PageServer::Impl* server)
      : ws_(std::move(socket)), server_(server), id_(server->next_page++) {}

  void start(http::request<http::string_body> request) {
    ws_.set_option(websocket::stream_base::timeout::suggested(beast::role_type::server));
    ws_.text(true);
    // A page sends short drive messages; a larger one is refused (the socket
    // closes) rather than buffered.
    ws_.read_message_max(kMaxPageMessageBytes);
    ws_.async_accept(request, [self = shared_from_this()](beast::error_code error) {
      if (error) return;
      auto& server = *self->server_;
      server.sockets.insert(self);
      server.page_count = server.sockets.size();
      for (const auto& greeting : server.greetings) self->must_send_.push_back(greeting);
      if (server.latest) self->frame_ = server.latest;
      self->write_next();
      self->read();
    });
  }

  void offer(Shared frame) {
    frame_ = std::move(frame);
    write_next();
  }

 private:
  void write_next() {
    if (writing_ || closed_) return;
    Shared next;
    if (!must_send_.empty()) {
      next = must_send_.front();
      must_send_.pop_front();
    } else if (frame_) {
      next = std::move(frame_);
      frame_.reset();
    } else {
      return;
    }
    writing_ = true;
    ws_.async_write(asio::buffer(*next), [self = shared_from_this(), next](beast::error_code error, std::size_t) {
      self->writing_ = false;
      if (error) return self->close();
      self->write_next();
    });
  }

  // What the page sends (driving) goes to take_events(); reading also
  // notices the page closing.
  void read() {
    ws_.async_read(incoming_, [self = shared_from_this()](beast::error_code error, std::size_t) {
      if (error) return self->close();
      if (self->ws_.got_text()) self->server_->note({self->id_, false, beast::buffers_to_string(self->incoming_.data())});
      self->incoming_.consume(self->incoming_.size());
      self->read();
    });
  }

  void close() {
    if (closed_) return;
    closed_ = true;
    server_->note({id_, true, {}});
    server_->forget(shared_from_this());
  }

  websocket::stream<beast::tcp_stream> ws_;
  PageServer::Impl* server_;
  std::deque<Shared> must_send_;
  Shared frame_;
  beast::flat_buffer incoming_;
  std::uint64_t id_;
  bool writing_ = false;
  bool closed_ = false;
};

// One HTTP connection: files until it asks for the WebSocket.
class HttpConnection : public std::enable_shared_from_this<HttpConnection> {
 public:
  HttpConnection(tcp::socket socket, PageServer::Impl* server)
      : stream_(std::move(socket)), server_(std::move(server)) {}

  void read() {
    request_ = {};
    stream_.expires_after(std::chrono::seconds(30));
    http::async_read(stream_, buffer_, request_, [self = shared_from_this()](beast::error_code error, std::size_t) {
      if (error) return;
      self->answer();
    });
  }

 private:
  void answer() {
    if (websocket::is_upgrade(request_)) {
      if (request_.target() == "/ws") {
        stream_.expires_never();
        std::make_shared<PageSocket>(stream_.release_socket(), server_)->start(std::move(request_));
        return;
      }
    }
    auto response = std::make_shared<http::response<http::string_body>>(http::status::not_found, request_.version());
    response->set(http::field::server, "player-view");
    response->set(http::field::content_type, "text/plain; charset=utf-8");
    response->body() = "not found\n";
    if (request_.method() != http::verb::get && request_.method() != http::verb::head) {
      response->result(http::status::method_not_allowed);
      response->body() = "only GET\n";
    } else {
      const std::string_view target(request_.target().data(), request_.target().size());
      for (const auto& asset : server_->assets) {
        if (target != asset.path) continue;
        response->result(http::status::ok);
        response->set(http::field::content_type, std::string(asset.content_type));
        response->set(http::field::cache_control, "no-store");
        response->body() = std::string(asset.body);
        break;
      }
    }
    response->keep_alive(request_.keep_alive());
    response->prepare_payload();
    http::async_write(stream_, *response, [self = shared_from_this(), response](beast::error_code error, std::size_t) {
      if (error || !response->keep_alive()) {
        beast::error_code ignored;
        self->stream_.socket().shutdown(tcp::socket::shutdown_send, ignored);
        return;
      }
      self->read();
    });
  }

  beast::tcp_stream stream_;
  PageServer::Impl* server_;
  beast::flat_buffer buffer_;
  http::request<http::string_body> request_;
};

}  // namespace page_server_detail

void PageServer::Impl::accept() {
  acceptor.async_accept([this](beast::error_code error, tcp::socket socket) {
    if (error == asio::error::operation_aborted) return;
    if (!error) std::make_shared<page_server_detail::HttpConnection>(std::move(socket), this)->read();
    accept();
  });
}

PageServer::PageServer(const std::string& address, std::uint16_t port, std::vector<PageAsset> assets)
    : impl_(std::make_unique<Impl>()) {
  impl_->assets = std::move(assets);
  beast::error_code error;
  const auto ip = asio::ip::make_address(address, error);
  if (error) throw PageServerError("'" + address + "' is not an IP address");
  const tcp::endpoint endpoint(ip, port);
  const std::string where = (ip.is_v6() ? "[" + address + "]" : address) + ":" + std::to_string(port);
  auto& acceptor = impl_->acceptor;
  acceptor.open(endpoint.protocol(), error);
  if (!error) acceptor.set_option(asio::socket_base::reuse_address(true), error);
  if (!error) acceptor.bind(endpoint, error);
  if (!error) acceptor.listen(asio::socket_base::max_listen_connections, error);
  if (error) throw PageServerError("cannot serve HTTP on " + where + ": " + error.message());
  impl_->port = acceptor.local_endpoint().port();
}

PageServer::~PageServer() {
  asio::post(impl_->io, [impl = impl_.get()] {
    beast::error_code ignored;
    impl->acceptor.close(ignored);
    impl->sockets.clear();
    impl->io.stop();
  });
  if (impl_->thread.joinable()) impl_->thread.join();
}

// The acceptor belongs to the server's thread once it runs: the port is
// kept aside rather than asked of the socket.
std::uint16_t PageServer::port() const { return impl_->port; }

void PageServer::start() {
  impl_->accept();
  impl_->thread = std::thread([impl = impl_.get()] { impl->io.run(); });
}

void PageServer::add_greeting(std::string message) {
  asio::post(impl_->io, [impl = impl_.get(), message = std::make_shared<const std::string>(std::move(message))] {
    impl->greetings.push_back(message);
  });
}

std::vector<PageEvent> PageServer::take_events() {
  const std::lock_guard lock(impl_->events_mutex);
  return std::exchange(impl_->events, {});
}

void PageServer::publish(std::string frame) {
  asio::post(impl_->io, [impl = impl_.get(), frame = std::make_shared<const std::string>(std::move(frame))] {
    impl->latest = frame;
    // A copy: a socket that fails while being offered leaves the set.
    const auto sockets = impl->sockets;
    for (const auto& socket : sockets) socket->offer(frame);
  });
}

std::size_t PageServer::pages() const { return impl_->page_count; }

}  // namespace playerkit::player_view
