// rmpposition against the emulated Segway RMP behind an slcan adapter on a
// pseudo-terminal, in this one process:
//
//  * CPU of the driver's I/O thread per cycle (its thread CPU clock, read by
//    a listener the driver calls at each publication): one status set of
//    five slcan frames parsed, the odometry, a publication and one 0x413
//    velocity frame written, 100 times a second (the RMP's native rate);
//  * latency from a velocity command written to the device
//    (Device::put_command, as the server does) to the 0x413 frame carrying
//    it on the line (the link's trace hook, right after write()), p50 and
//    p99 over --commands commands. Each command asks for another speed, so
//    its frame is told apart. The driver answers each status set, as 1.5
//    did, so up to one period (10 ms) of this is the bus's pace.
//
//   ./build/bench/segwayrmp_bench [--seconds 10] [--commands 300] [--interval 40]
//
// Figures only; the emulator shares the machine (its own thread).

#include <cstdint>
#include <cstdio>
#include <memory>
#include <span>
#include <string>
#include <string_view>
#include <thread>

#include "driver_bench_support.hpp"
#include "emulators/runner/emulator_runner.hpp"
#include "families/segwayrmp/emulator/segwayrmp_emulator.hpp"
#include "families/segwayrmp/protocol/rmp_frames.hpp"
#include "links/can/slcan.hpp"
#include "protocol/binary_codec.hpp"
#include "protocol/interfaces.hpp"
#include "protocol/messages/position.hpp"

namespace {

using namespace playerkit;
using namespace playerkit::bench;
using namespace std::chrono_literals;
namespace rmp = hardware::segwayrmp;

// The RMP ignores velocity until its motors are enabled, as a client would.
bool enable_motors(core::Device& position) {
  (void)position.take_replies();
  const auto payload = protocol::encode(protocol::PositionPowerConfig{protocol::kPositionMotorPowerReq, 1});
  if (position.enqueue_request(core::Request{1, position.address(), payload, {}}) !=
      core::Device::RequestStatus::kQueued) {
    return false;
  }
  const auto give_up = SteadyClock::now() + 5s;
  while (SteadyClock::now() < give_up) {
    for (const core::Reply& reply : position.take_replies()) return reply.type == protocol::MessageType::kAck;
    std::this_thread::sleep_for(5ms);
  }
  return false;
}

}  // namespace

int main(int argc, char** argv) {
  const BenchOptions options = parse_options(argc, argv, "segwayrmp_bench");
  emulators::EmulatorRunner robot(std::make_unique<emulators::SegwayRmpEmulator>(), emulators::PtyEndpoint{});
  DriverRig rig("segwayrmp_bench", "position:0 ( driver \"rmpposition\" canio \"slcan\" port \"" +
                                       robot.device_path() + "\" max_xspeed 1000 command_timeout 1 )\n");
  core::Device& position = rig.device(protocol::kPositionCode);
  LineWatch watch(position);
  PublishRecorder recorder(position);
  if (!position.subscribe() || !enable_motors(position)) {
    std::fprintf(stderr, "segwayrmp_bench: the driver did not set up\n");
    return 1;
  }

  const FollowResult follow = follow_publications(recorder, options);

  const CommandRun run = run_commands(position, watch, options, 20ms, [](int i) {
    protocol::PositionCommand command;
    command.xspeed = 10 + 10 * (i % 40);  // 10 ... 400 mm/s, never the previous one
    // The first 0x413 line carrying this translation.
    const std::int16_t wanted = rmp::trans_counts(command.xspeed);
    return CommandTrial{protocol::encode(command), [wanted](std::span<const std::uint8_t> bytes,
                                                            SteadyClock::time_point) {
                          const std::string_view text(reinterpret_cast<const char*>(bytes.data()), bytes.size());
                          const auto frame = links::can::parse_slcan_frame(text.substr(0, text.find('\r')));
                          if (!frame) return false;
                          const auto sent = rmp::parse_command(*frame);
                          return sent && sent->trans == wanted;
                        }};
  });
  rig.stop_and_shut_down(position, protocol::encode(protocol::PositionCommand{}));

  std::printf("segwayrmp_bench: Segway RMP emulated behind slcan on %s, status sets at 100 Hz\n",
              robot.device_path().c_str());
  print_follow(follow, "I/O thread");
  print_commands(run, "its 0x413 frame written");
  return 0;
}
