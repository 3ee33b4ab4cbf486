// trogdor against the emulated O-Bot on a pseudo-terminal, in this one
// process:
//
//  * CPU of the driver's thread per cycle (its thread CPU clock at each
//    publication): one GET_ODOM exchange and the odometry, every 15 ms,
//    while the robot is only followed;
//  * latency from a velocity command written to the device
//    (Device::put_command, as the server does) to its SET_VELOCITIES on the
//    line (the link's trace hook, right after write()), p50 and p99 over
//    --commands commands, each asking for other wheel units.
//
//   ./build/bench/trogdor_bench [--seconds 10] [--commands 300] [--interval 40]
//
// Figures only; the emulator shares the machine (its own thread).

#include <algorithm>
#include <cstdint>
#include <cstdio>
#include <memory>
#include <span>
#include <string>

#include "driver_bench_support.hpp"
#include "emulators/runner/emulator_runner.hpp"
#include "families/trogdor/emulator/trogdor_emulator.hpp"
#include "families/trogdor/protocol/trogdor_messages.hpp"
#include "families/trogdor/protocol/trogdor_units.hpp"
#include "protocol/binary_codec.hpp"
#include "protocol/interfaces.hpp"
#include "protocol/messages/position.hpp"

using namespace playerkit;
using namespace playerkit::bench;
using namespace std::chrono_literals;
namespace hw = hardware::trogdor;

int main(int argc, char** argv) {
  const BenchOptions options = parse_options(argc, argv, "trogdor_bench");
  emulators::EmulatorRunner robot(std::make_unique<emulators::TrogdorEmulator>(emulators::TrogdorEmulatorOptions{}, nullptr),
                                  emulators::PtyEndpoint{});
  DriverRig rig("trogdor_bench", "position:0 ( driver \"trogdor\" port \"" + robot.device_path() + "\" )\n");
  core::Device& position = rig.device(protocol::kPositionCode);
  LineWatch watch(position);
  PublishRecorder recorder(position);
  if (!rig.subscribe_all()) return 1;

  const FollowResult follow = follow_publications(recorder, options);

  // The phases spread over one 15 ms cycle.
  const CommandRun run = run_commands(position, watch, options, 15ms, [](int i) {
    protocol::PositionCommand command;
    command.xspeed = 100 + 40 * (i % 10);  // 100 ... 460 mm/s: 7 ... 30 units, never the previous ones
    // One SET_VELOCITIES per write, byte for byte the one these units make.
    hw::Bytes wanted = hw::set_velocities(hw::wheel_units_for(command.xspeed, 0));
    return CommandTrial{protocol::encode(command),
                        [wanted = std::move(wanted)](std::span<const std::uint8_t> bytes, SteadyClock::time_point) {
                          return std::equal(bytes.begin(), bytes.end(), wanted.begin(), wanted.end());
                        }};
  });
  position.unsubscribe();

  print_follow(follow, "driver thread");
  print_commands(run, "SET_VELOCITIES on the line");
  return run.missed == 0 ? 0 : 1;
}
