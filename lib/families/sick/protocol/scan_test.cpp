#include "families/sick/protocol/scan.hpp"

#include "families/sick/protocol/test_bytes.hpp"

#include <gtest/gtest.h>

namespace playerkit::hardware::sick {
namespace scan_test {

using testing::bytes;

std::vector<std::uint8_t> repeated(const char* pair, int times) {
  std::vector<std::uint8_t> out;
  const auto one = bytes(pair);
  for (int i = 0; i < times; ++i) out.insert(out.end(), one.begin(), one.end());
  return out;
}

std::vector<std::uint8_t> concat(std::initializer_list<std::vector<std::uint8_t>> parts) {
  std::vector<std::uint8_t> out;
  for (const auto& part : parts) out.insert(out.end(), part.begin(), part.end());
  return out;
}

// sicklms200.md §2.2: 361 values of 1000 mm, unit bits 01.
const auto kB0Golden =
    concat({bytes("02 80 D6 02 B0 69 41"), repeated("E8 03", 361), bytes("10 55 F1")});
// 181 values of 2000 mm, first 1, last 181.
const auto kB7Golden =
    concat({bytes("02 80 72 01 B7 01 00 B5 00 B5 40"), repeated("D0 07", 181), bytes("10 05 C2")});

TEST(SickScan, EncodesTheSheetsB0) {
  Scan scan;
  scan.unit = Unit::millimetre;
  scan.values.assign(361, 1000);
  const auto telegram = encode_scan(scan);
  EXPECT_EQ(telegram.size(), 732u);
  EXPECT_EQ(telegram, kB0Golden);
  EXPECT_EQ(scan_telegram_size(361), 732u);
  EXPECT_EQ(parse_scan(unframe_reply(kB0Golden)), scan);
}

TEST(SickScan, EncodesTheSheetsB7) {
  Scan scan;
  scan.subrange = Subrange{1, 181};
  scan.values.assign(181, 2000);
  EXPECT_EQ(encode_scan(scan), kB7Golden);
  EXPECT_EQ(subrange_scan_telegram_size(181), kB7Golden.size());
  EXPECT_EQ(parse_scan(unframe_reply(kB7Golden)), scan);
}

TEST(SickScan, CountWordFields) {
  EXPECT_EQ((CountWord{361, 0, Unit::millimetre}.encode()), 0x4169);
  EXPECT_EQ((CountWord{181, 0, Unit::centimetre}.encode()), 0x00B5);
  EXPECT_EQ((CountWord{401, 3, Unit::millimetre}.encode()), 0x4000 | 0x1800 | 401);
  EXPECT_EQ(CountWord::decode(0x4169), (CountWord{361, 0, Unit::millimetre}));
  EXPECT_EQ(CountWord::decode(0x1991), (CountWord{401, 3, Unit::centimetre}));
  EXPECT_THROW((void)(CountWord{1024, 0, Unit::millimetre}.encode()), std::invalid_argument);
  EXPECT_THROW((void)(CountWord{1, 4, Unit::millimetre}.encode()), std::invalid_argument);
  EXPECT_THROW((void)(CountWord{1, 0, static_cast<Unit>(4)}.encode()), std::invalid_argument);
}

TEST(SickScan, ValueBits) {
  EXPECT_EQ(make_value(1000), 1000);
  EXPECT_EQ(make_value(8191, 7), 0xFFFF);
  EXPECT_EQ(make_value(0x0123, 5), 0xA123);
  EXPECT_EQ(distance_of(0xA123), 0x0123);
  EXPECT_EQ(flags_of(0xA123), 5);
  EXPECT_THROW(make_value(8192), std::invalid_argument);
  EXPECT_THROW(make_value(1, 8), std::invalid_argument);
}

TEST(SickScan, CentimetreScanWithReflectorBits) {
  Scan scan;
  scan.unit = Unit::centimetre;
  scan.values = {make_value(12, 0), make_value(345, 7), make_value(8191, 1)};
  const Reply reply = unframe_reply(encode_scan(scan));
  EXPECT_EQ(reply.data, bytes("03 00 0C 00 59 E1 FF 3F"));
  EXPECT_EQ(parse_scan(reply), scan);
}

void expect_parse_error(const Reply& reply, const std::string& words) {
  try {
    (void)parse_scan(reply);
    ADD_FAILURE() << "accepted a scan of " << reply.data.size() << " data bytes";
  } catch (const TelegramError& error) {
    EXPECT_NE(std::string(error.what()).find(words), std::string::npos) << error.what();
  }
}

TEST(SickScan, RefusesWhatIsNotAWholeScan) {
  expect_parse_error(Reply{0xA0, {0x00}, 0x10}, "neither B0 nor B7");
  expect_parse_error(Reply{0xB0, {0x03}, 0x10}, "B0 scan: truncated");
  expect_parse_error(Reply{0xB7, {0x01, 0x00, 0x03}, 0x10}, "B7 scan: truncated");
  // The count says 3 values, 2 are there (and the other way round).
  expect_parse_error(Reply{0xB0, bytes("03 40 01 00 02 00"), 0x10}, "truncated: count 3");
  expect_parse_error(Reply{0xB0, bytes("01 40 01 00 02 00"), 0x10}, "too long: count 1");
  expect_parse_error(Reply{0xB7, bytes("01 00 03 00 02 40 01 00 02 00"), 0x10},
                     "disagrees with indices 1..3");
  Scan too_many;
  too_many.values.assign(1024, 0);
  EXPECT_THROW(encode_scan(too_many), TelegramError);
}

}  // namespace scan_test
}  // namespace playerkit::hardware::sick
