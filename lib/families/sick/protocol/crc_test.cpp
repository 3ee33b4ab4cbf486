#include "families/sick/protocol/crc.hpp"

#include "families/sick/protocol/test_bytes.hpp"

#include <gtest/gtest.h>

#include <span>

namespace playerkit::hardware::sick {
namespace crc_test {

using testing::bytes;

// sicklms200.md §1.4: the CRC after each byte of "mode change OK".
TEST(SickCrc, FollowsTheSheetsStepTable) {
  const auto reply = bytes("02 80 03 00 A0 00 10");
  const std::uint16_t after_each[] = {0x0002, 0x0284, 0x850B, 0x8913, 0x9283, 0x0503, 0x0A16};
  for (std::size_t n = 1; n <= reply.size(); ++n) {
    EXPECT_EQ(crc16(std::span(reply).first(n)), after_each[n - 1]) << "after " << n << " bytes";
  }
}

TEST(SickCrc, IsZeroForNothing) { EXPECT_EQ(crc16({}), 0); }

TEST(SickCrc, WorksAtCompileTime) {
  constexpr std::uint8_t get_type[] = {0x02, 0x00, 0x01, 0x00, 0x3A};
  static_assert(crc16(get_type) == 0x121E);
}

// Pairing each byte with the previous one makes the order matter, unlike a
// plain sum; a swapped pair must change the CRC.
TEST(SickCrc, DependsOnByteOrder) {
  EXPECT_NE(crc16(bytes("02 00 01 00 3A")), crc16(bytes("02 00 01 3A 00")));
}

}  // namespace crc_test
}  // namespace playerkit::hardware::sick
