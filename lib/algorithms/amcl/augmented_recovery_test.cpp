#include "algorithms/amcl/augmented_recovery.hpp"

#include <gtest/gtest.h>

#include <cmath>

namespace playerkit::amcl {
namespace augmented_recovery_test {

TEST(AugmentedRecovery, SteadyLikelihoodInjectsNothing) {
  AugmentedRecovery recovery(0.001, 0.1);
  EXPECT_EQ(recovery.injection_probability(), 0.0);
  for (int i = 0; i < 100; ++i) recovery.observe(std::log(0.5));
  EXPECT_NEAR(recovery.injection_probability(), 0.0, 1e-12);
}

TEST(AugmentedRecovery, SuddenDropInjectsAsTheBookSays) {
  AugmentedRecovery recovery(0.001, 0.1);
  recovery.observe(std::log(1.0));
  recovery.observe(std::log(0.01));
  // Linear domain: w_slow = 0.999 + 0.001 * 0.01, w_fast = 0.9 + 0.1 * 0.01.
  const double slow = 0.999 + 0.00001, fast = 0.9 + 0.001;
  EXPECT_NEAR(std::exp(recovery.log_slow()), slow, 1e-12);
  EXPECT_NEAR(std::exp(recovery.log_fast()), fast, 1e-12);
  EXPECT_NEAR(recovery.injection_probability(), 1.0 - fast / slow, 1e-12);
  // A lasting drop drives the fast average far below the slow one.
  for (int i = 0; i < 50; ++i) recovery.observe(std::log(0.01));
  EXPECT_GT(recovery.injection_probability(), 0.9);
  // Once the likelihood recovers the injection stops.
  for (int i = 0; i < 100; ++i) recovery.observe(std::log(1.0));
  EXPECT_EQ(recovery.injection_probability(), 0.0);
}

TEST(AugmentedRecovery, RisingLikelihoodNeverInjects) {
  AugmentedRecovery recovery(0.001, 0.1);
  for (int i = 1; i < 50; ++i) {
    recovery.observe(std::log(0.01 * i));
    EXPECT_EQ(recovery.injection_probability(), 0.0);
  }
}

TEST(AugmentedRecovery, ZeroRatesDisableAndResetForgets) {
  AugmentedRecovery off(0.0, 0.0);
  off.observe(0.0);
  off.observe(-50.0);
  EXPECT_EQ(off.injection_probability(), 0.0);
  AugmentedRecovery on(0.001, 0.1);
  on.observe(0.0);
  on.observe(-50.0);
  EXPECT_GT(on.injection_probability(), 0.05);
  on.reset();
  EXPECT_EQ(on.injection_probability(), 0.0);
}

TEST(AugmentedRecovery, StaysFiniteForTinyLikelihoods) {
  AugmentedRecovery recovery(0.001, 0.1);
  recovery.observe(-2000.0);  // exp() of this is 0 in a double
  recovery.observe(-2100.0);
  EXPECT_TRUE(std::isfinite(recovery.log_slow()));
  EXPECT_GT(recovery.injection_probability(), 0.09);
}

}  // namespace augmented_recovery_test
}  // namespace playerkit::amcl
