// khepera_position and khepera_ir against the emulated Khepera on a
// pseudo-terminal, both subscribed, all in this one process:
//
//  * CPU of the connection's I/O thread (its thread CPU clock) per cycle
//    (D, N, H, E and the publishing) at the default 50 ms cycle_time;
//  * latency from a velocity command written to the position device
//    (Device::put_command, as the server does) to its `D,l,r` leaving on the
//    line (the link's trace hook, right after write()), p50 and p99 over
//    --commands commands, each a speed the previous one was not.
//
//   ./build/bench/khepera_bench [--seconds 10] [--commands 400] [--interval 15]
//
// Figures only; the emulator shares the machine (its own thread).

#include <algorithm>
#include <cstdint>
#include <cstdio>
#include <memory>
#include <span>
#include <string>
#include <thread>

#include "driver_bench_support.hpp"
#include "emulators/runner/emulator_runner.hpp"
#include "families/khepera/driver/khepera_device_driver.hpp"
#include "families/khepera/emulator/khepera_emulator.hpp"
#include "protocol/binary_codec.hpp"
#include "protocol/interfaces.hpp"
#include "protocol/messages/position.hpp"

using namespace playerkit;
using namespace playerkit::bench;
using namespace std::chrono_literals;

int main(int argc, char** argv) {
  const BenchOptions options =
      parse_options(argc, argv, "khepera_bench", BenchOptions{.seconds = 10, .commands = 400, .interval_ms = 15}, 1);
  emulators::EmulatorRunner robot(std::make_unique<emulators::KheperaEmulator>(), emulators::PtyEndpoint{});
  DriverRig rig("khepera_bench", "position:0 ( driver \"khepera_position\" port \"" + robot.device_path() +
                                     "\" )\nir:0 ( driver \"khepera_ir\" )\n");
  core::Device& position = rig.device(protocol::kPositionCode);
  LineWatch watch(position);
  if (!rig.subscribe_all()) return 1;
  auto& connection = dynamic_cast<drivers::khepera::KheperaDeviceDriver&>(position.driver()).connection();
  // MOTOR_POWER on, through the device's queue as a client's request goes.
  core::Request power;
  power.client = 1;
  power.device = {protocol::kPositionCode, 0};
  power.payload =
      protocol::encode(protocol::PositionPowerConfig{.request = protocol::kPositionMotorPowerReq, .value = 1});
  (void)position.enqueue_request(power);
  bool powered = false;
  for (const auto until = SteadyClock::now() + 2s; !powered && SteadyClock::now() < until;) {
    for (const core::Reply& reply : position.take_replies()) powered = reply.type == protocol::MessageType::kAck;
    if (!powered) std::this_thread::sleep_for(5ms);
  }
  if (!powered) {
    std::fprintf(stderr, "khepera_bench: MOTOR_POWER was not ACKed\n");
    return 1;
  }

  // A cycle: D, N, H, E and both devices published.
  const FollowResult follow = follow_connection(connection, options, "cycles");

  const CommandRun run = run_commands(connection, position, watch, options, 5ms, [](int i) {
    const int units = 1 + i % 40;  // 25 ... 1000 mm/s: 3 ... 120 pulses, never the previous one
    protocol::PositionCommand command;
    command.xspeed = units * 25;
    // The first `D,<left>,` written since.
    const std::string wanted = "D," + std::to_string(3 * units) + ",";
    return CommandTrial{protocol::encode(command), [wanted](std::span<const std::uint8_t> bytes,
                                                            SteadyClock::time_point) {
                          return bytes.size() >= wanted.size() && std::equal(wanted.begin(), wanted.end(), bytes.begin());
                        }};
  });

  rig.stop_and_shut_down(position, protocol::encode(protocol::PositionCommand{}));

  std::printf("khepera_bench: Khepera emulated on %s; position and ir subscribed, cycle_time 50 ms\n",
              robot.device_path().c_str());
  print_follow(follow, "I/O thread");
  print_commands(run, "D,l,r written");
  return 0;
}
