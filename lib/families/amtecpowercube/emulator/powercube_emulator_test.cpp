// The emulated wrist on a simulated clock, frame by frame, as 1.5's driver
// talks to it (amtecpowercube.md §2.2): start-up, homing, steps that arrive
// on time at the top speed and acceleration, velocity, halt, errors.

#include "families/amtecpowercube/emulator/powercube_emulator.hpp"

#include <gtest/gtest.h>

#include <cmath>

#include "families/amtecpowercube/protocol/powercube_units.hpp"

namespace playerkit::emulators {
namespace {

namespace pc = hardware::powercube;
using namespace std::chrono_literals;
using Module = PowercubeEmulator::Module;
using Bytes = std::vector<std::uint8_t>;

struct Wrist {
  explicit Wrist(PowercubeEmulatorOptions options = {}) : unit(options) {}

  // One request, the replies it brought.
  std::vector<Telegram> send(Module module, const Bytes& data, int baud = PowercubeEmulator::kBaud) {
    unit.receive(pc::encode(module, data), now, baud);
    return unit.take_output();
  }
  std::uint32_t get(Module module, pc::Parameter parameter) {
    const auto replies = send(module, pc::get_data(parameter));
    EXPECT_EQ(replies.size(), 1u);
    if (replies.size() != 1) return 0;
    const auto frame = pc::decode(replies[0].bytes);
    EXPECT_TRUE(frame && frame->module == static_cast<std::uint8_t>(module));
    return frame ? pc::reply_value(*frame, parameter).value_or(0xDEADBEEF) : 0;
  }
  double degrees(Module module) { return pc::degrees(pc::float_from_bits(get(module, pc::Parameter::position))); }
  void pass(Duration time) {
    now += time;
    unit.advance(now);
  }
  void home_both() {
    for (const Module m : {Module::pan, Module::tilt}) {
      send(m, pc::reset_data());
      send(m, pc::home_data());
    }
    pass(10s);
  }

