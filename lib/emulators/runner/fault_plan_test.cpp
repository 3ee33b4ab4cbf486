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
  for (const char* argument : {"bad-checksum=0.1", "garbage=0.25", "truncate=0.05", "drop=0.01",
                               "silent-start=2.5", "slow-start=1.5", "vanish=5:3", "seed=42"}) {
    add_fault(plan, argument);
  }
  EXPECT_TRUE(plan.any());
  EXPECT_DOUBLE_EQ(plan.bad_checksum, 0.1);
  EXPECT_DOUBLE_EQ(plan.garbage, 0.25);
  EXPECT_DOUBLE_EQ(plan.truncate, 0.05);
  EXPECT_DOUBLE_EQ(plan.drop, 0.01);
  EXPECT_EQ(plan.silent_start, Duration(2500ms));
  EXPECT_EQ(plan.slow_start, Duration(1500ms));
  EXPECT_EQ(plan.vanish_at, Duration(5s));
  EXPECT_EQ(plan.vanish_for, Duration(3s));
  EXPECT_EQ(plan.seed, 42u);
  EXPECT_EQ(plan.describe(),
            "bad-checksum=0.1, garbage=0.25, truncate=0.05, drop=0.01, silent-start=2.5, slow-start=1.5, vanish=5:3");
}

TEST(FaultPlan, EveryListedKindIsTakenAndEveryKindTakenIsListed) {
  // The list is what `player-drivers emulate --help` prints and what a bad
  // argument's message names: a kind missing from it could not be found.
  const std::string all_kinds = error_of("meteor=1");
  std::size_t listed = 0;
  for (const FaultKind& kind : fault_kinds()) {
    const std::string example = std::string(kind.argument.substr(0, kind.argument.find('=') + 1)) +
                                (kind.argument.ends_with("AT:FOR") ? "1:2" : "1");
    EXPECT_EQ(error_of(example), "no error") << example;
    EXPECT_FALSE(kind.summary.empty()) << kind.argument;
    EXPECT_NE(all_kinds.find(kind.argument), std::string::npos) << kind.argument;
    ++listed;
  }
  EXPECT_EQ(listed, 8u) << "a kind was added to add_fault: list it in fault_kinds() too";
}

TEST(FaultPlan, ASlowStartBeginsAtEveryOpenASilentStartOnlyOnce) {
  FaultPlan slow;
  add_fault(slow, "slow-start=2");
  EXPECT_FALSE(slow.line_dead(Duration(0s))) << "nobody on the line yet: nothing to hear";
  EXPECT_TRUE(slow.line_dead(Duration(10s), Duration(9s)));
  EXPECT_FALSE(slow.line_dead(Duration(11s), Duration(9s)));
  EXPECT_TRUE(slow.line_dead(Duration(31s), Duration(30s))) << "a host that reopens waits again";

  FaultPlan silent;
  add_fault(silent, "silent-start=2");
  EXPECT_TRUE(silent.line_dead(Duration(1s)));
  EXPECT_FALSE(silent.line_dead(Duration(31s), Duration(30s)));
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
  EXPECT_NE(error_of("drop=1.5").find("a probability lies between 0 and 1"), std::string::npos);
  EXPECT_NE(error_of("slow-start=-1").find("seconds lie between 0 and 1e6"), std::string::npos);
  EXPECT_NE(error_of("garbage=lots").find("'lots' is not a number"), std::string::npos);
  EXPECT_NE(error_of("vanish=5").find("expected vanish=AT:FOR"), std::string::npos);
  EXPECT_NE(error_of("vanish=5:0").find("FOR must be above 0"), std::string::npos);
  EXPECT_NE(error_of("meteor=1").find("unknown fault 'meteor'"), std::string::npos);
  EXPECT_NE(error_of("meteor=1").find("kinds: bad-checksum=P"), std::string::npos);
  EXPECT_NE(error_of("truncate").find("expected KIND=VALUE"), std::string::npos);
}

}  // namespace fault_plan_test
}  // namespace playerkit::emulators
