#include "client/endpoint.hpp"

#include <stdexcept>
#include <string>
#include <vector>

#include <gtest/gtest.h>

namespace playerkit::client {
namespace endpoint_test {

TEST(ParseServerEndpoint, HostAloneKeepsThePlayerPort) {
  EXPECT_EQ(parse_server_endpoint("robot1"), (ServerEndpoint{"robot1", 6665}));
}

TEST(ParseServerEndpoint, HostAndPort) {
  EXPECT_EQ(parse_server_endpoint("127.0.0.1:7000"), (ServerEndpoint{"127.0.0.1", 7000}));
}

TEST(ParseServerEndpoint, PortAloneMeansLocalhost) {
  EXPECT_EQ(parse_server_endpoint(":7000"), (ServerEndpoint{"localhost", 7000}));
}

TEST(ParseServerEndpoint, BracketedIpv6WithAndWithoutPort) {
  EXPECT_EQ(parse_server_endpoint("[::1]:7000"), (ServerEndpoint{"::1", 7000}));
  EXPECT_EQ(parse_server_endpoint("[::1]"), (ServerEndpoint{"::1", 6665}));
  EXPECT_EQ(parse_server_endpoint("::1"), (ServerEndpoint{"::1", 6665}));
}

TEST(ParseServerEndpoint, RefusesBadPorts) {
  EXPECT_FALSE(parse_server_endpoint("host:0"));
  EXPECT_FALSE(parse_server_endpoint("host:65536"));
  EXPECT_FALSE(parse_server_endpoint("host:x"));
  EXPECT_FALSE(parse_server_endpoint("host:"));
  EXPECT_FALSE(parse_server_endpoint("[::1]x"));
  EXPECT_FALSE(parse_server_endpoint("[::1"));
  EXPECT_FALSE(parse_server_endpoint(""));
}

TEST(ServerEndpointToString, BracketsIpv6) {
  EXPECT_EQ(to_string(ServerEndpoint{"localhost", 6665}), "localhost:6665");
  EXPECT_EQ(to_string(ServerEndpoint{"::1", 7000}), "[::1]:7000");
}

TEST(SplitToolTarget, ADeviceFirstMeansTheDefaultServer) {
  const std::vector<std::string> arguments{"laser:0", "position"};
  const auto target = split_tool_target(arguments);
  EXPECT_EQ(target.server, ServerEndpoint{});
  EXPECT_EQ(target.rest, arguments);
}

TEST(SplitToolTarget, AHostFirstIsTheServer) {
  const std::vector<std::string> arguments{"robot1:7000", "laser:0", "sonar"};
  const auto target = split_tool_target(arguments);
  EXPECT_EQ(target.server, (ServerEndpoint{"robot1", 7000}));
  EXPECT_EQ(target.rest, (std::vector<std::string>{"laser:0", "sonar"}));
}

TEST(SplitToolTarget, AnInterfaceNameWithAnIndexIsADeviceNotAHost) {
  const std::vector<std::string> arguments{"laser:6665"};
  EXPECT_EQ(split_tool_target(arguments).server, ServerEndpoint{});
}

TEST(SplitToolTarget, RefusesAFirstArgumentThatIsNeither) {
  const std::vector<std::string> arguments{"robot1:notaport", "laser"};
  EXPECT_THROW(split_tool_target(arguments), std::invalid_argument);
}

TEST(SplitToolTarget, NothingGivenIsTheDefaultServerAndNoDevices) {
  const auto target = split_tool_target({});
  EXPECT_EQ(target.server, ServerEndpoint{});
  EXPECT_TRUE(target.rest.empty());
}

}  // namespace endpoint_test
}  // namespace playerkit::client
