#include "core/plugin.hpp"

#include <gtest/gtest.h>

namespace playerkit::core {
namespace plugin_test {

// Loading a real plugin and serving its data is tested in lib/server with
// examples/plugin-driver; here only the failures.
TEST(PluginTest, MissingFileSaysWhichFile) {
  DriverRegistry registry;
  try {
    load_driver_plugin("/nonexistent/libnothing.so", registry);
    FAIL() << "expected a PluginError";
  } catch (const PluginError& e) {
    EXPECT_NE(std::string(e.what()).find("/nonexistent/libnothing.so"), std::string::npos);
  }
}

TEST(PluginTest, LibraryWithoutEntryPointIsRefused) {
  DriverRegistry registry;
  // Any shared library without our entry point will do; libc is always there.
  try {
    load_driver_plugin("libc.so.6", registry);
    FAIL() << "expected a PluginError";
  } catch (const PluginError& e) {
    EXPECT_NE(std::string(e.what()).find("no playerkit entry point"), std::string::npos) << e.what();
  }
  EXPECT_TRUE(registry.all().empty());
}

}  // namespace plugin_test
}  // namespace playerkit::core
