// Runs the C checks of playercclient_test.c against a real server on loopback
// and checks, on the server's side, what they sent.

#include <gtest/gtest.h>

#include <algorithm>
#include <cstring>
#include <optional>
#include <string>

#include "playercclient.h"
#include "playercclient_test.h"
#include "protocol/binary_codec.hpp"
#include "protocol/interfaces.hpp"
#include "protocol/messages/position.hpp"
#include "test_server.hpp"

namespace playerkit::testing {
namespace {

constexpr const char* kConfig =
    "laser:0 ( driver \"source\" )\n"
    "position:0 ( driver \"actuator\" )\n"
    "sonar:0 ( driver \"echo\" )\n";

// A failed C check names the file, line and condition that did not hold.
#define EXPECT_C_CHECK_PASSES(call)                 \
  do {                                              \
    const char* failure_ = (call);                  \
    EXPECT_TRUE(failure_ == nullptr) << failure_;   \
  } while (0)

// The hooks the C checks call; exceptions stop here, never cross into C.
struct HookContext {
  TestServer* server;
  std::string error;
  std::optional<std::vector<std::uint8_t>> position_command;  // as the hook saw it
};

int publish_laser(void* context, const unsigned char* bytes, std::size_t length,
                  std::uint32_t sec, std::uint32_t usec) {
  auto* hooks = static_cast<HookContext*>(context);
  try {
    hooks->server->device("laser:0").publish(std::vector<std::uint8_t>(bytes, bytes + length),
                                              protocol::Timestamp{sec, usec});
    return 0;
  } catch (const std::exception& e) {
    hooks->error = e.what();
    return -1;
  }
}

int copy_position_command(void* context, unsigned char* bytes, std::size_t capacity,
                          std::size_t* length) {
  auto* hooks = static_cast<HookContext*>(context);
  try {
    core::Device& position = hooks->server->device("position:0");
    if (!eventually([&] { return position.latest_command().has_value(); })) return -1;
    hooks->position_command = position.latest_command()->payload;
    *length = std::min(capacity, hooks->position_command->size());
    std::memcpy(bytes, hooks->position_command->data(), *length);
    return 0;
  } catch (const std::exception& e) {
    hooks->error = e.what();
    return -1;
  }
}

int stop_server(void* context) {
  auto* hooks = static_cast<HookContext*>(context);
  try {
    hooks->server->stop();
    return 0;
  } catch (const std::exception& e) {
    hooks->error = e.what();
    return -1;
  }
}

class PlayerCClientTest : public ::testing::Test {
 protected:
  // Every test leaves the process-wide debug level as it found it.
  void SetUp() override { saved_level_ = player_debug_level(-1); }
  void TearDown() override {
    player_debug_level(saved_level_);
    EXPECT_EQ(hooks_.error, "") << "a hook failed";
  }

  const pcc_server* server() { return &c_view_; }

  // The command the C check had the hook fetch, decoded here on its own.
  std::optional<protocol::PositionCommand> position_command() const {
    if (!hooks_.position_command) return std::nullopt;
    return protocol::decode<protocol::PositionCommand>(*hooks_.position_command);
  }

