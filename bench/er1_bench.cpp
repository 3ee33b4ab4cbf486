// er1_position against the emulated ER1 on a pseudo-terminal (230400 baud
// as far as a pty has one), in this one process:
//
//  * CPU of the driver's thread per cycle (its thread CPU clock, read by a
//    listener the driver calls after each publication): two position reads
//    and the odometry, 50 times a second, while the robot is only followed;
//  * latency from a velocity command written to the device
//    (Device::put_command, as the server does) to its bytes on the line
//    (the link's trace hook, right after write()): to the first command
//    of the speed sequence, and to the EXECUTE of motor 1 that sets both
//    wheels going, p50 and p99 over --commands commands. Each command asks
//    for another speed, so its bytes are told apart.
//
//   ./build/bench/er1_bench [--seconds 10] [--commands 300] [--interval 40]
//
// Figures only; the emulator shares the machine (its own thread).

#include <cstdint>
#include <cstdio>
#include <memory>
#include <optional>
#include <span>
#include <string>
#include <vector>

#include "driver_bench_support.hpp"
#include "emulators/runner/emulator_runner.hpp"
#include "families/er1/emulator/er1_emulator.hpp"
#include "families/er1/protocol/er1_commands.hpp"
#include "protocol/binary_codec.hpp"
#include "protocol/interfaces.hpp"
#include "protocol/messages/position.hpp"

namespace {

using namespace playerkit;
using namespace playerkit::bench;
using namespace std::chrono_literals;
namespace rcm = hardware::er1;

// A command's way onto the line: its first write (motor 0's status read
// that opens the sequence), then motor 1's EXECUTE once motor 1's velocity
// register took the value awaited. Only the matcher touches it, under the
// watch's lock.
struct Er1Sequence {
  std::int32_t wanted = 0;  // motor 1's speed register
  bool value_sent = false;
  std::optional<SteadyClock::time_point> first_write;

  bool on_line(std::span<const std::uint8_t> bytes, SteadyClock::time_point when) {
    if (bytes.size() < 4) return false;
    if (!first_write && bytes[0] == 0 && bytes[3] == rcm::opcode::read_status) first_write = when;
    if (bytes[0] == 1 && bytes[3] == rcm::opcode::velocity && bytes.size() == 8) {
      const auto value = static_cast<std::int32_t>((std::uint32_t{bytes[4]} << 24) | (std::uint32_t{bytes[5]} << 16) |
                                                   (std::uint32_t{bytes[6]} << 8) | bytes[7]);
      value_sent = value == wanted;
    }
    return value_sent && bytes[0] == 1 && bytes[3] == rcm::opcode::execute;
  }
};

}  // namespace

int main(int argc, char** argv) {
  const BenchOptions options = parse_options(argc, argv, "er1_bench");
  emulators::EmulatorRunner robot(std::make_unique<emulators::Er1Emulator>(), emulators::PtyEndpoint{});
  DriverRig rig("er1_bench", "position:0 ( driver \"er1_position\" port \"" + robot.device_path() + "\" )\n");
  core::Device& position = rig.device(protocol::kPositionCode);
  LineWatch watch(position);
  PublishRecorder recorder(position);
  if (!rig.subscribe_all()) return 1;

  const FollowResult follow = follow_publications(recorder, options);

  Er1Sequence sequence;
  std::vector<double> to_first_write;
  const CommandRun run = run_commands(
      position, watch, options, 20ms,
      [&sequence](int i) {
        protocol::PositionCommand command;
        command.xspeed = 10 + 10 * (i % 40);  // 10 ... 400 mm/s, never the previous one
        sequence = Er1Sequence{};
        sequence.wanted = rcm::speed_register(command.xspeed);
        return CommandTrial{protocol::encode(command), [&sequence](std::span<const std::uint8_t> bytes,
                                                                   SteadyClock::time_point when) {
                              return sequence.on_line(bytes, when);
                            }};
      },
      [&](SteadyClock::time_point sent) {
        if (sequence.first_write) to_first_write.push_back(milliseconds(*sequence.first_write - sent));
      });
  rig.stop_and_shut_down(position, protocol::encode(protocol::PositionCommand{}));

  std::printf("er1_bench: ER1 emulated on %s, odometry read every 20 ms\n", robot.device_path().c_str());
  print_follow(follow, "driver thread");
  print_commands(run, "motor 1's EXECUTE written");
  print_latency("first byte on the line", to_first_write, run.missed);
  return 0;
}
