// The nomad driver against the emulated Nomad 200 behind its server on a
// loopback TCP port, in this one process:
//
//  * CPU of the driver's thread per cycle (its thread CPU clock, read by a
//    listener the driver calls after each publication): one VM and one GS
//    exchange, every 50 ms, while the robot is only followed;
//  * latency from a velocity command written to the device
//    (Device::put_command, as the server does) to the VM carrying it on the
//    link (the link's trace hook, right after write()), p50 and p99 over
//    --commands commands, each another speed so its bytes are told apart.
//
//   ./build/bench/nomad_bench [--seconds 10] [--commands 300] [--interval 40] [--delay 20]
//
// --delay is the emulated server's reply time in ms (nomad.md §6: 10-50).
// Figures only; the emulator shares the machine (its own thread).

#include <algorithm>
#include <cstdint>
#include <cstdio>
#include <memory>
#include <span>
#include <string>

#include "driver_bench_support.hpp"
#include "emulators/runner/emulator_runner.hpp"
#include "families/nomad/emulator/nomad_emulator.hpp"
#include "families/nomad/protocol/nclient_message.hpp"
#include "families/nomad/protocol/nomad_units.hpp"
#include "protocol/binary_codec.hpp"
#include "protocol/interfaces.hpp"
#include "protocol/messages/nomad.hpp"

using namespace playerkit;
using namespace playerkit::bench;
using namespace std::chrono_literals;
namespace nomad = hardware::nomad;

int main(int argc, char** argv) {
  int delay_ms = 20;
  const BenchOptions options = parse_options(argc, argv, "nomad_bench", {}, 5,
                                             {{"--delay", [&delay_ms](int v) { delay_ms = std::clamp(v, 0, 1000); }}});
  emulators::NomadEmulatorOptions robot_options;
  robot_options.reply_delay = std::chrono::milliseconds(delay_ms);
  emulators::EmulatorRunner robot(std::make_unique<emulators::NomadEmulator>(robot_options), emulators::TcpEndpoint{});
  DriverRig rig("nomad_bench", "nomad:0 ( driver \"nomad\" port \"" + robot.device_path() + "\" )\n");
  core::Device& device = rig.device(protocol::kNomadCode);
  LineWatch watch(device);
  PublishRecorder recorder(device);
  if (!rig.subscribe_all()) return 1;

  const FollowResult follow = follow_publications(recorder, options);

  const CommandRun run = run_commands(device, watch, options, 20ms, [](int i) {
    protocol::NomadCommand command;
    command.vel_trans = 10 * (1 + i % 40);  // 10 ... 400 mm/s, never the previous one
    // The VM whose translation word is this speed.
    const std::int32_t wanted = nomad::tenth_inches_from_mm(command.vel_trans);
    return CommandTrial{protocol::encode(command), [wanted](std::span<const std::uint8_t> bytes,
                                                            SteadyClock::time_point) {
                          const auto message = nomad::decode(bytes);
                          return message && message->type == nomad::message_type::kVelocityMode &&
                                 !message->words.empty() && message->words[0] == wanted;
                        }};
  });
  rig.stop_and_shut_down(device, protocol::encode(protocol::NomadCommand{}));

  std::printf("nomad_bench: Nomad 200 emulated behind its server on %s, replies after %d ms\n",
              robot.device_path().c_str(), delay_ms);
  print_follow(follow, "driver thread");
  print_commands(run, "its VM written");
  return 0;
}
