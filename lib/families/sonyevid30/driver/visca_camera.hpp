#pragma once
// Talking VISCA to one camera over a link (sonyevid30.md §1.1, §2.2) with
// the kit's exchange: a command waits for its ACK and notes the socket it
// runs in until its completion comes; an inquiry waits for its `90 50`
// answer; completions and late errors arriving meanwhile are matched to
// their sockets. Every wait has a deadline (1.5 waited forever), an error
// packet is a refusal naming the command and the camera's reason, and a
// full command buffer is met by cancelling the socket the new command would
// replace, once.

#include <array>
#include <chrono>
#include <cstdint>
#include <functional>
#include <optional>
#include <string>

#include "families/sonyevid30/protocol/visca.hpp"
#include "framing/terminated_packet_format.hpp"
#include "links/byte_link.hpp"
#include "links/exchange.hpp"
#include "links/framed_reader.hpp"

namespace playerkit::drivers::sonyevid30 {

namespace visca = hardware::sonyevid30;

// What a command sets going, so that a new one knows which socket it replaces.
enum class Function { pan_tilt, zoom, other };

class ViscaCamera {
 public:
  // `link` must outlive the camera; `stopping` is asked while waiting;
  // `warn` gets one line per error packet no exchange was waiting for.
  ViscaCamera(links::ByteLink& link, std::function<bool()> stopping, std::function<void(const std::string&)> warn);

  // The socket the camera runs `packet` in. Throws links::ExchangeError:
  // no_reply, stopped, or refused (an error packet; the message names it).
  int command(const visca::Bytes& packet, const std::string& name, Function function);
  // The answer (`90 50 ... FF`, whole); `valid` judges its data (a garbled
  // answer is not the answer). Throws as command() does.
  visca::Bytes inquire(const visca::Bytes& packet, const std::string& name,
                       const std::function<bool(const visca::Reply&)>& valid,
                       std::chrono::milliseconds timeout = kReplyTimeout);
  // Cancels what socket 1 or 2 runs; true when something was cancelled.
  bool cancel(int socket);
  // Takes what arrived unasked: completions free their sockets, error packets are warned of.
  void take_pending();

  [[nodiscard]] bool busy(int socket) const { return sockets_[socket - 1].has_value(); }
  [[nodiscard]] std::uint64_t completions() const { return completions_; }
  [[nodiscard]] std::uint64_t cancelled() const { return cancelled_; }
  [[nodiscard]] std::uint64_t late_errors() const { return late_errors_; }

  // The camera answers at once; a reply later than this is a lost one.
  static constexpr std::chrono::milliseconds kReplyTimeout{500};
  static constexpr int kAttempts = 3;

 private:
  // A completion or a late error: true when `reply` was one (and noted).
  bool note(const visca::Reply& reply);
  int send_command(const visca::Bytes& packet, const std::string& name, Function function);

  framing::TerminatedPacketFormat format_;
  links::FramedReader reader_;
  links::Exchanger exchanger_;
  std::function<void(const std::string&)> warn_;
  std::array<std::optional<Function>, 2> sockets_{};
  std::uint64_t completions_ = 0;
  std::uint64_t cancelled_ = 0;
  std::uint64_t late_errors_ = 0;
};

}  // namespace playerkit::drivers::sonyevid30
