#include "stop_signals.hpp"

#include <gtest/gtest.h>

#include <csignal>

namespace playerkit::tools {
namespace stop_signals_test {

TEST(StopSignals, SigtermIsRememberedInsteadOfEndingTheProcess) {
  install_stop_signals();
  EXPECT_FALSE(stop_requested());
  ASSERT_EQ(std::raise(SIGTERM), 0);  // would end the test program without the handler
  EXPECT_TRUE(stop_requested());
  EXPECT_EQ(stop_signal_number(), SIGTERM);
}

TEST(StopSignals, BrokenPipesAreIgnored) {
  ignore_broken_pipes();
  EXPECT_EQ(std::raise(SIGPIPE), 0);  // would end the test program if not ignored
}

}  // namespace stop_signals_test
}  // namespace playerkit::tools
