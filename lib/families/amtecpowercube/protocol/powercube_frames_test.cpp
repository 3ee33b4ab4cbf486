// Golden bytes from amtecpowercube.md §1's worked examples, and the frames
// read back.

#include "families/amtecpowercube/protocol/powercube_frames.hpp"

#include <gtest/gtest.h>

#include <cmath>

#include "families/amtecpowercube/protocol/powercube_units.hpp"

namespace playerkit::hardware::powercube {
namespace {

using Bytes = std::vector<std::uint8_t>;

TEST(PowercubeFrames, SheetsWorkedExamples) {
  EXPECT_EQ(encode(Module::pan, get_data(Parameter::position)), (Bytes{0x02, 0x05, 0x82, 0x0A, 0x3C, 0x52, 0x03}));
  EXPECT_EQ(encode(Module::tilt, get_data(Parameter::position)), (Bytes{0x02, 0x05, 0x62, 0x0A, 0x3C, 0x51, 0x03}));
  // HALT's 02 escaped; its check byte 0x0E.
  EXPECT_EQ(encode(Module::pan, halt_data()), (Bytes{0x02, 0x05, 0x81, 0x10, 0x82, 0x0E, 0x03}));
  // A step to -45 deg in 1125 ms: the motion id 0x10 escaped.
  EXPECT_EQ(encode(Module::pan, step_data(static_cast<float>(radians(-45.0)), 1125)),
            (Bytes{0x02, 0x05, 0x88, 0x0B, 0x10, 0x90, 0xDB, 0x0F, 0x49, 0xBF, 0x65, 0x04, 0x82, 0x03}));
}

TEST(PowercubeFrames, CommandData) {
  EXPECT_EQ(reset_data(), Bytes{0x00});
  EXPECT_EQ(home_data(), Bytes{0x01});
  EXPECT_EQ(velocity_data(1.0F), (Bytes{0x0B, 0x11, 0x00, 0x00, 0x80, 0x3F}));
  EXPECT_EQ(set_float_data(Parameter::max_position, 1.0F), (Bytes{0x08, 0x46, 0x00, 0x00, 0x80, 0x3F}));
  EXPECT_EQ(header_d1(12), 0x05);
  EXPECT_EQ(header_d2(11, 6), 0x66);
}

TEST(PowercubeFrames, AnEscapedCheckByteAndEscapedValues) {
  // A homed state (02 00 00 00) is sent escaped, and so is a check byte of 0x10.
  const Bytes frame = encode(Module::tilt, value_reply_data(Parameter::state, state_bit::homed));
  EXPECT_EQ(frame, (Bytes{0x02, 0x05, 0x66, 0x0A, 0x27, 0x10, 0x82, 0x00, 0x00, 0x00, 0x3E, 0x03}));
  const Bytes check_escaped = encode(0x03, Bytes{0x0D});  // 3 + 13 = 0x10
  EXPECT_EQ(check_escaped, (Bytes{0x02, 0x04, 0x61, 0x0D, 0x10, 0x90, 0x03}));
}

TEST(PowercubeFrames, DecodesWhatItEncodes) {
  const auto frame = decode(encode(Module::pan, value_reply_data(Parameter::position, float_bits(0.5F))));
  ASSERT_TRUE(frame);
  EXPECT_EQ(frame->module, 12);
  EXPECT_TRUE(check_holds(*frame));
  EXPECT_EQ(reply_value(*frame, Parameter::position), float_bits(0.5F));
  EXPECT_FALSE(reply_value(*frame, Parameter::velocity));
  auto wrong = *frame;
  ++wrong.check;
  EXPECT_FALSE(check_holds(wrong));
  EXPECT_FALSE(decode(Bytes{0x02, 0x05, 0x03}));       // no room for a check byte
  EXPECT_FALSE(decode(Bytes{0x02, 0x05, 0x81, 0x10, 0x41, 0x00, 0x03}));  // an escape of nothing
}

TEST(PowercubeFrames, TheFormatCutsFramesOutOfNoise) {
  const framing::DleStuffedFormat format(frame_options());
  Bytes stream{0xFF, 0x7E};
  const Bytes frame = encode(Module::pan, halt_data());
  stream.insert(stream.end(), frame.begin(), frame.end());
  EXPECT_EQ(format.scan(stream).kind, framing::FrameScan::Kind::skip);
  EXPECT_EQ(format.scan(stream).length, 2u);
  const auto whole = format.scan(std::span(stream).subspan(2));
  EXPECT_EQ(whole.kind, framing::FrameScan::Kind::frame);
  EXPECT_EQ(whole.length, frame.size());
}

TEST(PowercubeUnits, PlayerAnglesAsTheSheetMapsThem) {
  // §3.1: pan 0.5 rad -> -28 (1.5 truncated -28.6; rounded, -29); tilt 0.5 rad -> 28.6;
  // pan 3.5 rad is past half a circle: 159.46.
  EXPECT_NEAR(player_pan_degrees(0.5), -28.648, 1e-3);
  EXPECT_NEAR(player_pan_degrees(3.5), 159.465, 1e-3);
  EXPECT_EQ(wire_degrees(player_pan_degrees(0.5)), -29);
  EXPECT_EQ(wire_degrees(degrees(static_cast<float>(radians(30.0)))), 30);  // a float just under 30 deg stays 30
  EXPECT_NEAR(pan_module_radians(45), -0.7853982, 1e-7);
  EXPECT_EQ(step_milliseconds(45, 40), 1125);
  EXPECT_EQ(step_milliseconds(-45, 40), 1125);
  EXPECT_EQ(step_milliseconds(3000, 1), 65535);
  EXPECT_EQ(wire_degrees(1e9), 32767);
}

}  // namespace
}  // namespace playerkit::hardware::powercube
