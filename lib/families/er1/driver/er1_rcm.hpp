#pragma once
// Talking to the ER1's Robot Control Module over a link: one command, its
// fixed-length reply (er1.md §2), with the kit's exchange (a deadline, one
// more try, counted timeouts), and the sequences 1.5's driver sent. Unlike
// 1.5, no read waits forever and the handshake does not demand its replies
// within 1 ms.

#include <chrono>
#include <cstdint>
#include <functional>
#include <vector>

#include "families/er1/driver/er1_wheels.hpp"
#include "families/er1/protocol/er1_commands.hpp"
#include "families/er1/protocol/er1_frame_format.hpp"
#include "links/byte_link.hpp"
#include "links/exchange.hpp"
#include "links/framed_reader.hpp"

namespace playerkit::drivers::er1 {

struct WheelCounts {
  std::int32_t left = 0;  // as the wheel turns forward: the mirrored motor's count negated
  std::int32_t right = 0;
};

class Rcm {
 public:
  // `link` must outlive the RCM; `stopping` is asked while waiting.
  Rcm(links::ByteLink& link, Wiring wiring, std::function<bool()> stopping);

  // The reply to `command`. Throws links::ExchangeError (no_reply after
  // kAttempts, stopped); LinkErrors pass through.
  rcm::Bytes ask(const rcm::Bytes& command);

  // INIT to both motors, then each motor's odometry reset (er1.md §2.1).
  void start();
  // Both wheels to these speeds (mm/s) from their next EXECUTE, with 1.5's
  // speed and acceleration sequences.
  void drive(const WheelSpeeds& wheels);
  [[nodiscard]] WheelCounts counts();
  // 1.5's full stop of both motors, then both speeds 0.
  void stop();

  static constexpr std::chrono::milliseconds kReplyTimeout{250};
  static constexpr int kAttempts = 3;
  // Longer than a count's exchange takes when nothing goes wrong.
  static constexpr std::chrono::milliseconds kCountSkew{20};

 private:
  void send_all(const std::vector<rcm::Bytes>& commands);
  std::int32_t count(rcm::Motor motor);

  Wiring wiring_;
  rcm::ReplyFormat format_;
  links::FramedReader reader_;
  links::Exchanger exchanger_;
  bool standing_ = true;  // the speed sequence from standstill is the longer one
};

}  // namespace playerkit::drivers::er1
