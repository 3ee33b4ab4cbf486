// A driver from a shared object, served to a real client.

#include <gtest/gtest.h>

#include "core/plugin.hpp"
#include "protocol/binary_codec.hpp"
#include "protocol/interfaces.hpp"
#include "protocol/messages/power.hpp"
#include "support/raw_client.hpp"
#include "test_server.hpp"

namespace playerkit::testing {
namespace plugin_test {

TEST(PluginTest, ExamplePluginDriverIsServedToAClient) {
  TestServer server("power:0 ( driver \"simbattery\" volts 12.3 drain 0 rate 50 )\n", {}, 0,
                    [](core::DriverRegistry& registry) {
                      core::load_driver_plugin(PLAYERKIT_EXAMPLE_PLUGIN, registry);
                    });
  RawClient client(server.port());
  client.read_banner();
  ASSERT_EQ(client.open({protocol::kPowerCode, 0}, 'r'), 'r');
  for (int round = 0; round < 50; ++round) {
    for (const auto& message : client.read_round()) {
      if (message.type() != protocol::MessageType::kData) continue;
      EXPECT_EQ(message.device(), (protocol::DeviceAddress{protocol::kPowerCode, 0}));
      EXPECT_EQ(protocol::decode<protocol::PowerData>(message.payload).charge, 123);
      return;
    }
  }
  FAIL() << "no power data from the plugin's driver";
}

TEST(PluginTest, PluginOptionsAreCheckedAtStartUp) {
  try {
    TestServer server("power:0 ( driver \"simbattery\" rate 0 )\n", {}, 0,
                      [](core::DriverRegistry& registry) {
                        core::load_driver_plugin(PLAYERKIT_EXAMPLE_PLUGIN, registry);
                      });
    FAIL() << "expected a configuration error";
  } catch (const std::exception& e) {
    EXPECT_EQ(std::string(e.what()),
              "test.cfg:1:1: driver 'simbattery' could not be created: rate must be positive");
  }
}

}  // namespace plugin_test
}  // namespace playerkit::testing
