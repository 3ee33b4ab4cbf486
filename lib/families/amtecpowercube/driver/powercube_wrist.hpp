#pragma once
// Talking to the wrist's two modules over a link: one frame, one reply
// frame from the module addressed (amtecpowercube.md §2), with the kit's
// exchange (a deadline, retries, counted timeouts), and the start-up 1.5's
// driver did: both modules found, reset, homed one after the other. Unlike
// 1.5, no read and no homing waits forever, and a reply must come from the
// module asked and echo the command it answers.

#include <array>
#include <chrono>
#include <cstdint>
#include <functional>
#include <vector>

#include "families/amtecpowercube/protocol/powercube_frames.hpp"
#include "framing/dle_stuffed_format.hpp"
#include "links/byte_link.hpp"
#include "links/exchange.hpp"
#include "links/framed_reader.hpp"

namespace playerkit::drivers::amtecpowercube {

namespace pc = hardware::powercube;

// A module's position limits as it reports them, degrees (module convention).
struct ModuleReach {
  double min = 0;
  double max = 0;
  // Limits with min >= max are no limits (a module that reports none).
  [[nodiscard]] double clamp(double degrees) const;
};

class PowercubeWrist {
 public:
  // `link` must outlive the wrist; `stopping` is asked while waiting.
  PowercubeWrist(links::ByteLink& link, std::function<bool()> stopping);

  // The module's reply to `data`. Throws links::ExchangeError (no_reply
  // after kAttempts, stopped); LinkErrors pass through.
  pc::Frame ask(pc::Module module, const std::vector<std::uint8_t>& data);

  [[nodiscard]] float read_float(pc::Module module, pc::Parameter parameter);
  [[nodiscard]] std::uint32_t read_state(pc::Module module);

  // Each module answers its position, or an ExchangeError names the one
  // that does not; its limits are read; then both are reset and homed (pan
  // first, as 1.5 did). The reach of pan and tilt, in that order.
  std::array<ModuleReach, 2> start();
  // Homes one module and waits for its homed bit (std::runtime_error after kHomingTimeout).
  void home(pc::Module module);
  void halt(pc::Module module) { ask(module, pc::halt_data()); }
  void step(pc::Module module, float radians, std::uint16_t milliseconds) {
    ask(module, pc::step_data(radians, milliseconds));
  }
  void velocity(pc::Module module, float radians_per_second) { ask(module, pc::velocity_data(radians_per_second)); }

  static constexpr std::chrono::milliseconds kReplyTimeout{200};
  // Sends of one frame before the module counts as gone: a reply lost to
  // line noise is asked for again (every command here may be repeated).
  static constexpr int kAttempts = 5;
  // The longest homing: half a turn at a slow module's speed.
  static constexpr std::chrono::milliseconds kHomingTimeout{30000};
  // How often the homed bit is asked for (1.5's 20 ms).
  static constexpr std::chrono::milliseconds kHomingPoll{20};

 private:
  framing::DleStuffedFormat format_;
  links::FramedReader reader_;
  links::Exchanger exchanger_;
};

[[nodiscard]] const char* module_name(pc::Module module);

}  // namespace playerkit::drivers::amtecpowercube
