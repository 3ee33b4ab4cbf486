// The rflex drivers against an emulated B21r's RFLEX controller on a
// pseudo-terminal, 100 ms report bursts, the usual devices (position,
// sonar, power, bumper) subscribed, all in this one process:
//
//  * CPU of the connection's I/O thread (its thread CPU clock) while it only
//    follows the robot (a pair of motion reports, sonar and status each
//    100 ms: its native rate), then while commands arrive every --interval ms;
//  * latency from a velocity command written to the position device
//    (Device::put_command, as the server does) to its translation SET_DIR
//    leaving on the line (the link's trace hook, right after write()), p50
//    and p99 over --commands commands, each another speed so it is told
//    apart from the cycle's repeats.
//
//   ./build/bench/rflex_bench [--seconds 10] [--commands 300] [--interval 40]
//
// Figures only; the emulator shares the machine (its own thread).

#include <cstdint>
#include <cstdio>
#include <memory>
#include <span>
#include <string>

#include "driver_bench_support.hpp"
#include "emulators/runner/emulator_runner.hpp"
#include "families/rflex/driver/rflex_device_driver.hpp"
#include "families/rflex/emulator/rflex_emulator.hpp"
#include "protocol/binary_codec.hpp"
#include "protocol/interfaces.hpp"
#include "protocol/messages/position.hpp"

using namespace playerkit;
using namespace playerkit::bench;
using namespace std::chrono_literals;

int main(int argc, char** argv) {
  const BenchOptions options = parse_options(argc, argv, "rflex_bench", {}, 1);
  emulators::EmulatorRunner robot(std::make_unique<emulators::rflex::RflexEmulator>(), emulators::PtyEndpoint{});
  DriverRig rig("rflex_bench", "position:0 ( driver \"rflex_position\" rflex_serial_port \"" + robot.device_path() +
                                   "\" odo_distance_conversion 103 odo_angle_conversion 35000 )\n"
                                   "sonar:0 ( driver \"rflex_sonar\" num_sonar_banks 3 num_sonars_in_bank [8 8 8] )\n"
                                   "power:0 ( driver \"rflex_power\" )\n"
                                   "bumper:0 ( driver \"rflex_bumper\" bumper_count 14 rflex_done 1 )\n");
  core::Device& position = rig.device(protocol::kPositionCode);
  LineWatch watch(position);
  if (!rig.subscribe_all()) return 1;
  auto& connection = dynamic_cast<drivers::rflex::RflexDeviceDriver&>(position.driver()).connection();

  // A cycle is a pair of motion reports.
  const FollowResult follow = follow_connection(connection, options, "motion_reports", 2);

  const CommandRun run = run_commands(connection, position, watch, options, 20ms, [](int i) {
    const int speed = 20 + 10 * (i % 40);  // mm/s, never the previous one
    protocol::PositionCommand command;
    command.xspeed = speed;
    // The translation SET_DIR with this velocity (odo_distance_conversion 103).
    const std::int64_t wanted = speed * 103;
    return CommandTrial{protocol::encode(command), [wanted](std::span<const std::uint8_t> bytes,
                                                            SteadyClock::time_point) {
                          // One packet per write: 1B 02 02 00 07 0E axis v3 v2 v1 v0 ...
                          if (bytes.size() < 11 || bytes[2] != 0x02 || bytes[4] != 0x07 || bytes[6] != 0x00) return false;
                          const std::int64_t velocity =
                              (std::int64_t{bytes[7]} << 24) | (bytes[8] << 16) | (bytes[9] << 8) | bytes[10];
                          return velocity == wanted;
                        }};
  });

  rig.stop_and_shut_down(position, protocol::encode(protocol::PositionCommand{}));

  std::printf("rflex_bench: B21r RFLEX emulated on %s, 100 ms bursts; position, sonar, power, bumper subscribed\n",
              robot.device_path().c_str());
  print_follow(follow, "I/O thread");
  print_commands(run, "SET_DIR written");
  return 0;
}