  PowercubeEmulator unit;
  Duration now{0};
};

TEST(PowercubeEmulator, AnswersEachFrameWithOneFrameCarryingTheValue) {
  Wrist wrist({.pan_start = 30});
  const auto replies = wrist.send(Module::pan, pc::get_data(pc::Parameter::position));
  ASSERT_EQ(replies.size(), 1u);
  const auto frame = pc::decode(replies[0].bytes);
  ASSERT_TRUE(frame);
  EXPECT_TRUE(pc::check_holds(*frame));
  EXPECT_EQ(replies[0].bytes[1], 0x05);  // the request's header, the reply's length
  EXPECT_EQ(replies[0].bytes[2], 0x86);
  EXPECT_NEAR(wrist.degrees(Module::pan), 30, 1e-4);
  // A homed state goes out escaped (§6.3): 10 82 00 00 00.
  wrist.home_both();
  const auto state = wrist.send(Module::tilt, pc::get_data(pc::Parameter::state));
  ASSERT_EQ(state.size(), 1u);
  EXPECT_EQ(Bytes(state[0].bytes.begin() + 5, state[0].bytes.begin() + 10), (Bytes{0x10, 0x82, 0, 0, 0}));
}

TEST(PowercubeEmulator, IsSilentToBadChecksAbsentModulesAndOtherSpeeds) {
  Wrist wrist({.tilt_present = false});
  Bytes frame = pc::encode(Module::pan, pc::get_data(pc::Parameter::position));
  frame[frame.size() - 2] ^= 1;
  wrist.unit.receive(frame, 0ns, PowercubeEmulator::kBaud);
  EXPECT_TRUE(wrist.unit.take_output().empty());
  EXPECT_EQ(wrist.unit.bad_checks(), 1u);
  EXPECT_TRUE(wrist.send(Module::tilt, pc::get_data(pc::Parameter::position)).empty());
  EXPECT_TRUE(wrist.send(Module::pan, pc::get_data(pc::Parameter::position), 9600).empty());
  // Noise and a frame split anywhere.
  Bytes stream{0x55, 0x10, 0x03};
  const Bytes good = pc::encode(Module::pan, pc::halt_data());
  stream.insert(stream.end(), good.begin(), good.end());
  wrist.unit.receive(std::span(stream).first(5), 0ns, 0);
  wrist.unit.receive(std::span(stream).subspan(5), 0ns, 0);
  EXPECT_EQ(wrist.unit.take_output().size(), 1u);
}

TEST(PowercubeEmulator, HomesToZeroAndSetsTheHomedBitWhenThere) {
  Wrist wrist({.pan_start = -45, .tilt_start = 20});
  wrist.send(Module::pan, pc::reset_data());
  wrist.send(Module::pan, pc::home_data());
  EXPECT_EQ(wrist.get(Module::pan, pc::Parameter::state) & pc::state_bit::homed, 0u);
  wrist.pass(200ms);
  EXPECT_GT(wrist.degrees(Module::pan), -45);
  EXPECT_LT(wrist.degrees(Module::pan), 0);
  wrist.pass(2s);
  EXPECT_EQ(wrist.get(Module::pan, pc::Parameter::state), pc::state_bit::homed);
  EXPECT_NEAR(wrist.degrees(Module::pan), 0, 1e-6);
  EXPECT_NEAR(wrist.degrees(Module::tilt), 20, 1e-4);  // not told to home
}

TEST(PowercubeEmulator, AStepArrivesAfterItsTimeWithinSpeedAndAcceleration) {
  Wrist wrist;
  wrist.home_both();
  // -45 deg in 1125 ms (40 deg/s, the sheet's example).
  wrist.send(Module::pan, pc::step_data(static_cast<float>(pc::radians(-45)), 1125));
  double fastest = 0;
  const Duration sent = wrist.now;
  for (int i = 0; i < 60; ++i) {
    wrist.pass(20ms);
    fastest = std::max(fastest, std::fabs(pc::degrees(pc::float_from_bits(wrist.get(Module::pan, pc::Parameter::velocity)))));
    if (wrist.now - sent < 1100ms) {
      EXPECT_GT(wrist.degrees(Module::pan), -44.9) << "at " << (wrist.now - sent).count();
    }
  }
  EXPECT_NEAR(wrist.degrees(Module::pan), -45, 1e-4);
  EXPECT_LE(fastest, 90);
  EXPECT_GT(fastest, 40);
  EXPECT_EQ(wrist.unit.next_deadline(), Duration::max());
}

TEST(PowercubeEmulator, AStepTooQuickForTheModuleGoesFlatOutAndArrivesLate) {
  Wrist wrist;
  wrist.home_both();
  wrist.send(Module::tilt, pc::step_data(static_cast<float>(pc::radians(90)), 100));
  wrist.pass(500ms);
  EXPECT_LT(wrist.degrees(Module::tilt), 60);
  wrist.pass(1s);
  EXPECT_NEAR(wrist.degrees(Module::tilt), 90, 1e-4);
}

TEST(PowercubeEmulator, VelocityRampsAndStopsAtTheLimit) {
  Wrist wrist({.tilt_max = 30});
  wrist.home_both();
  wrist.send(Module::tilt, pc::velocity_data(static_cast<float>(pc::radians(60))));
  wrist.pass(100ms);
  EXPECT_NEAR(pc::degrees(pc::float_from_bits(wrist.get(Module::tilt, pc::Parameter::velocity))), 36, 0.5);
  wrist.pass(2s);
  EXPECT_NEAR(wrist.degrees(Module::tilt), 30, 1e-4);
  EXPECT_EQ(wrist.unit.velocity(Module::tilt), 0);
  // A velocity past the top speed is the top speed.
  wrist.send(Module::tilt, pc::velocity_data(static_cast<float>(pc::radians(-500))));
  wrist.pass(1s);
  EXPECT_NEAR(pc::degrees(wrist.unit.velocity(Module::tilt)), -90, 1e-6);
}

TEST(PowercubeEmulator, HaltBrakesAndHoldsUntilResetOrHome) {
  Wrist wrist;
  wrist.home_both();
  wrist.send(Module::pan, pc::velocity_data(1.0F));
  wrist.pass(300ms);
  wrist.send(Module::pan, pc::halt_data());
  const double held = wrist.degrees(Module::pan);
  EXPECT_TRUE(wrist.get(Module::pan, pc::Parameter::state) & pc::state_bit::halted);
  wrist.send(Module::pan, pc::step_data(0, 100));
  wrist.pass(1s);
  EXPECT_NEAR(wrist.degrees(Module::pan), held, 1e-6);
  wrist.send(Module::pan, pc::reset_data());
  wrist.send(Module::pan, pc::step_data(0, 100));
  wrist.pass(1s);
  EXPECT_NEAR(wrist.degrees(Module::pan), 0, 1e-6);
}

TEST(PowercubeEmulator, AModuleNotHomedOrInErrorDoesNotMove) {
  Wrist wrist;
  wrist.send(Module::pan, pc::step_data(1.0F, 100));
  wrist.pass(1s);
  EXPECT_EQ(wrist.degrees(Module::pan), 0);
  wrist.home_both();
  wrist.unit.raise_error(Module::pan);
  EXPECT_EQ(wrist.get(Module::pan, pc::Parameter::state), pc::state_bit::homed | pc::state_bit::error);
  wrist.send(Module::pan, pc::step_data(1.0F, 100));
  wrist.pass(1s);
  EXPECT_EQ(wrist.degrees(Module::pan), 0);
  wrist.send(Module::pan, pc::reset_data());
  EXPECT_EQ(wrist.get(Module::pan, pc::Parameter::state), pc::state_bit::homed);
}

TEST(PowercubeEmulator, RefusesSettingsNoModuleHas) {
  EXPECT_THROW(PowercubeEmulator({.max_speed = 0}), std::invalid_argument);
  EXPECT_THROW(PowercubeEmulator({.pan_min = 10}), std::invalid_argument);
  EXPECT_THROW(PowercubeEmulator({.tilt_start = 200}), std::invalid_argument);
  EXPECT_THROW(PowercubeEmulator({.pan_present = false, .tilt_present = false}), std::invalid_argument);
}

}  // namespace
}  // namespace playerkit::emulators
