#include "families/ptu46/protocol/ptu_commands.hpp"

#include <gtest/gtest.h>

#include <string>

namespace playerkit::hardware::ptu46 {
namespace {

std::string wire(const Command& command) {
  const auto bytes = encode(command);
  return {bytes.begin(), bytes.end()};
}

// ptu46.md §2.1: every command the reference driver sends, lower case, one space after.
TEST(PtuCommands, EncodesWhatTheSheetLists) {
  EXPECT_EQ(wire(empty()), " ");
  EXPECT_EQ(wire(terse_feedback()), "ft ");
  EXPECT_EQ(wire(echo_off()), "ed ");
  EXPECT_EQ(wire(set_control_mode(ControlMode::independent)), "ci ");
  EXPECT_EQ(wire(set_control_mode(ControlMode::pure_velocity)), "cv ");
  EXPECT_EQ(wire(reset()), "r ");
  EXPECT_EQ(wire(query(Axis::tilt, Quantity::resolution)), "tr ");
  EXPECT_EQ(wire(query(Axis::pan, Quantity::resolution)), "pr ");
  EXPECT_EQ(wire(query(Axis::pan, Quantity::min_position)), "pn ");
  EXPECT_EQ(wire(query(Axis::pan, Quantity::max_position)), "px ");
  EXPECT_EQ(wire(query(Axis::tilt, Quantity::min_position)), "tn ");
  EXPECT_EQ(wire(query(Axis::tilt, Quantity::max_position)), "tx ");
  EXPECT_EQ(wire(query(Axis::pan, Quantity::lower_speed)), "pl ");
  EXPECT_EQ(wire(query(Axis::pan, Quantity::upper_speed)), "pu ");
  EXPECT_EQ(wire(query(Axis::tilt, Quantity::lower_speed)), "tl ");
  EXPECT_EQ(wire(query(Axis::tilt, Quantity::upper_speed)), "tu ");
  EXPECT_EQ(wire(query(Axis::pan, Quantity::position)), "pp ");
  EXPECT_EQ(wire(query(Axis::tilt, Quantity::speed)), "ts ");
  // The sheet's worked example: pan 30 deg -> pp583, 50 deg/s -> ps972.
  EXPECT_EQ(wire(set_position(Axis::pan, 583)), "pp583 ");
  EXPECT_EQ(wire(set_speed(Axis::pan, 972)), "ps972 ");
  EXPECT_EQ(wire(set_position(Axis::tilt, -907)), "tp-907 ");
  EXPECT_EQ(wire(set_speed(Axis::tilt, -120)), "ts-120 ");
}

TEST(PtuCommands, ParsesAnyCaseWithOrWithoutArgument) {
  EXPECT_EQ(parse_command("PP583"), (ParsedCommand{"pp", 583}));
  EXPECT_EQ(parse_command("tp-907"), (ParsedCommand{"tp", -907}));
  EXPECT_EQ(parse_command("Ps+40"), (ParsedCommand{"ps", 40}));
  EXPECT_EQ(parse_command("FT"), (ParsedCommand{"ft", std::nullopt}));
  EXPECT_EQ(parse_command("r"), (ParsedCommand{"r", std::nullopt}));
}

TEST(PtuCommands, RefusesWhatIsNoCommandShape) {
  EXPECT_EQ(parse_command(""), std::nullopt);
  EXPECT_EQ(parse_command("583"), std::nullopt);
  EXPECT_EQ(parse_command("pp58x"), std::nullopt);
  EXPECT_EQ(parse_command("pp-"), std::nullopt);
  EXPECT_EQ(parse_command("pp99999999999999999999"), std::nullopt);
}

TEST(PtuCommands, EveryEncodedCommandParsesBackToItsNameAndArgument) {
  for (const Axis axis : {Axis::pan, Axis::tilt}) {
    for (const std::int64_t n : {-3090, -1, 0, 1, 583, 3090}) {
      const auto position = parse_command(set_position(axis, n).text);
      ASSERT_TRUE(position);
      EXPECT_EQ(position->name, (std::string{axis_letter(axis), 'p'}));
      EXPECT_EQ(position->argument, n);
      const auto speed = parse_command(set_speed(axis, n).text);
      ASSERT_TRUE(speed);
      EXPECT_EQ(speed->name, (std::string{axis_letter(axis), 's'}));
      EXPECT_EQ(speed->argument, n);
    }
  }
}

}  // namespace
}  // namespace playerkit::hardware::ptu46
