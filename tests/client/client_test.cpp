// lib/client against player-serve's library on loopback.

#include "client/client.hpp"

#include <gtest/gtest.h>

#include <poll.h>

#include <boost/asio/ip/tcp.hpp>
#include <boost/asio/write.hpp>

#include "core/driver.hpp"
#include "protocol/binary_codec.hpp"
#include "protocol/interfaces.hpp"
#include "protocol/messages/position.hpp"
#include "test_server.hpp"

namespace playerkit::client {
namespace client_test {

using protocol::Access;
using protocol::MessageType;
using testing::TestServer;
using Bytes = std::vector<std::uint8_t>;

constexpr const char* kConfig =
    "position:0 ( driver \"actuator\" )\n"
    "laser:0 ( driver \"echo\" )\n"
    "sonar:0 ( driver \"source\" )\n";
constexpr protocol::DeviceAddress kPosition{protocol::kPositionCode, 0};
constexpr protocol::DeviceAddress kLaser{protocol::kLaserCode, 0};
constexpr protocol::DeviceAddress kSonar{protocol::kSonarCode, 0};

TEST(ClientTest, ConnectsAndReadsTheBanner) {
  TestServer server(kConfig);
  auto client = Client::connect("127.0.0.1", server.port());
  EXPECT_EQ(client.server_version(), "1.5");
  const auto first = client.read(2s);
  ASSERT_TRUE(first);
  EXPECT_EQ(first->type(), MessageType::kSynch);
}

TEST(ClientTest, ConnectionRefusedIsAClearError) {
  std::uint16_t closed_port = 0;
  {
    boost::asio::io_context io;
    boost::asio::ip::tcp::acceptor probe(io, {boost::asio::ip::make_address("127.0.0.1"), 0});
    closed_port = probe.local_endpoint().port();
  }
  try {
    Client::connect("127.0.0.1", closed_port, 2s);
    FAIL() << "expected a ClientError";
  } catch (const ClientError& e) {
    EXPECT_NE(std::string(e.what()).find("cannot connect to 127.0.0.1:" + std::to_string(closed_port)),
              std::string::npos)
        << e.what();
  }
}

TEST(ClientTest, ASilentPeerIsATimeoutAndNotAPlayerServerAnError) {
  boost::asio::io_context io;
  const auto loopback = boost::asio::ip::make_address("127.0.0.1");
  // The kernel completes the handshake for the backlog: connected, but no banner.
  boost::asio::ip::tcp::acceptor silent(io, {loopback, 0});
  EXPECT_THROW(Client::connect("127.0.0.1", silent.local_endpoint().port(), 300ms), TimeoutError);

  boost::asio::ip::tcp::acceptor talker(io, {loopback, 0});
  std::thread answer_with_junk([&] {
    boost::asio::ip::tcp::socket peer(io);
    talker.accept(peer);
    const std::string junk(32, '?');
    boost::asio::write(peer, boost::asio::buffer(junk));
  });
  try {
    Client::connect("127.0.0.1", talker.local_endpoint().port(), 2s);
    ADD_FAILURE() << "expected a ClientError";
  } catch (const TimeoutError&) {
    ADD_FAILURE() << "expected the banner check, not a timeout";
  } catch (const ClientError& e) {
    EXPECT_NE(std::string(e.what()).find("not a Player server"), std::string::npos) << e.what();
  }
  answer_with_junk.join();
}

TEST(ClientTest, DeviceListCarriesDriverNames) {
  TestServer server(kConfig);
  auto client = Client::connect("127.0.0.1", server.port());
  const auto devices = client.device_list();
  ASSERT_EQ(devices.size(), 3u);
  EXPECT_EQ(devices[0].address, kPosition);
  EXPECT_EQ(devices[0].driver_name, "actuator");
  EXPECT_EQ(devices[1].driver_name, "echo");
  EXPECT_EQ(devices[2].port, server.port());
}

TEST(ClientTest, AccessRequestsReturnWhatTheServerGranted) {
  TestServer server(kConfig);
  auto client = Client::connect("127.0.0.1", server.port());
  auto grant = client.request_access(kSonar, Access::kRead);
  EXPECT_EQ(grant.access, Access::kRead);
  EXPECT_EQ(grant.driver_name, "source");
  grant = client.request_access({protocol::kSonarCode, 9}, Access::kRead);
  EXPECT_EQ(grant.access, Access::kError);
  EXPECT_EQ(grant.driver_name, "");
}

TEST(ClientTest, DataWaitingDuringARequestIsNotLost) {
  TestServer server(kConfig);
  auto client = Client::connect("127.0.0.1", server.port());
  client.request_access(kSonar, Access::kRead);
  client.request_access(kLaser, Access::kRead);
  client.set_frequency(100);
  server.device("sonar:0").publish({7, 7}, {3, 0});
  // Let data rounds pile up unread, then make a request.
  std::this_thread::sleep_for(100ms);
  const auto reply = client.request(kLaser, Bytes{1, 42});
  EXPECT_EQ(reply.type(), MessageType::kAck);
  EXPECT_EQ(reply.payload, (Bytes{1, 42}));
  // The rounds that came before the reply are still there, data first.
  bool got_data = false;
  for (int i = 0; i < 50 && !got_data; ++i) {
    const auto message = client.read(100ms);
    ASSERT_TRUE(message);
    EXPECT_FALSE(protocol::is_reply(message->type()));
    if (message->type() == MessageType::kData) {
      EXPECT_EQ(message->payload, (Bytes{7, 7}));
      EXPECT_EQ(message->device(), kSonar);
      got_data = true;
    }
  }
  EXPECT_TRUE(got_data);
}

TEST(ClientTest, RequestsGetTheirOwnRepliesInOrder) {
  TestServer server(kConfig);
  auto client = Client::connect("127.0.0.1", server.port());
  client.request_access(kLaser, Access::kRead);
  EXPECT_EQ(client.request(kLaser, Bytes{1, 1}).payload, (Bytes{1, 1}));
  EXPECT_EQ(client.request(kLaser, Bytes{5}).type(), MessageType::kNack);
  EXPECT_EQ(client.request(kPosition, Bytes{1}).type(), MessageType::kError);  // not open
}

TEST(ClientTest, CommandsReachTheDevice) {
  TestServer server(kConfig);
  auto client = Client::connect("127.0.0.1", server.port());
  ASSERT_EQ(client.request_access(kPosition, Access::kAll).access, Access::kAll);
  protocol::PositionCommand command;
  command.xspeed = 250;
  client.write_command(kPosition, protocol::encode(command));
  core::Device& position = server.device("position:0");
  ASSERT_TRUE(testing::eventually([&] { return position.latest_command().has_value(); }));
  EXPECT_EQ(protocol::decode<protocol::PositionCommand>(position.latest_command()->payload).xspeed, 250);
}

TEST(ClientTest, PullModeDeliversOneRoundPerRequest) {
  TestServer server(kConfig);
  auto client = Client::connect("127.0.0.1", server.port());
  client.request_access(kSonar, Access::kRead);
  client.set_data_mode(protocol::DataMode::kPullAll);
  while (client.read(150ms)) {
  }
  server.device("sonar:0").publish({4}, {3, 0});
  client.request_data();
  std::vector<MessageType> types;
  while (auto message = client.read(300ms)) types.push_back(message->type());
  EXPECT_EQ(types, (std::vector<MessageType>{MessageType::kData, MessageType::kSynch}));
  client.set_data_mode(protocol::DataMode::kPushNew);
  EXPECT_THROW(client.request_data(), ClientError);
}

TEST(ClientTest, AuthenticationWithTheRightKeyAndTheWrongOne) {
  server::ServerOptions options;
  options.auth_key = "sesame";
  TestServer server(kConfig, options);
  auto good = Client::connect("127.0.0.1", server.port());
  good.authenticate("sesame");
  EXPECT_EQ(good.request_access(kSonar, Access::kRead).access, Access::kRead);
  auto bad = Client::connect("127.0.0.1", server.port());
  try {
    bad.authenticate("open up");
    ADD_FAILURE() << "expected a ClientError";
  } catch (const ClientError& e) {
    EXPECT_NE(std::string(e.what()).find("closed the connection"), std::string::npos) << e.what();
  }
}

TEST(ClientTest, AuthenticatingWhereNoKeyIsNeededIsRefused) {
  TestServer server(kConfig);
  auto client = Client::connect("127.0.0.1", server.port());
  try {
    client.authenticate("sesame");
    ADD_FAILURE() << "expected a ClientError";
  } catch (const ClientError& e) {
    EXPECT_NE(std::string(e.what()).find("refused by the server"), std::string::npos) << e.what();
  }
  EXPECT_EQ(client.request_access(kSonar, Access::kRead).access, Access::kRead);  // still usable
}

TEST(ClientTest, ServerGoingAwayIsAClientError) {
  auto server = std::make_unique<TestServer>(kConfig);
  auto client = Client::connect("127.0.0.1", server->port());
  server.reset();
  EXPECT_THROW(
      {
        while (client.read(2s)) {
        }
      },
      ClientError);
}

// Answers each request 200 ms late, with the request's bytes, and queues up to 8.
class PatientDriver : public core::ThreadedDriver {
 protected:
  void run(std::stop_token stop) override {
    while (!stop.stop_requested()) {
      if (device().pending_requests() > 0) {
        if (!sleep_for(stop, 200ms)) return;
        device().service_requests();
      }
      if (!sleep_for(stop, 5ms)) return;
    }
  }
  core::RequestResult handle_request(const core::Request& request) override {
    return core::RequestResult::ack(request.payload);
  }
};

void add_patient_driver(core::DriverRegistry& registry) {
  registry.add({"patient", {protocol::kLaserCode}, Access::kAll,
                [](const core::DriverContext&) { return std::make_unique<PatientDriver>(); },
                core::DeviceLimits{8}, "slow answers"});
}

TEST(ClientTest, ALateReplyIsNotTakenForTheNextRequestsReply) {
  TestServer server("laser:0 ( driver \"patient\" )\n", {}, 0, add_patient_driver);
  auto client = Client::connect("127.0.0.1", server.port());
  client.request_access(kLaser, Access::kRead);
  client.set_timeout(50ms);
  EXPECT_THROW(client.request(kLaser, Bytes{1, 1}), TimeoutError);
  client.set_timeout(5s);
  // The first answer (200 ms late) arrives while this request waits.
  EXPECT_EQ(client.request(kLaser, Bytes{1, 2}).payload, (Bytes{1, 2}));
  // The late answer is still delivered to read(), not dropped.
  // (SYNCH rounds keep coming at 10 Hz: bound the search.)
  std::optional<protocol::Message> late_reply;
  for (int i = 0; i < 100 && !late_reply; ++i) {
    auto message = client.read(300ms);
    if (message && protocol::is_reply(message->type())) late_reply = std::move(message);
  }
  ASSERT_TRUE(late_reply);
  EXPECT_EQ(late_reply->payload, (Bytes{1, 1}));
}

TEST(ClientTest, AsyncReadHandlersRunInRunForInArrivalOrder) {
  TestServer server(kConfig);
  auto client = Client::connect("127.0.0.1", server.port());
  client.request_access(kSonar, Access::kRead);
  std::vector<Bytes> data;
  std::function<void(protocol::Message)> on_message = [&](protocol::Message message) {
    if (message.type() == MessageType::kData) data.push_back(message.payload);
    if (data.size() < 2) client.async_read(on_message);  // keep reading
  };
  client.async_read(on_message);
  EXPECT_EQ(client.pending_handlers(), 1u);
  server.device("sonar:0").publish({1}, {3, 0});
  for (int i = 0; i < 50 && data.empty(); ++i) client.run_for(100ms);
  server.device("sonar:0").publish({2}, {4, 0});
  for (int i = 0; i < 50 && data.size() < 2; ++i) client.run_for(100ms);
  EXPECT_EQ(data, (std::vector<Bytes>{{1}, {2}}));
  EXPECT_EQ(client.pending_handlers(), 0u);
  // With no handler pending, run_for returns at once and runs nothing.
  EXPECT_EQ(client.run_for(10s), 0u);
}

TEST(ClientTest, PollRunsHandlersForWhatHasArrivedWithoutWaiting) {
  TestServer server(kConfig);
  auto client = Client::connect("127.0.0.1", server.port());
  client.request_access(kSonar, Access::kRead);
  std::vector<MessageType> types;
  client.async_read([&](protocol::Message message) { types.push_back(message.type()); });
  server.device("sonar:0").publish({9}, {3, 0});
  // Wait on the descriptor, as a select()/poll() loop would, then poll().
  for (int i = 0; i < 50 && types.empty(); ++i) {
    pollfd watch{client.native_handle(), POLLIN, 0};
    ASSERT_GE(::poll(&watch, 1, 100), 0);
    client.poll();
  }
  ASSERT_EQ(types.size(), 1u);  // one handler, one message
  EXPECT_FALSE(protocol::is_reply(types.front()));
  EXPECT_EQ(client.pending_handlers(), 0u);
  EXPECT_EQ(client.poll(), 0u);
}

TEST(ClientTest, ARequestInProgressKeepsItsReplyFromHandlers) {
  TestServer server(kConfig);
  auto client = Client::connect("127.0.0.1", server.port());
  client.request_access(kLaser, Access::kRead);
  std::vector<protocol::Message> handled;
  client.async_read([&](protocol::Message message) { handled.push_back(std::move(message)); });
  EXPECT_EQ(client.request(kLaser, Bytes{1, 3}).payload, (Bytes{1, 3}));
  EXPECT_TRUE(handled.empty());  // handlers run only in poll() and run_for()
  client.run_for(2s);
  ASSERT_EQ(handled.size(), 1u);
  EXPECT_FALSE(protocol::is_reply(handled.front().type()));
}

TEST(ClientTest, NativeHandleIsTheSocketUntilClosed) {
  TestServer server(kConfig);
  auto client = Client::connect("127.0.0.1", server.port());
  EXPECT_GE(client.native_handle(), 0);
  client.close();
  EXPECT_EQ(client.native_handle(), -1);
}

}  // namespace client_test
}  // namespace playerkit::client
