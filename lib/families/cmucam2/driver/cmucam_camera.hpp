#pragma once
// Talking to a CMUcam2 over a link, one exchange per command (cmucam2.md
// §2): `ACK` CR, any data lines, the prompt `:`. Unlike the 1.5 driver, no
// read waits forever, a refusal is an answer, and a T packet is read whether
// or not the camera puts a prompt after it (§6.6 allows both): the CR that
// returns the camera to idle is matched by its own `ACK` and prompt.

#include <chrono>
#include <functional>
#include <string>

#include "families/cmucam2/protocol/cmucam_protocol.hpp"
#include "framing/terminated_line_format.hpp"
#include "links/byte_link.hpp"
#include "links/exchange.hpp"
#include "links/framed_reader.hpp"

namespace playerkit::drivers::cmucam2 {

namespace cam = hardware::cmucam2;

class CmucamCamera {
 public:
  // `link` must outlive the camera; `stopping` is asked while waiting.
  CmucamCamera(links::ByteLink& link, std::function<bool()> stopping);

  // Each throws links::ExchangeError: no_reply when the camera stays silent
  // (after kAttempts), refused for its NCK. LinkErrors pass through.
  void command(const std::string& text);
  // The one data line a query (GS, GV) answers with, of those `accept` takes.
  std::string query(const std::string& text, std::function<bool(std::string_view)> accept);
  // One poll-mode T packet of `bounds`, the camera left idle.
  cam::TPacket track(const cam::ColorBounds& bounds);

  // The lone CR that ends streaming and leaves the camera idle.
  void idle() { command(""); }

  static constexpr std::chrono::milliseconds kReplyTimeout{300};
  static constexpr int kAttempts = 3;

 private:
  framing::TerminatedLineFormat format_;
  links::FramedReader reader_;
  links::Exchanger exchanger_;
};

}  // namespace playerkit::drivers::cmucam2
