#pragma once
// The live page's web server: serves the embedded page over HTTP and sends
// the scene to every open page over a WebSocket. Boost.Beast stays inside
// page_server.cpp (the costliest file of the tool to compile); this header
// is plain C++.
//
// One thread of its own runs the sockets. publish() may be called from any
// thread: every page gets the frame, but a page that is still sending an
// earlier one keeps only the newest waiting (one frame in flight, one
// waiting), so a slow tab never holds up the others or grows a queue.

#include <cstdint>
#include <memory>
#include <stdexcept>
#include <string>
#include <string_view>
#include <vector>

namespace playerkit::player_view {

struct PageAsset {
  std::string_view path;          // "/", "/view.js"
  std::string_view content_type;  // "text/html; charset=utf-8"
  std::string_view body;
};

// The page's files, embedded at build time (page_assets.cpp is generated
// from tools/player-view/page/).
const std::vector<PageAsset>& page_assets();

// What a page said (a WebSocket text message) or that it closed.
struct PageEvent {
  std::uint64_t page = 0;  // numbered from 1 as pages open
  bool closed = false;
  std::string text;
};

// Page messages kept for take_events() at most; beyond, new messages are
// dropped (closings never are), so a page sending without end cannot grow
// the tool's memory.
inline constexpr std::size_t kMaxPageEvents = 256;

// The address is not an IP address, or the port cannot be listened on.
class PageServerError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

class PageServer {
 public:
  // Listens at once (port 0: a free port, see port()); throws PageServerError
  // naming the address and the reason ("address already in use").
  PageServer(const std::string& address, std::uint16_t port, std::vector<PageAsset> assets);
  ~PageServer();
  PageServer(const PageServer&) = delete;
  PageServer& operator=(const PageServer&) = delete;

  [[nodiscard]] std::uint16_t port() const;
  // Starts the server's thread.
  void start();
  // A first message of every page from now on (the map), never dropped;
  // greetings go in the order they were added.
  void add_greeting(std::string message);
  // The newest frame, for every page.
  void publish(std::string frame);
  // Pages open now.
  [[nodiscard]] std::size_t pages() const;
  // The pages' messages and closings since the last call, oldest first.
  std::vector<PageEvent> take_events();

  struct Impl;  // page_server.cpp's; public so its connection classes can name it

 private:
  std::unique_ptr<Impl> impl_;
};

}  // namespace playerkit::player_view
