// The p2os drivers against an emulated Pioneer 3-DX on a pseudo-terminal,
// 10 Hz SIPs, every device of a usual robot (position, sonar, power, bumper)
// subscribed, all in this one process:
//
//  * CPU of the connection's I/O thread (its thread CPU clock) while it
//    only follows the robot, then while commands arrive every --interval ms;
//  * latency from a velocity command written to the position device
//    (Device::put_command, as the server does) to its VEL2 bytes leaving on
//    the line (the link's trace hook, which runs right after write()), p50
//    and p99 over --commands commands. Each command asks for another wheel
//    speed, so its VEL2 is told apart from the keep-alive repeats.
//
//   ./build/bench/p2os_bench [--seconds 10] [--commands 400] [--interval 15]
//
// Figures only; the emulator shares the machine (its own thread).

#include <cstdint>
#include <cstdio>
#include <memory>
#include <span>
#include <string>

#include "driver_bench_support.hpp"
#include "emulators/runner/emulator_runner.hpp"
#include "families/p2os/driver/p2os_device_driver.hpp"
#include "families/p2os/emulator/p2os_robot_emulator.hpp"
#include "protocol/binary_codec.hpp"
#include "protocol/interfaces.hpp"
#include "protocol/messages/position.hpp"

using namespace playerkit;
using namespace playerkit::bench;
using namespace std::chrono_literals;

int main(int argc, char** argv) {
  const BenchOptions options =
      parse_options(argc, argv, "p2os_bench", BenchOptions{.seconds = 10, .commands = 400, .interval_ms = 15}, 1);

  emulators::P2osEmulatorOptions robot_options;
  robot_options.subclass = "p3dx";
  emulators::EmulatorRunner robot(std::make_unique<emulators::P2osRobotEmulator>(robot_options),
                                  emulators::PtyEndpoint{});
  // The rig's ServerClock is the wall clock: no driver here claims it.
  DriverRig rig("p2os_bench", "position:0 ( driver \"p2os_position\" port \"" + robot.device_path() +
                                  "\" max_xspeed 900 )\n"
                                  "sonar:0 ( driver \"p2os_sonar\" )\n"
                                  "power:0 ( driver \"p2os_power\" )\n"
                                  "bumper:0 ( driver \"p2os_bumper\" )\n");
  core::Device& position = rig.device(protocol::kPositionCode);
  LineWatch watch(position);
  if (!rig.subscribe_all()) return 1;
  auto& connection = dynamic_cast<drivers::p2os::P2osDeviceDriver&>(position.driver()).connection();

  // SIPs in, four devices published, keep-alives out.
  const FollowResult follow = follow_connection(connection, options, "sips");

  // Random phases matter here: a fixed interval would lock onto a polling
  // loop's slice, as onto the 5 ms one the I/O thread had until 2026-12-07.
  const CommandRun run = run_commands(connection, position, watch, options, 5ms, [](int i) {
    const int units = 1 + i % 40;  // 20 ... 800 mm/s, never the previous one
    protocol::PositionCommand command;
    command.xspeed = units * 20;
    // The right-wheel byte of a VEL2, so it is told from the keep-alive repeats.
    return CommandTrial{protocol::encode(command), [units](std::span<const std::uint8_t> bytes,
                                                           SteadyClock::time_point) {
                          // One frame per write: FA FB 06 20 3B right left chk chk.
                          return bytes.size() >= 7 && bytes[3] == 0x20 && bytes[5] == units;
                        }};
  });

  rig.stop_and_shut_down(position, protocol::encode(protocol::PositionCommand{}));

  std::printf("p2os_bench: Pioneer p3dx emulated on %s, 10 Hz SIPs; position, sonar, power, bumper subscribed\n",
              robot.device_path().c_str());
  print_follow(follow, "I/O thread", "SIP");
  print_commands(run, "VEL2 written");
  return 0;
}
