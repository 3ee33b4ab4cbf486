// The reb drivers on an emulated UBot (REB, LPRSerCom) on a pseudo-terminal,
// position, ir and power subscribed, all in this one process:
//
//  * CPU of the connection's I/O thread (its thread CPU clock) per cycle
//    (W, I,15, H,2, H,0 every 25 ms: the board's own pace is a command and
//    its reply every 2-3 ms) while it only follows the robot, then while
//    commands arrive every --interval ms;
//  * latency from a velocity command written to the position device
//    (Device::put_command, as the server does) to its `D,2,...` line leaving
//    on the link (the trace hook, right after write()), p50 and p99 over
//    --commands commands, each asking for another left-wheel speed.
//
//   ./build/bench/reb_bench [--seconds 10] [--commands 400] [--interval 15]
//
// Figures only; the emulator shares the machine (its own thread).

#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <memory>
#include <span>
#include <string>

#include "driver_bench_support.hpp"
#include "emulators/runner/emulator_runner.hpp"
#include "families/reb/driver/reb_device_driver.hpp"
#include "families/reb/emulator/reb_emulator.hpp"
#include "families/reb/protocol/reb_params.hpp"
#include "protocol/binary_codec.hpp"
#include "protocol/interfaces.hpp"
#include "protocol/messages/position.hpp"

using namespace playerkit;
using namespace playerkit::bench;
using namespace std::chrono_literals;

int main(int argc, char** argv) {
  const BenchOptions options =
      parse_options(argc, argv, "reb_bench", BenchOptions{.seconds = 10, .commands = 400, .interval_ms = 15}, 1);
  emulators::EmulatorRunner robot(std::make_unique<emulators::RebEmulator>(emulators::RebEmulatorOptions{}),
                                  emulators::PtyEndpoint{});
  // The rig's ServerClock is the wall clock: no driver here claims it.
  DriverRig rig("reb_bench", "position:0 ( driver \"reb_position\" port \"" + robot.device_path() +
                                 "\" subclass \"slow\" )\n"
                                 "ir:0 ( driver \"reb_ir\" )\n"
                                 "power:0 ( driver \"reb_power\" )\n");
  core::Device& position = rig.device(protocol::kPositionCode);
  LineWatch watch(position);
  if (!rig.subscribe_all()) return 1;
  auto& connection = dynamic_cast<drivers::reb::RebDeviceDriver&>(position.driver()).connection();
  (void)position.enqueue_request(core::Request{1, position.address(),
                                               protocol::encode(protocol::PositionPowerConfig{2, 1}), {}});

  // A cycle: a poll of the board and three publications.
  const FollowResult follow = follow_connection(connection, options, "cycles");

  const hardware::reb::RebParams& slow = hardware::reb::params_for("slow");
  const auto cycles_before = counter(connection, "cycles");
  const CommandRun run = run_commands(connection, position, watch, options, 5ms, [&slow](int i) {
    protocol::PositionCommand command;
    command.xspeed = (1 + i % 30) * 20;  // 20 ... 600 mm/s, never the previous one
    // The left motor's set-point, pulses per 10 ms, in a `D,2,v` line.
    const int wanted = hardware::reb::motor_speeds(command.xspeed, 0.0, slow).left;
    return CommandTrial{protocol::encode(command), [wanted](std::span<const std::uint8_t> bytes,
                                                            SteadyClock::time_point) {
                          const std::string text(bytes.begin(), bytes.end());
                          return text.rfind("D,2,", 0) == 0 && std::atoi(text.c_str() + 4) == wanted;
                        }};
  });
  const auto busy_cycles = counter(connection, "cycles") - cycles_before;

  rig.stop_and_shut_down(position, protocol::encode(protocol::PositionCommand{}));

  std::printf("reb_bench: UBot (slow) emulated on %s; position, ir, power subscribed\n", robot.device_path().c_str());
  print_follow(follow, "I/O thread");
  print_commands(run, "D,2 written");
  std::printf("  %llu cycles while commanded\n", static_cast<unsigned long long>(busy_cycles));
  return 0;
}
