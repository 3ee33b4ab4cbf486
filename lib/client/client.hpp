#pragma once
// A Player 1.5 client over TCP: what libplayerc and the 1.5 C++ client did,
// with timeouts and clear errors. Blocking calls, each bounded by a timeout.
//
//   auto client = client::Client::connect("localhost", 6665);
//   client.request_access({protocol::kLaserCode, 0}, protocol::Access::kRead);
//   while (auto message = client.read(1s)) { ... }      // data, SYNCH, ...
//   auto reply = client.request({protocol::kLaserCode, 0}, get_geom_bytes);
//
// Messages that arrive while a request waits for its reply (data, SYNCH, other
// replies) are kept, in order, for read(): nothing is lost.
//
// Asynchronous reading, in the manner of Asio: async_read() registers a handler
// for the next message; poll() and run_for() run the handlers on the calling
// thread. native_handle() is the socket, for select()/poll() loops that watch
// several connections. A Client is used by one thread at a time.

#include <chrono>
#include <cstdint>
#include <deque>
#include <functional>
#include <map>
#include <memory>
#include <optional>
#include <span>
#include <stdexcept>
#include <string>
#include <vector>

#include <boost/asio/io_context.hpp>
#include <boost/asio/ip/tcp.hpp>

#include "protocol/constants.hpp"
#include "protocol/device_address.hpp"
#include "protocol/frame_reader.hpp"
#include "protocol/message.hpp"

namespace playerkit::client {

using namespace std::chrono_literals;

// Connection refused or lost, not a Player server, a refused authentication.
class ClientError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

class TimeoutError : public ClientError {
 public:
  using ClientError::ClientError;
};

struct AccessGrant {
  protocol::Access access = protocol::Access::kError;
  std::string driver_name;  // empty when the device does not exist
};

struct DeviceEntry {
  protocol::DeviceAddress address;
  std::uint16_t port = 0;
  std::string driver_name;
};

class Client {
 public:
  // Connects and reads the banner. Throws ClientError (refused, unreachable,
  // no banner) or TimeoutError.
  static Client connect(const std::string& host, std::uint16_t port,
                        std::chrono::milliseconds timeout = 5s);
  Client(Client&&) noexcept;
  Client& operator=(Client&&) noexcept;
  ~Client();

  // "1.5" for Player 1.5 servers.
  [[nodiscard]] const std::string& server_version() const { return server_version_; }

  // The first message on a server started with -k. Throws ClientError when the
  // server refuses (it closes the connection).
  void authenticate(std::string_view key);
  AccessGrant request_access(protocol::DeviceAddress device, protocol::Access access);
  // Devices on this port, with their driver names.
  std::vector<DeviceEntry> device_list();
  void set_data_mode(protocol::DataMode mode);
  void set_frequency(std::uint16_t hz);
  // Pull modes: asks for one data round.
  void request_data();

  // The next message, or nullopt if none comes within `timeout`. Throws
  // ClientError when the connection is lost.
  std::optional<protocol::Message> read(std::chrono::milliseconds timeout);
  void write_command(protocol::DeviceAddress device, std::span<const std::uint8_t> payload);
  // Sends a request and returns its reply (ACK, NACK or ERR): the first reply
  // whose device and index are the request's. Throws TimeoutError.
  protocol::Message request(protocol::DeviceAddress device, std::span<const std::uint8_t> payload);

  using ReadHandler = std::function<void(protocol::Message)>;
  // Registers a handler for the next message not yet taken (handlers queue up in
  // order; a handler may call async_read again to keep reading). Handlers run
  // only inside poll() and run_for(), never inside request(), so a request in
  // progress always gets its own reply. read() takes messages before handlers do.
  void async_read(ReadHandler handler);
  // Takes what the socket already holds, without waiting, and runs the handlers
  // it satisfies. Returns how many ran. Throws ClientError on a lost connection.
  std::size_t poll();
  // Runs handlers as messages arrive, until `duration` has passed or no handler
  // is pending. Returns how many ran.
  std::size_t run_for(std::chrono::milliseconds duration);
  [[nodiscard]] std::size_t pending_handlers() const { return handlers_.size(); }
  // Messages already read from the socket and waiting here: a select()/poll()
  // loop on native_handle() must take these first, the socket will not show them.
  [[nodiscard]] std::size_t queued_messages() const { return incoming_.size(); }

  // The socket descriptor: readable when the server has sent something. -1 once closed.
  int native_handle();

  void set_timeout(std::chrono::milliseconds timeout) { timeout_ = timeout; }
  void close();

 private:
  Client();
  // Runs the io_context until `done` or the deadline; cancels what is pending
  // on timeout. Returns whether `done` became true.
  bool run_until(const bool& done, std::chrono::steady_clock::time_point deadline);
  // Reads from the socket until at least one more message is queued or the deadline.
  bool receive_more(std::chrono::steady_clock::time_point deadline);
  // Queues whatever the socket holds now, without waiting.
  void receive_available();
  void feed(std::size_t received);
  std::size_t dispatch_handlers();
  void send(const std::vector<std::uint8_t>& bytes);
  protocol::Message player_request(std::vector<std::uint8_t> payload);

  std::unique_ptr<boost::asio::io_context> io_;
  std::unique_ptr<boost::asio::ip::tcp::socket> socket_;
  std::string server_version_;
  std::chrono::milliseconds timeout_{5s};
  protocol::FrameReader reader_{kMaxReadPayload};
  struct Incoming {
    protocol::Message message;
    bool late_reply = false;  // answers a request that timed out
  };
  std::deque<Incoming> incoming_;
  std::deque<ReadHandler> handlers_;
  // Replies still owed to requests that timed out, per device: the next ones
  // to arrive must not be taken as the answer to a later request.
  std::map<protocol::DeviceAddress, std::size_t> abandoned_replies_;
  std::vector<std::uint8_t> read_buffer_;

  // Large enough for a full camera image; the server may send more than 1.5's 8160.
  static constexpr std::size_t kMaxReadPayload = 16u << 20;
};

}  // namespace playerkit::client
