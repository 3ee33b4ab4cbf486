#include "emulators/runner/fault_plan.hpp"

#include <gtest/gtest.h>

#include <stdexcept>
#include <string>

namespace playerkit::emulators {
namespace fault_plan_test {

using namespace std::chrono_literals;

std::string error_of(std::string_view argument) {
  FaultPlan plan;
  try {
    add_fault(plan, argument);
  } catch (const std::invalid_argument& error) {
    return error.what();
  }
  return "no error";
}

TEST(FaultPlan, ParsesEveryKind) {
  FaultPlan plan;
  EXPECT_FALSE(plan.any());
  for (const char* argument : {"bad-checksum=0.1", "garbage=0.25", "truncate=0.05", "silent-start=2.5",
                               "vanish=5:3", "seed=42"}) {
    add_fault(plan, argument);
  }
  EXPECT_TRUE(plan.any());
  EXPECT_DOUBLE_EQ(plan.bad_checksum, 0.1);
  EXPECT_DOUBLE_EQ(plan.garbage, 0.25);
  EXPECT_DOUBLE_EQ(plan.truncate, 0.05);
  EXPECT_EQ(plan.silent_start, Duration(2500ms));
  EXPECT_EQ(plan.vanish_at, Duration(5s));
  EXPECT_EQ(plan.vanish_for, Duration(3s));
  EXPECT_EQ(plan.seed, 42u);
  EXPECT_EQ(plan.describe(), "bad-checksum=0.1, garbage=0.25, truncate=0.05, silent-start=2.5, vanish=5:3");
}

TEST(FaultPlan, TheLineIsDeadWhileSilentAndWhileVanished) {
  FaultPlan plan;
  add_fault(plan, "silent-start=1");
  add_fault(plan, "vanish=5:3");
  EXPECT_TRUE(plan.line_dead(Duration(500ms)));
  EXPECT_FALSE(plan.line_dead(Duration(1s)));
  EXPECT_FALSE(plan.line_dead(Duration(4999ms)));
  EXPECT_TRUE(plan.line_dead(Duration(5s)));
  EXPECT_TRUE(plan.line_dead(Duration(7999ms)));
  EXPECT_FALSE(plan.line_dead(Duration(8s)));  // it came back
}

TEST(FaultPlan, BadArgumentsSayWhatIsWrongAndListTheKinds) {
  EXPECT_NE(error_of("bad-checksum=2").find("a probability lies between 0 and 1"), std::string::npos);
  EXPECT_NE(error_of("garbage=lots").find("'lots' is not a number"), std::string::npos);
  EXPECT_NE(error_of("vanish=5").find("expected vanish=AT:FOR"), std::string::npos);
  EXPECT_NE(error_of("vanish=5:0").find("FOR must be above 0"), std::string::npos);
  EXPECT_NE(error_of("meteor=1").find("unknown fault 'meteor'"), std::string::npos);
  EXPECT_NE(error_of("meteor=1").find("kinds: bad-checksum=P"), std::string::npos);
  EXPECT_NE(error_of("truncate").find("expected KIND=VALUE"), std::string::npos);
}

}  // namespace fault_plan_test
}  // namespace playerkit::emulators
