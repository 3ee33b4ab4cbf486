#include "interfaces/ptz_requests.hpp"

#include <gtest/gtest.h>

#include <vector>

#include "protocol/binary_codec.hpp"

namespace playerkit::interfaces {
namespace ptz_requests_test {

using Bytes = std::vector<std::uint8_t>;

// Position control only, as the simulator's head; echoes generic commands.
struct Head final : PtzHead {
  bool set_control_mode(std::uint8_t mode) override {
    modes.push_back(mode);
    return mode == protocol::kPtzPositionControl;
  }
  std::optional<protocol::PtzGenericConfig> generic_config(const protocol::PtzGenericConfig& command) override {
    return command;
  }
  std::vector<std::uint8_t> modes;
};

core::Request request(Bytes payload) {
  core::Request r;
  r.payload = std::move(payload);
  return r;
}

TEST(PtzRequests, ControlModeIsTheHeadsToAccept) {
  Head head;
  const core::RequestResult position = answer_ptz_request(head, request({2, 1}));
  EXPECT_EQ(position.type, protocol::MessageType::kAck);
  EXPECT_TRUE(position.payload.empty());
  EXPECT_EQ(answer_ptz_request(head, request({2, 0})).type, protocol::MessageType::kNack);
  EXPECT_EQ(head.modes, (std::vector<std::uint8_t>{1, 0}));
}

TEST(PtzRequests, GenericConfigCarriesTheUnitsBytesBothWays) {
  Head head;
  // subtype @0, length uint16 @1, config[32] @3.
  Bytes payload(35, 0);
  payload[0] = 1;
  payload[2] = 3;
  payload[3] = 0x81;
  payload[4] = 0x09;
  payload[5] = 0xFF;
  const core::RequestResult reply = answer_ptz_request(head, request(payload));
  ASSERT_EQ(reply.type, protocol::MessageType::kAck);
  EXPECT_EQ(reply.payload, payload);
  PtzHead nothing;
  EXPECT_EQ(answer_ptz_request(nothing, request(payload)).type, protocol::MessageType::kNack);
}

TEST(PtzRequests, WrongSizesAndUnknownSubtypesAreNacked) {
  Head head;
  Bytes overlong(35, 0);
  overlong[0] = 1;
  overlong[2] = 33;  // more than config[] holds
  for (const Bytes& payload : {Bytes{}, Bytes{2}, Bytes{2, 1, 0}, Bytes{1, 0, 0}, overlong, Bytes{3, 1}}) {
    EXPECT_EQ(answer_ptz_request(head, request(payload)).type, protocol::MessageType::kNack)
        << ::testing::PrintToString(payload);
  }
  EXPECT_TRUE(head.modes.empty());
}

}  // namespace ptz_requests_test
}  // namespace playerkit::interfaces
