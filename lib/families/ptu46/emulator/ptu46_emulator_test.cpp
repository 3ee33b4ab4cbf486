#include "families/ptu46/emulator/ptu46_emulator.hpp"

#include <gtest/gtest.h>

#include <string>

namespace playerkit::emulators {
namespace {

using namespace std::chrono_literals;
using Axis = Ptu46Emulator::Axis;

// A host typing at the unit on a simulated clock.
struct Host {
  Ptu46Emulator unit;
  Duration now{0};

  // Everything the unit sent back for `text`, telegrams joined.
  std::string send(const std::string& text) {
    unit.receive(std::span(reinterpret_cast<const std::uint8_t*>(text.data()), text.size()), now, 9600);
    std::string out;
    for (const Telegram& telegram : unit.take_output()) out.append(telegram.bytes.begin(), telegram.bytes.end());
    return out;
  }
  void wait(Duration duration) {
    const Duration until = now + duration;
    while (unit.next_deadline() <= until) {
      now = unit.next_deadline();
      unit.advance(now);
    }
    now = until;
    unit.advance(now);
  }
  // The reference driver's start-up (ptu46.md §2.2 steps 2-3).
  void start_like_player() {
    send(" ");
    send("ft ed ci ");
  }
};

TEST(Ptu46Emulator, EchoesUntilEchoIsDisabled) {
  Host host;
  // Echo first (the bytes as they came), then the verbose power-up reply.
  EXPECT_EQ(host.send("pn "), "pn * Current Pan minimum position is -3090\r\n");
  EXPECT_EQ(host.send("ed "), "ed *\r\n");
  EXPECT_FALSE(host.unit.echo());
  EXPECT_EQ(host.send("pn "), "* Current Pan minimum position is -3090\r\n");
}

TEST(Ptu46Emulator, TerseRepliesAfterThePlayerStartUp) {
  Host host;
  host.start_like_player();
  EXPECT_TRUE(host.unit.terse());
  EXPECT_EQ(host.send("tr "), "* 185.1428\r\n");
  EXPECT_EQ(host.send("pr "), "* 185.1428\r\n");
  EXPECT_EQ(host.send("pn "), "* -3090\r\n");
  EXPECT_EQ(host.send("px "), "* 3090\r\n");
  EXPECT_EQ(host.send("tn "), "* -907\r\n");
  EXPECT_EQ(host.send("tx "), "* 604\r\n");
  EXPECT_EQ(host.send("pl "), "* 0\r\n");
  EXPECT_EQ(host.send("pu "), "* 2902\r\n");
  EXPECT_EQ(host.send("tl "), "* 0\r\n");
  EXPECT_EQ(host.send("tu "), "* 2902\r\n");
}

TEST(Ptu46Emulator, DelimitersAndCaseAsTheManualAllows) {
  Host host;
  host.start_like_player();
  // CR, LF or space end a command; empty commands get no answer.
  EXPECT_EQ(host.send("PX\r"), "* 3090\r\n");
  EXPECT_EQ(host.send("tX\n"), "* 604\r\n");
  EXPECT_EQ(host.send("   \r\n"), "");
  // A command split across two reads is one command.
  EXPECT_EQ(host.send("p"), "");
  EXPECT_EQ(host.send("n "), "* -3090\r\n");
  EXPECT_EQ(host.send("xyz "), "! Illegal Command\r\n");
  EXPECT_EQ(host.send("pr5 "), "! Illegal Command\r\n");
}

TEST(Ptu46Emulator, MovesToAPositionAtItsSpeed) {
  Host host;
  host.start_like_player();
  EXPECT_EQ(host.send("ps1000 "), "*\r\n");
  EXPECT_EQ(host.send("pp583 "), "*\r\n");
  host.wait(300ms);  // 1000 positions/s: 300 of the 583 so far
  EXPECT_NEAR(host.unit.position(Axis::pan), 300, 1);
  EXPECT_EQ(host.send("pp "), "* 300\r\n");
  host.wait(1s);
  EXPECT_EQ(host.send("pp "), "* 583\r\n");
  EXPECT_EQ(host.unit.next_deadline(), Duration::max());  // arrived: nothing more to do
  EXPECT_EQ(host.send("ps "), "* 1000\r\n");
}

TEST(Ptu46Emulator, RefusesPositionsAndSpeedsBeyondItsLimits) {
  Host host;
  host.start_like_player();
  EXPECT_EQ(host.send("pp3091 "), "! Maximum allowable Pan position is 3090\r\n");
  EXPECT_EQ(host.send("tp-908 "), "! Minimum allowable Tilt position is -907\r\n");
  EXPECT_EQ(host.send("ts2903 "), "! Maximum allowable Tilt speed is 2902\r\n");
  EXPECT_EQ(host.send("ps-5 "), "! Negative speeds need pure velocity control (CV)\r\n");
  EXPECT_EQ(host.unit.target(Axis::pan), 0);
  EXPECT_EQ(host.unit.speed(Axis::tilt), 1000);
}

TEST(Ptu46Emulator, PureVelocityDrivesTheAxisUntilItsLimit) {
  Host host;
  host.start_like_player();
  EXPECT_EQ(host.send("cv "), "*\r\n");
  EXPECT_EQ(host.unit.speed(Axis::tilt), 0);  // switching holds the axes
  EXPECT_EQ(host.send("ts-500 "), "*\r\n");
  host.wait(1s);
  EXPECT_NEAR(host.unit.position(Axis::tilt), -500, 1);
  host.wait(2s);
  EXPECT_EQ(host.send("tp "), "* -907\r\n");  // stopped at the limit
  EXPECT_EQ(host.unit.next_deadline(), Duration::max());
  EXPECT_EQ(host.send("tp0 "), "! Position commands need independent control (CI)\r\n");
  EXPECT_EQ(host.send("ts0 "), "*\r\n");
  EXPECT_EQ(host.send("ci "), "*\r\n");
  EXPECT_EQ(host.unit.target(Axis::tilt), -907);  // held where it stood
}

TEST(Ptu46Emulator, ResetAnswersAsTheDriverExpectsAndRecalibrates) {
  Host host;
  host.start_like_player();
  host.send("pp100 ");
  host.wait(1s);
  EXPECT_EQ(host.send("r "), "!T!T!P!P*\r\n");
  EXPECT_EQ(host.send("pp "), "* 0\r\n");
}

TEST(Ptu46Emulator, RefusesLimitsTheUnitCannotHave) {
  EXPECT_THROW(Ptu46Emulator({.resolution_arc_seconds = 0}), std::invalid_argument);
  EXPECT_THROW(Ptu46Emulator({.pan_min = 0}), std::invalid_argument);
  EXPECT_THROW(Ptu46Emulator({.lower_speed = 3000}), std::invalid_argument);
}

}  // namespace
}  // namespace playerkit::emulators