 private:
  int saved_level_ = 0;
  TestServer test_server_{kConfig};
  HookContext hooks_{&test_server_, {}, std::nullopt};
  pcc_server c_view_{test_server_.port(), &hooks_, publish_laser, copy_position_command,
                     stop_server};
};

TEST(PlayerCClientHeaderTest, StructLayoutsAreTheWiresInStrictC89) {
  EXPECT_C_CHECK_PASSES(pcc_c89_check_struct_layouts());
}

#define PCC_INTERFACE(NAME) {"PLAYER_" #NAME "_CODE", PLAYER_##NAME##_CODE, PLAYER_##NAME##_STRING}

TEST(PlayerCClientHeaderTest, InterfaceCodesAndNamesAreTheProtocolLibrarys) {
  struct Entry {
    const char* constant;
    int code;
    const char* name;
  };
  const Entry header[] = {
      PCC_INTERFACE(PLAYER),     PCC_INTERFACE(POWER),      PCC_INTERFACE(GRIPPER),
      PCC_INTERFACE(POSITION),   PCC_INTERFACE(SONAR),      PCC_INTERFACE(LASER),
      PCC_INTERFACE(BLOBFINDER), PCC_INTERFACE(PTZ),        PCC_INTERFACE(AUDIO),
      PCC_INTERFACE(FIDUCIAL),   PCC_INTERFACE(COMMS),      PCC_INTERFACE(SPEECH),
      PCC_INTERFACE(GPS),        PCC_INTERFACE(BUMPER),     PCC_INTERFACE(TRUTH),
      PCC_INTERFACE(IDARTURRET), PCC_INTERFACE(IDAR),       PCC_INTERFACE(DESCARTES),
      PCC_INTERFACE(DIO),        PCC_INTERFACE(AIO),        PCC_INTERFACE(IR),
      PCC_INTERFACE(WIFI),       PCC_INTERFACE(WAVEFORM),   PCC_INTERFACE(LOCALIZE),
      PCC_INTERFACE(MCOM),       PCC_INTERFACE(SOUND),      PCC_INTERFACE(AUDIODSP),
      PCC_INTERFACE(AUDIOMIXER), PCC_INTERFACE(POSITION3D), PCC_INTERFACE(SIMULATION),
      PCC_INTERFACE(SERVICE_ADV), PCC_INTERFACE(BLINKENLIGHT), PCC_INTERFACE(NOMAD),
      PCC_INTERFACE(CAMERA),     PCC_INTERFACE(NULL),
  };
  ASSERT_EQ(std::size(header), protocol::all_interfaces().size());
  for (const Entry& entry : header) {
    const auto* info = protocol::find_interface(static_cast<std::uint16_t>(entry.code));
    ASSERT_NE(info, nullptr) << entry.constant;
    EXPECT_EQ(info->constant, entry.constant);
    EXPECT_EQ(info->name, entry.name);
  }
}

TEST(PlayerCClientHeaderTest, MessageTypesAndModesAreThoseOfTheWire) {
  EXPECT_EQ(PLAYER_MSGTYPE_DATA, static_cast<int>(protocol::MessageType::kData));
  EXPECT_EQ(PLAYER_MSGTYPE_CMD, static_cast<int>(protocol::MessageType::kCommand));
  EXPECT_EQ(PLAYER_MSGTYPE_REQ, static_cast<int>(protocol::MessageType::kRequest));
  EXPECT_EQ(PLAYER_MSGTYPE_RESP_ACK, static_cast<int>(protocol::MessageType::kAck));
  EXPECT_EQ(PLAYER_MSGTYPE_SYNCH, static_cast<int>(protocol::MessageType::kSynch));
  EXPECT_EQ(PLAYER_MSGTYPE_RESP_NACK, static_cast<int>(protocol::MessageType::kNack));
  EXPECT_EQ(PLAYER_MSGTYPE_RESP_ERR, static_cast<int>(protocol::MessageType::kError));
  EXPECT_EQ(PLAYER_READ_MODE, static_cast<char>(protocol::Access::kRead));
  EXPECT_EQ(PLAYER_WRITE_MODE, static_cast<char>(protocol::Access::kWrite));
  EXPECT_EQ(PLAYER_ALL_MODE, static_cast<char>(protocol::Access::kAll));
  EXPECT_EQ(PLAYER_CLOSE_MODE, static_cast<char>(protocol::Access::kClose));
  EXPECT_EQ(PLAYER_ERROR_MODE, static_cast<char>(protocol::Access::kError));
  EXPECT_EQ(PLAYER_DATAMODE_PUSH_ALL, static_cast<int>(protocol::DataMode::kPushAll));
  EXPECT_EQ(PLAYER_DATAMODE_PULL_ALL, static_cast<int>(protocol::DataMode::kPullAll));
  EXPECT_EQ(PLAYER_DATAMODE_PUSH_NEW, static_cast<int>(protocol::DataMode::kPushNew));
  EXPECT_EQ(PLAYER_DATAMODE_PULL_NEW, static_cast<int>(protocol::DataMode::kPullNew));
  EXPECT_EQ(PLAYER_PLAYER_DEV_REQ, protocol::kPlayerDevReq);
  EXPECT_EQ(PLAYER_PLAYER_AUTH_REQ, protocol::kPlayerAuthReq);
  EXPECT_EQ(PLAYER_PLAYER_NAMESERVICE_REQ, protocol::kPlayerNameserviceReq);
  EXPECT_EQ(PLAYER_KEYLEN, protocol::kKeyLength);
  EXPECT_EQ(PLAYER_MAX_REQREP_SIZE, protocol::kMaxRequestReplySize);
  EXPECT_STREQ(PLAYER_IDENT_STRING, "Player v.");
}

TEST_F(PlayerCClientTest, TheAppendixFragmentsWorkAsWritten) {
  EXPECT_C_CHECK_PASSES(pcc_c89_appendix_example(server()));
  const auto command = position_command();
  ASSERT_TRUE(command);
  EXPECT_EQ(command->yawspeed, 40);
  EXPECT_EQ(command->xspeed, 0);
}

TEST_F(PlayerCClientTest, ConnectReadsTheBannerAndGivesTheSocket) {
  EXPECT_C_CHECK_PASSES(pcc_check_connect_reads_banner_and_socket(server()));
}

TEST(PlayerCClientFailureTest, ConnectFailsCleanlyOnAClosedPortAndBadArguments) {
  EXPECT_C_CHECK_PASSES(pcc_check_connect_failures());
}

TEST_F(PlayerCClientTest, DeviceAccessReportsTheGrantIncludingErrorForAMissingDevice) {
  EXPECT_C_CHECK_PASSES(pcc_check_device_access(server()));
}

TEST_F(PlayerCClientTest, ReadGivesTheHeaderInHostOrderAndThePayloadAsSent) {
  EXPECT_C_CHECK_PASSES(pcc_check_read_data_header_in_host_order(server()));
}

TEST_F(PlayerCClientTest, ReadCutsAPayloadLongerThanTheBuffer) {
  EXPECT_C_CHECK_PASSES(pcc_check_read_cuts_long_payloads(server()));
}

TEST_F(PlayerCClientTest, WriteSendsTheCommandAsGiven) {
  EXPECT_C_CHECK_PASSES(pcc_check_write_command(server()));
  const auto command = position_command();
  ASSERT_TRUE(command);
  EXPECT_EQ(command->xspeed, 300);
  EXPECT_EQ(command->yawspeed, -40);
  EXPECT_EQ(command->state, 1);
  EXPECT_EQ(command->xpos, 0);
}

TEST_F(PlayerCClientTest, WriteRefusesOversizedAndMissingCommandsAndStaysInStep) {
  EXPECT_C_CHECK_PASSES(pcc_check_write_refuses_bad_commands(server()));
}

TEST_F(PlayerCClientTest, RequestReturnsTheMatchingReplyWithoutOverrun) {
  EXPECT_C_CHECK_PASSES(pcc_check_request_and_replies(server()));
}

TEST_F(PlayerCClientTest, RequestRefusesOversizedEmptyAndMissingPayloads) {
  EXPECT_C_CHECK_PASSES(pcc_check_request_refuses_bad_payloads(server()));
}

TEST_F(PlayerCClientTest, DisconnectedConnectionFailsEveryCall) {
  EXPECT_C_CHECK_PASSES(pcc_check_use_after_disconnect(server()));
}

TEST_F(PlayerCClientTest, ALostConnectionIsMinusOneNotAnException) {
  EXPECT_C_CHECK_PASSES(pcc_check_lost_connection(server()));
}

TEST_F(PlayerCClientTest, DebugLevelReturnsThePreviousLevel) {
  EXPECT_C_CHECK_PASSES(pcc_check_debug_level());
}

TEST_F(PlayerCClientTest, DiagnosticsFollowTheDebugLevel) {
  EXPECT_C_CHECK_PASSES(pcc_check_diagnostics_follow_debug_level(server()));
}

}  // namespace
}  // namespace playerkit::testing
