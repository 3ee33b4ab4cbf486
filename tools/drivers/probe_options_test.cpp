#include "probe_options.hpp"

#include <gtest/gtest.h>

#include "protocol/interfaces.hpp"

namespace playerkit::player_drivers {
namespace probe_options_test {

template <class Make>
std::string usage_error_of(Make make) {
  try {
    make();
  } catch (const UsageError& e) {
    return e.what();
  }
  return "";
}

TEST(ListOptions, InterfaceByName) {
  EXPECT_EQ(make_list_options({"laser", true}).interface, protocol::kLaserCode);
  EXPECT_TRUE(make_list_options({"laser", true}).json);
  EXPECT_FALSE(make_list_options({}).interface);
  EXPECT_EQ(usage_error_of([] { make_list_options({"lazer", false}); }),
            "--interface 'lazer' is not a Player interface; did you mean 'laser'?");
}

TEST(ProbeOptions, PortsAndBudget) {
  const ProbeOptions options = make_probe_options({{"/dev/ttyUSB0", "tcp:127.0.0.1:4001"}, true, false, 5.0});
  EXPECT_EQ(options.ports.size(), 2u);
  EXPECT_TRUE(options.json);
  EXPECT_EQ(options.settings.budget, std::chrono::milliseconds(5000));
  EXPECT_EQ(usage_error_of([] { make_probe_options({}); }),
            "probe: name the ports to try, e.g. /dev/ttyUSB0 (or tcp:HOST:PORT for a serial bridge)");
  EXPECT_EQ(usage_error_of([] { make_probe_options({{"/dev/ttyS0", "/dev/ttyS0"}, false, false, 10.0}); }),
            "probe: port /dev/ttyS0 is named twice");
  EXPECT_EQ(usage_error_of([] { make_probe_options({{"/dev/ttyS0"}, false, false, 0.1}); }),
            "--budget: 1 to 120 seconds a port");
}

}  // namespace probe_options_test
}  // namespace playerkit::player_drivers
