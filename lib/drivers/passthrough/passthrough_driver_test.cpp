// Options, registration and a refused setup without any server. The end-to-end
// behaviour (data, commands, requests, chains, a remote that goes away) is in
// tests/passthrough/, against real servers on loopback.
#include "drivers/passthrough/passthrough_driver.hpp"

#include <gtest/gtest.h>

#include <mutex>
#include <string>
#include <vector>

#include <boost/asio/io_context.hpp>
#include <boost/asio/ip/tcp.hpp>

#include "config/errors.hpp"
#include "drivers/test_support.hpp"
#include "protocol/interfaces.hpp"

namespace playerkit::drivers {
namespace passthrough_driver_test {

using protocol::Access;

const RemoteDevice& remote_of(core::Device& device) {
  auto* driver = dynamic_cast<PassthroughDriver*>(&device.driver());
  if (driver == nullptr) throw std::runtime_error("not a passthrough device");
  return driver->remote();
}

TEST(Passthrough, DefaultsAreThe15Ones) {
  testing::BuiltinDevices builtin;
  builtin.load("laser:2 ( driver \"passthrough\" )\n");
  const RemoteDevice& remote = remote_of(builtin.device(protocol::kLaserCode, 2));
  EXPECT_EQ(remote.host, "localhost");
  EXPECT_EQ(remote.port, 6665);
  // The remote index is the `index` option, not this device's index.
  EXPECT_EQ(remote.address, (protocol::DeviceAddress{protocol::kLaserCode, 0}));
  EXPECT_EQ(to_string(remote), "laser:0 on localhost:6665");
}

TEST(Passthrough, OptionsNameTheRemoteDeviceOfThisInterface) {
  testing::BuiltinDevices builtin;
  builtin.load("position:1 ( driver \"passthrough\" host \"bee\" port 7000 index 3 )\n");
  const RemoteDevice& remote = remote_of(builtin.device(protocol::kPositionCode, 1));
  EXPECT_EQ(remote.host, "bee");
  EXPECT_EQ(remote.port, 7000);
  EXPECT_EQ(remote.address, (protocol::DeviceAddress{protocol::kPositionCode, 3}));
}

TEST(Passthrough, BadOptionsAreConfigErrorsNamingThem) {
  const std::vector<std::pair<std::string, std::string>> cases = {
      {"port 0", "port 0 is not a TCP port"},
      {"port 65536", "port 65536 is not a TCP port"},
      {"index -1", "index -1 is not a device index"},
      {"host \"\"", "host is empty"},
  };
  for (const auto& [options, expected] : cases) {
    testing::BuiltinDevices builtin;
    try {
      builtin.load("laser ( driver \"passthrough\" " + options + " )\n");
      ADD_FAILURE() << options << ": expected a ConfigError";
    } catch (const config::ConfigError& e) {
      EXPECT_NE(std::string(e.what()).find(expected), std::string::npos) << e.what();
      EXPECT_NE(std::string(e.what()).find("test.cfg:1:"), std::string::npos) << e.what();
    }
  }
}

TEST(Passthrough, ServesEveryInterfaceWithAllAccessAndQueuesOnlyMessages) {
  core::DriverRegistry registry;
  register_builtin_drivers(registry);
  const core::DriverSpec* spec = registry.find("passthrough");
  ASSERT_NE(spec, nullptr);
  EXPECT_EQ(spec->interfaces.size(), protocol::all_interfaces().size());
  EXPECT_EQ(spec->access, Access::kAll);

  testing::BuiltinDevices builtin;
  builtin.load(
      "laser ( driver \"passthrough\" )\n"
      "comms ( driver \"passthrough\" )\n");
  EXPECT_FALSE(builtin.device(protocol::kLaserCode).queues_data());
  EXPECT_EQ(builtin.device(protocol::kLaserCode).info().limits.command_queue, 0u);
  EXPECT_TRUE(builtin.device(protocol::kCommsCode).queues_data());
  EXPECT_GT(builtin.device(protocol::kCommsCode).info().limits.command_queue, 0u);
}

TEST(Passthrough, NoServerAtTheRemotePortRefusesTheSubscriptionWithALogLine) {
  // A port bound but not listening: connections to it are refused, and no
  // other program can take it while the test runs.
  boost::asio::io_context io;
  boost::asio::ip::tcp::socket holder(io);
  holder.open(boost::asio::ip::tcp::v4());
  holder.bind({boost::asio::ip::make_address_v4("127.0.0.1"), 0});
  const std::string port = std::to_string(holder.local_endpoint().port());

  testing::BuiltinDevices builtin;
  std::mutex mutex;
  std::vector<std::string> lines;
  builtin.logger.set_sink([&](core::LogLevel, std::string_view line) {
    std::lock_guard lock(mutex);
    lines.emplace_back(line);
  });
  builtin.load("sonar ( driver \"passthrough\" host \"127.0.0.1\" port " + port + " index 4 )\n");
  core::Device& sonar = builtin.device(protocol::kSonarCode);
  EXPECT_FALSE(sonar.subscribe());
  EXPECT_EQ(sonar.subscriptions(), 0);
  std::lock_guard lock(mutex);
  ASSERT_EQ(lines.size(), 1u);
  EXPECT_NE(lines[0].find("sonar:0@6665 (passthrough): setup failed"), std::string::npos) << lines[0];
  EXPECT_NE(lines[0].find("sonar:4"), std::string::npos) << lines[0];
  EXPECT_NE(lines[0].find("127.0.0.1:" + port), std::string::npos) << lines[0];
}

}  // namespace passthrough_driver_test
}  // namespace playerkit::drivers
