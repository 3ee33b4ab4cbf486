#include "families/p2os/protocol/commands.hpp"

#include "families/p2os/protocol/errors.hpp"
#include "families/p2os/protocol/frame.hpp"
#include "families/p2os/protocol/test_support.hpp"

#include <gtest/gtest.h>

namespace playerkit::hardware::p2os {
namespace commands_test {

using testing::hex;
namespace golden = testing::golden;

TEST(CommandFrame, ReproducesTheWorkedExamples) {
  EXPECT_EQ(command_frame(Command::plain(command::sync0)), hex(golden::sync0));
  EXPECT_EQ(command_frame(Command::plain(command::open)), hex(golden::open));
  EXPECT_EQ(command_frame(Command::with_integer(command::enable, 1)), hex(golden::enable_1));
  EXPECT_EQ(command_frame(Command::with_integer(command::vel2, encode_vel2({.left = 5, .right = 5}))),
            hex(golden::vel2_right5_left5));
  EXPECT_EQ(command_frame(Command::with_integer(command::vel, -300)), hex(golden::vel_minus_300));
  EXPECT_EQ(command_frame(Command::type_only(command::seto)), hex(golden::seto));
}

TEST(DecodeCommand, ReadsTheWorkedExamplesBack) {
  const Command enable = decode_command(frame_payload(hex(golden::enable_1)));
  EXPECT_EQ(enable.number, command::enable);
  EXPECT_EQ(enable.form, ArgumentForm::integer);
  EXPECT_EQ(enable.value(), 1);

  const Command vel = decode_command(frame_payload(hex(golden::vel_minus_300)));
  EXPECT_EQ(vel.number, command::vel);
  EXPECT_TRUE(vel.negative);
  EXPECT_EQ(vel.value(), -300);

  const Command seto = decode_command(frame_payload(hex(golden::seto)));
  EXPECT_EQ(seto.number, command::seto);
  EXPECT_EQ(seto.form, ArgumentForm::type_only);
  EXPECT_EQ(seto.value(), 0);

  const Command vel2 = decode_command(frame_payload(hex(golden::vel2_right5_left5)));
  EXPECT_EQ(decode_vel2(vel2.magnitude), (Vel2Wheels{.left = 5, .right = 5}));

  const Command sync0 = decode_command(frame_payload(hex(golden::sync0)));
  EXPECT_EQ(sync0.number, command::sync0);
  EXPECT_EQ(sync0.form, ArgumentForm::none);
}

TEST(DecodeCommand, RoundTripsEveryForm) {
  const Command commands[] = {
      Command::plain(command::stop),
      Command::with_integer(command::rvel, 45),
      Command::with_integer(command::rvel, -45),
      Command::with_integer(command::sound, 0x7255),
      Command::with_integer(command::vel, 65535),
      Command::with_integer(command::vel, -65535),
      Command::type_only(command::seto),
      Command::with_string(command::tty3, "TC 10 20 30 40 50 60\r"),
      Command::with_string(command::tty3, ""),
  };
  for (const Command& c : commands) {
    EXPECT_EQ(decode_command(encode_command(c)), c) << command_name(c.number, true);
  }
}

TEST(Vel2, SignedWheelsInTheirBytes) {
  // Right wheel in the low byte, left in the high, each signed.
  EXPECT_EQ(encode_vel2({.left = -1, .right = 5}), 0xFF05);
  EXPECT_EQ(decode_vel2(0x80FF), (Vel2Wheels{.left = -128, .right = -1}));
  for (int left = -128; left <= 127; left += 17) {
    for (int right = -128; right <= 127; right += 13) {
      const Vel2Wheels wheels{.left = static_cast<std::int8_t>(left),
                              .right = static_cast<std::int8_t>(right)};
      EXPECT_EQ(decode_vel2(encode_vel2(wheels)), wheels);
    }
  }
  // Sent as ARGINT with the raw 16 bits, whatever the signs.
  EXPECT_EQ(encode_command(Command::with_integer(command::vel2, encode_vel2({.left = -3, .right = 4}))),
            hex("20 3B 04 FD"));
}

TEST(EncodeCommand, RefusesValuesThatDoNotFit) {
  EXPECT_THROW(Command::with_integer(command::vel, 65536), EncodeError);
  EXPECT_THROW(Command::with_integer(command::vel, -65536), EncodeError);
  EXPECT_THROW(encode_command(Command::with_string(command::tty3, std::string(256, 'x'))),
               EncodeError);
  // N = 1 + 1 + 1 + L + 2 must stay <= 200.
  EXPECT_NO_THROW(encode_command(Command::with_string(command::tty3, std::string(195, 'x'))));
  EXPECT_THROW(encode_command(Command::with_string(command::tty3, std::string(196, 'x'))),
               EncodeError);
}

TEST(DecodeCommand, RejectsTruncatedArgumentsWithAClearError) {
  EXPECT_THROW(decode_command({}), DecodeError);
  EXPECT_THROW(decode_command(hex("0B 3B 2C")), DecodeError);    // one value byte of two
  EXPECT_THROW(decode_command(hex("42 2B")), DecodeError);       // string without length
  EXPECT_THROW(decode_command(hex("42 2B 05 41 42")), DecodeError);  // 2 of 5 characters
  try {
    decode_command(hex("0B 3B 2C"));
    FAIL();
  } catch (const DecodeError& e) {
    EXPECT_NE(std::string(e.what()).find("integer argument"), std::string::npos) << e.what();
  }
}

TEST(DecodeCommand, RejectsUnknownArgumentTypes) {
  try {
    decode_command(hex("0B 55 01 00"));
    FAIL();
  } catch (const DecodeError& e) {
    EXPECT_NE(std::string(e.what()).find("0x55"), std::string::npos) << e.what();
  }
}

TEST(DecodeCommand, IgnoresBytesAfterACompleteArgument) {
  const Command c = decode_command(hex("04 3B 01 00 99"));
  EXPECT_EQ(c.value(), 1);
}

TEST(CommandName, DependsOnTheConnectionForReusedNumbers) {
  EXPECT_EQ(command_name(0, false), "SYNC0");
  EXPECT_EQ(command_name(0, true), "PULSE");
  EXPECT_EQ(command_name(1, true), "OPEN");
  EXPECT_EQ(command_name(2, true), "CLOSE");
  EXPECT_EQ(command_name(32, true), "VEL2");
  EXPECT_EQ(command_name(200, true), "command 200");
}

}  // namespace commands_test
}  // namespace playerkit::hardware::p2os
