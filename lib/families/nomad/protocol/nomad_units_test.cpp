#include "families/nomad/protocol/nomad_units.hpp"

#include <gtest/gtest.h>

#include <cmath>

namespace playerkit::hardware::nomad {
namespace nomad_units_test {

TEST(NomadUnits, TenthsOfAnInchAndOfADegree) {
  EXPECT_EQ(tenth_inches_from_mm(1000), 394);  // 39.37 in
  EXPECT_EQ(tenth_inches_from_mm(-254), -100);
  EXPECT_EQ(tenth_inches_from_mm(2), 1);  // the reference truncated this to 0
  EXPECT_DOUBLE_EQ(mm_from_tenth_inches(100), 254.0);
  EXPECT_EQ(tenth_degrees_from_degrees(-15), -150);
  EXPECT_DOUBLE_EQ(degrees_from_tenth_degrees(905), 90.5);
  EXPECT_DOUBLE_EQ(mm_from_inches(255), 6477.0);
}

TEST(NomadUnits, DemandsOutsideAWordAreClamped) {
  EXPECT_EQ(tenth_inches_from_mm(1e12), 2147483647);
  EXPECT_EQ(tenth_degrees_from_degrees(NAN), 0);
}

}  // namespace nomad_units_test
}  // namespace playerkit::hardware::nomad
