// The passthrough driver (manual §7.31) between real servers on loopback: a
// client of the aggregating server talks to the robots' devices through it.

#include "drivers/passthrough/passthrough_driver.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <chrono>
#include <latch>
#include <memory>
#include <optional>
#include <string>
#include <thread>
#include <vector>

#include "client/client.hpp"
#include "drivers/builtin.hpp"
#include "fixed_port_server.hpp"
#include "protocol/binary_codec.hpp"
#include "protocol/interfaces.hpp"
#include "protocol/messages/laser.hpp"
#include "protocol/messages/position.hpp"
#include "support/eventually.hpp"
#include "test_server.hpp"

namespace playerkit::drivers {
namespace passthrough_test {

using namespace std::chrono_literals;
using client::Client;
using playerkit::testing::eventually;
using playerkit::testing::FixedPortServer;
using playerkit::testing::TestServer;
using protocol::Access;
using protocol::DeviceAddress;
using protocol::Message;
using protocol::MessageType;
using protocol::Timestamp;
using Bytes = std::vector<std::uint8_t>;

// Generous: the machine may be busy (sanitizers, parallel tests); passing
// tests never wait this long.
constexpr std::chrono::milliseconds kWait = 10s;

constexpr const char* kRobotConfig =
    "position:0 ( driver \"actuator\" )\n"
    "laser:0 ( driver \"source\" )\n";

constexpr DeviceAddress kPosition0{protocol::kPositionCode, 0};
constexpr DeviceAddress kPosition1{protocol::kPositionCode, 1};
constexpr DeviceAddress kLaser0{protocol::kLaserCode, 0};
constexpr DeviceAddress kLaser1{protocol::kLaserCode, 1};

void with_builtin_drivers(core::DriverRegistry& registry) { register_builtin_drivers(registry); }

std::string passthrough(const std::string& local, std::uint16_t port, int index) {
  return local + " ( driver \"passthrough\" host \"127.0.0.1\" port " + std::to_string(port) +
         " index " + std::to_string(index) + " )\n";
}

protocol::LaserData laser_scan(std::uint16_t first_range) {
  protocol::LaserData scan;
  scan.min_angle = -9000;
  scan.max_angle = 9000;
  scan.resolution = 100;
  scan.range_res = 1;
  scan.range_count = 3;
  for (std::uint16_t i = 0; i < 3; ++i) {
    scan.ranges[i] = static_cast<std::uint16_t>(first_range + 10 * i);
    scan.intensity[i] = static_cast<std::uint8_t>(i + 1);
  }
  return scan;
}

Bytes velocity(std::int32_t xspeed, std::int32_t yawspeed) {
  protocol::PositionCommand command;
  command.xspeed = xspeed;
  command.yawspeed = yawspeed;
  command.state = 1;
  return protocol::encode(command);
}

// Reads until each of `devices` has sent a DATA message with the wanted
// timestamp; the first such message of each, in the order asked for.
std::vector<std::optional<Message>> await_data(Client& client,
                                               const std::vector<DeviceAddress>& devices,
                                               Timestamp wanted_for_all = {}) {
  std::vector<std::optional<Message>> found(devices.size());
  const auto all_found = [&] {
    return std::all_of(found.begin(), found.end(), [](const auto& m) { return m.has_value(); });
  };
  eventually(
      [&] {
        auto message = client.read(50ms);
        if (!message || message->type() != MessageType::kData) return all_found();
        for (std::size_t i = 0; i < devices.size(); ++i) {
          const bool timestamp_ok =
              wanted_for_all == Timestamp{} || message->timestamp() == wanted_for_all;
          if (!found[i] && message->device() == devices[i] && timestamp_ok) found[i] = *message;
        }
        return all_found();
      },
      kWait);
  return found;
}

bool command_arrives(core::Device& actuator, const Bytes& expected) {
  return eventually(
      [&] {
        const auto command = actuator.latest_command();
        return command && command->payload == expected;
      },
      kWait);
}

// Manual §7.31, first example: bee and bug aggregated by orac.
TEST(Passthrough, OneServerAggregatesTwoRobots) {
  TestServer bee(kRobotConfig);
  TestServer bug(kRobotConfig);
  TestServer orac(passthrough("position:0", bee.port(), 0) + passthrough("laser:0", bee.port(), 0) +
                      passthrough("position:1", bug.port(), 0) +
                      passthrough("laser:1", bug.port(), 0),
                  {}, 0, with_builtin_drivers);
  auto client = Client::connect("127.0.0.1", orac.port());

  const auto list = client.device_list();
  ASSERT_EQ(list.size(), 4u);
  const std::vector<DeviceAddress> expected{kPosition0, kLaser0, kPosition1, kLaser1};
  for (std::size_t i = 0; i < list.size(); ++i) {
    EXPECT_EQ(list[i].address, expected[i]) << i;
    EXPECT_EQ(list[i].port, orac.port());
    EXPECT_EQ(list[i].driver_name, "passthrough");
  }
  for (const DeviceAddress device : {kPosition0, kPosition1}) {
    const auto grant = client.request_access(device, Access::kAll);
    EXPECT_EQ(grant.access, Access::kAll);
    EXPECT_EQ(grant.driver_name, "passthrough");
  }
  for (const DeviceAddress device : {kLaser0, kLaser1}) {
    EXPECT_EQ(client.request_access(device, Access::kRead).access, Access::kRead);
  }

  // Each robot's scan, with its own time of measurement.
  const Timestamp bee_time{1'100'000'000, 111'111};
  const Timestamp bug_time{1'200'000'000, 222'222};
  bee.device("laser:0").publish(protocol::encode(laser_scan(1000)), bee_time);
  bug.device("laser:0").publish(protocol::encode(laser_scan(4000)), bug_time);
  const auto scans = await_data(client, {kLaser0, kLaser1});
  ASSERT_TRUE(scans[0] && scans[1]);
  EXPECT_EQ(scans[0]->timestamp(), bee_time);
  EXPECT_EQ(scans[1]->timestamp(), bug_time);
  EXPECT_EQ(protocol::decode<protocol::LaserData>(scans[0]->payload), laser_scan(1000));
  EXPECT_EQ(protocol::decode<protocol::LaserData>(scans[1]->payload), laser_scan(4000));

  // Each robot gets the command written to its device, and only that one.
  client.write_command(kPosition0, velocity(300, 10));
  client.write_command(kPosition1, velocity(-200, -5));
  EXPECT_TRUE(command_arrives(bee.device("position:0"), velocity(300, 10)));
  EXPECT_TRUE(command_arrives(bug.device("position:0"), velocity(-200, -5)));
}

TEST(Passthrough, RequestsGoToTheRemoteAndEachReplyToTheClientThatAsked) {
  // slowreply answers after 200 ms from a queue of one: two requests at once
  // only both succeed if the passthrough queues them and asks in turn.
  TestServer robot(
      "sonar:0 ( driver \"slowreply\" )\n"
      "sonar:1 ( driver \"echo\" )\n");
  TestServer orac(passthrough("sonar:0", robot.port(), 0) + passthrough("sonar:1", robot.port(), 1),
                  {}, 0, with_builtin_drivers);
  constexpr DeviceAddress kSlow{protocol::kSonarCode, 0};
  constexpr DeviceAddress kEcho{protocol::kSonarCode, 1};

  constexpr int kClients = 2;
  std::latch ready(kClients);
  std::vector<Message> replies(kClients);
  std::vector<std::string> failures(kClients);
  std::vector<std::thread> threads;
  for (int id = 0; id < kClients; ++id) {
    threads.emplace_back([&, id] {
      try {
        auto client = Client::connect("127.0.0.1", orac.port());
        client.set_timeout(kWait);
        client.request_access(kSlow, Access::kAll);
        const auto mark = static_cast<std::uint8_t>(0x40 + id);
        ready.arrive_and_wait();
        replies[static_cast<std::size_t>(id)] = client.request(kSlow, Bytes{1, mark, mark, mark});
      } catch (const std::exception& e) {
        failures[static_cast<std::size_t>(id)] = e.what();
      }
    });
  }
  for (auto& thread : threads) thread.join();
  for (int id = 0; id < kClients; ++id) {
    const auto i = static_cast<std::size_t>(id);
    ASSERT_EQ(failures[i], "") << "client " << id;
    const auto mark = static_cast<std::uint8_t>(0x40 + id);
    EXPECT_EQ(replies[i].type(), MessageType::kAck) << "client " << id;
    EXPECT_EQ(replies[i].device(), kSlow);
    EXPECT_EQ(replies[i].payload, (Bytes{1, mark, mark, mark})) << "client " << id;
  }

  // The remote's answer is passed on as it is: ACK with its bytes, or NACK.
  auto client = Client::connect("127.0.0.1", orac.port());
  client.request_access(kEcho, Access::kAll);
  const auto ack = client.request(kEcho, Bytes{1, 7, 8});
  EXPECT_EQ(ack.type(), MessageType::kAck);
  EXPECT_EQ(ack.payload, (Bytes{1, 7, 8}));
  EXPECT_EQ(client.request(kEcho, Bytes{9}).type(), MessageType::kNack);
}

// robot <- relay 1 <- ... <- the server the client uses.
void expect_chain_delivers(int servers) {
  std::vector<std::unique_ptr<TestServer>> chain;
  chain.push_back(std::make_unique<TestServer>(kRobotConfig));
  while (static_cast<int>(chain.size()) < servers) {
    const std::uint16_t upstream = chain.back()->port();
    chain.push_back(std::make_unique<TestServer>(
        passthrough("position:0", upstream, 0) + passthrough("laser:0", upstream, 0), server::ServerOptions{},
        0, with_builtin_drivers));
  }
  TestServer& robot = *chain.front();
  auto client = Client::connect("127.0.0.1", chain.back()->port());
  ASSERT_EQ(client.request_access(kLaser0, Access::kRead).access, Access::kRead);
  ASSERT_EQ(client.request_access(kPosition0, Access::kAll).access, Access::kAll);

  const Timestamp taken{1'300'000'000, 5};
  robot.device("laser:0").publish(protocol::encode(laser_scan(2500)), taken);
  const auto scans = await_data(client, {kLaser0});
  ASSERT_TRUE(scans[0]);
  EXPECT_EQ(scans[0]->timestamp(), taken);
  EXPECT_EQ(protocol::decode<protocol::LaserData>(scans[0]->payload), laser_scan(2500));

  client.write_command(kPosition0, velocity(123, 4));
  EXPECT_TRUE(command_arrives(robot.device("position:0"), velocity(123, 4)));
}

TEST(Passthrough, ChainOfTwoServersDeliversEndToEnd) { expect_chain_delivers(2); }

TEST(Passthrough, ChainOfThreeServersDeliversEndToEnd) { expect_chain_delivers(3); }

TEST(Passthrough, CommsMessagesAndCommandsAreAllPassedOnInOrder) {
  const auto with_mailbox = [](core::DriverRegistry& registry) {
    registry.add({"mailbox", {protocol::kCommsCode}, Access::kAll,
                  [](const core::DriverContext&) { return std::make_unique<core::Driver>(); },
                  core::DeviceLimits{.request_queue = 8, .data_queue = 64, .command_queue = 64},
                  "a queued comms device"});
  };
  TestServer robot("comms:0 ( driver \"mailbox\" )\n", {}, 0, with_mailbox);
  TestServer orac(passthrough("comms:0", robot.port(), 0), {}, 0, with_builtin_drivers);
  constexpr DeviceAddress kComms{protocol::kCommsCode, 0};
  auto client = Client::connect("127.0.0.1", orac.port());
  ASSERT_EQ(client.request_access(kComms, Access::kAll).access, Access::kAll);

  // A burst: the remote sends all five in one round; all five must come out.
  constexpr std::uint8_t kBurst = 5;
  for (std::uint8_t i = 1; i <= kBurst; ++i) {
    robot.device("comms:0").publish(Bytes{i, 0xAA}, Timestamp{1'400'000'000, i});
  }
  Bytes received;
  eventually(
      [&] {
        const auto message = client.read(50ms);
        if (message && message->type() == MessageType::kData && message->device() == kComms) {
          received.push_back(message->payload.at(0));
        }
        return received.size() >= kBurst;
      },
      kWait);
  EXPECT_EQ(received, (Bytes{1, 2, 3, 4, 5}));

  for (std::uint8_t i = 1; i <= kBurst; ++i) client.write_command(kComms, Bytes{static_cast<std::uint8_t>(10 + i)});
  Bytes sent;
  eventually(
      [&] {
        while (const auto command = robot.device("comms:0").take_command()) {
          sent.push_back(command->payload.at(0));
        }
        return sent.size() >= kBurst;
      },
      kWait);
  EXPECT_EQ(sent, (Bytes{11, 12, 13, 14, 15}));
}

std::size_t lines_containing(const TestServer& server, const std::string& text) {
  const auto lines = server.log_lines();
  return static_cast<std::size_t>(std::count_if(lines.begin(), lines.end(), [&](const std::string& line) {
    return line.find(text) != std::string::npos;
  }));
}

TEST(Passthrough, RemoteThatGoesAwayIsReportedOnceAndResumedWhenItReturns) {
  auto robot = std::make_unique<FixedPortServer>(kRobotConfig, 0);
  const std::uint16_t robot_port = robot->port();
  TestServer orac(passthrough("laser:0", robot_port, 0), {}, 0, with_builtin_drivers);
  auto reader = Client::connect("127.0.0.1", orac.port());
  ASSERT_EQ(reader.request_access(kLaser0, Access::kRead).access, Access::kRead);
  robot->device("laser:0").publish(protocol::encode(laser_scan(100)), Timestamp{10, 1});
  ASSERT_TRUE(await_data(reader, {kLaser0}, Timestamp{10, 1})[0]);

  robot.reset();  // the robot's server goes away
  const std::string lost = "lost laser:0 on 127.0.0.1:" + std::to_string(robot_port);
  ASSERT_TRUE(eventually([&] { return orac.logged(lost); }, kWait));
  // Several reconnection attempts later, still one line saying so.
  ASSERT_TRUE(eventually([&] { return lines_containing(orac, "still away") >= 2; }, kWait));
  EXPECT_EQ(lines_containing(orac, lost), 1u);

  // Newcomers are refused; the reader keeps its subscription, and a request
  // is answered at once rather than left waiting.
  auto newcomer = Client::connect("127.0.0.1", orac.port());
  const auto refused = newcomer.request_access(kLaser0, Access::kRead);
  EXPECT_EQ(refused.access, Access::kError);
  EXPECT_EQ(refused.driver_name, "passthrough");
  EXPECT_EQ(reader.request(kLaser0, Bytes{protocol::kLaserGetGeom}).type(), MessageType::kNack);

  // Back on the same port: data flows again to the reader that stayed.
  robot = std::make_unique<FixedPortServer>(kRobotConfig, robot_port);
  robot->device("laser:0").publish(protocol::encode(laser_scan(200)), Timestamp{20, 2});
  const auto resumed = await_data(reader, {kLaser0}, Timestamp{20, 2});
  ASSERT_TRUE(resumed[0]);
  EXPECT_EQ(protocol::decode<protocol::LaserData>(resumed[0]->payload), laser_scan(200));
  EXPECT_TRUE(orac.logged("127.0.0.1:" + std::to_string(robot_port) + " is back"));
  EXPECT_EQ(newcomer.request_access(kLaser0, Access::kRead).access, Access::kRead);
}

TEST(Passthrough, RemoteWithoutTheDeviceOrRefusingItGivesEWithALogLine) {
  TestServer robot(
      "laser:0 ( driver \"source\" )\n"
      "laser:1 ( driver \"refuser\" )\n");
  TestServer orac(passthrough("laser:0", robot.port(), 3) + passthrough("laser:1", robot.port(), 1),
                  {}, 0, with_builtin_drivers);
  const std::string where = "127.0.0.1:" + std::to_string(robot.port());
  auto client = Client::connect("127.0.0.1", orac.port());

  const auto missing = client.request_access(kLaser0, Access::kRead);
  EXPECT_EQ(missing.access, Access::kError);
  EXPECT_EQ(missing.driver_name, "passthrough");
  EXPECT_TRUE(orac.logged("laser:0@" + std::to_string(orac.port()) + " (passthrough): setup failed"));
  EXPECT_TRUE(orac.logged("the remote server " + where + " has no device laser:3"));

  EXPECT_EQ(client.request_access(kLaser1, Access::kAll).access, Access::kError);
  EXPECT_TRUE(orac.logged("the remote server " + where + " refused laser:1 (its driver 'refuser'"));
}

}  // namespace passthrough_test
}  // namespace playerkit::drivers
