// The LMS 200 emulator request by request, and the Player 1.5 driver's
// start-up (sicklms200.md §1.1) as a scripted host session.

#include "families/sick/emulator/sick_lms200_emulator.hpp"

#include "families/sick/emulator/sick_test_host.hpp"
#include "families/sick/emulator/sick_test_room.hpp"
#include "families/sick/protocol/replies.hpp"
#include "families/sick/protocol/test_bytes.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

namespace playerkit::emulators {
namespace sick_lms200_emulator_test {

using namespace std::chrono_literals;
using testing::TestHost;
using hardware::sick::testing::bytes;
namespace sick = hardware::sick;

const sick::Request kInstallation = sick::InstallationModeRequest{"SICK_LMS"};
const auto kOkBytes = bytes("02 80 03 00 A0 00 10 16 0A");
const auto kRefusalBytes = bytes("02 80 03 00 92 00 10 DE 6E");

// The driver's T6: the F4 block with body[6] (measuring mode) and body[7]
// (unit) changed.
sick::SetConfigRequest configure(const sick::ConfigBlock& current, sick::MeasuringMode mode,
                                 sick::Unit unit) {
  sick::SetConfigRequest request{current};
  request.config.set_measuring_mode(mode);
  request.config.set_unit(unit);
  return request;
}

TEST(SickLms200Emulator, ReferenceSetupAtTheDefaultRate) {
  const grid::OccupancyGrid room = testing::box_room();
  const geometry::Pose2 pose{1.0, 1.2, 0.0};
  SickLms200Emulator device({.map = &room, .pose = pose});
  EXPECT_EQ(device.baud(), 9600);
  TestHost host(device);

  // Steps 3-5: T1 twice at 38400, each given 1000 ms; the device hears noise.
  host.set_baud(38400);
  for (int attempt = 0; attempt < 2; ++attempt) {
    host.send(kInstallation);
    host.wait(1000ms);
    EXPECT_FALSE(host.next_reply()) << "attempt " << attempt;
  }
  EXPECT_TRUE(host.writes().empty());
  EXPECT_GT(device.noise_bytes(), 0u);

  // Step 6a: at 9600 T1 is answered, ACK first.
  host.set_baud(9600);
  host.send(kInstallation);
  ASSERT_EQ(host.writes().size(), 2u);
  EXPECT_EQ(host.writes()[0].second.bytes, std::vector<std::uint8_t>{0x06});
  EXPECT_FALSE(host.writes()[0].second.has_checksum);
  EXPECT_EQ(host.writes()[1].second.bytes, kOkBytes);
  EXPECT_TRUE(host.writes()[1].second.has_checksum);
  EXPECT_EQ(host.next_reply()->code, 0xA0);
  EXPECT_EQ(device.mode(), SickLaserEmulator::Mode::installation);

  // Step 6b: T2 0x40, answered at 9600; then the device listens at 38400.
  EXPECT_EQ(sick::parse_mode_reply(host.ask(sick::BaudRateRequest{38400})), sick::ModeReply{});
  EXPECT_EQ(device.baud(), 38400);
  host.set_baud(38400);  // step 6c

  // Step 8: T3, T4, T5, T6.
  const auto type = sick::parse_type_reply(host.ask(sick::GetTypeRequest{}));
  EXPECT_EQ(type.type, "LMS200;30106        ");
  const auto variant = sick::parse_variant_reply(host.ask(sick::SetVariantRequest{{180, 50}}));
  EXPECT_TRUE(variant.accepted);
  EXPECT_EQ(variant.variant, (sick::Variant{180, 50}));
  const auto config = sick::parse_config_reply(host.ask(sick::GetConfigRequest{}));
  const auto configured = sick::parse_set_config_reply(host.ask(
      configure(config.config, sick::MeasuringMode::reflector_levels, sick::Unit::millimetre)));
  EXPECT_TRUE(configured.accepted);
  EXPECT_EQ(configured.config.measuring_mode(), sick::MeasuringMode::reflector_levels);
  EXPECT_EQ(configured.config.unit(), sick::Unit::millimetre);

  // Step 9: T7, then the stream.
  EXPECT_EQ(sick::parse_mode_reply(host.ask(sick::StreamAllRequest{})), sick::ModeReply{});
  host.wait(1s);
  const auto scans = testing::scans_of(host.drain());
  ASSERT_GE(scans.size(), 4u);
  for (const sick::Scan& scan : scans) {
    EXPECT_FALSE(scan.subrange);
    EXPECT_EQ(scan.unit, sick::Unit::millimetre);
    ASSERT_EQ(scan.values.size(), 361u);
    for (std::size_t i = 0; i < 361; ++i) {
      const double angle = -std::numbers::pi / 2 + static_cast<double>(i) * std::numbers::pi / 360;
      const double expected_mm = 1000.0 * testing::room_range(pose.translation(), angle);
      EXPECT_NEAR(sick::distance_of(scan.values[i]), expected_mm, 1.0) << "value " << i;
      EXPECT_EQ(sick::flags_of(scan.values[i]), 0) << "value " << i;
    }
  }
  EXPECT_EQ(device.mode(), SickLaserEmulator::Mode::streaming_all);
}

TEST(SickLms200Emulator, HighSpeedStepSwitchesTo500000AfterAnswering) {
  SickLms200Emulator device({.power_up_baud = 38400});
  TestHost host(device, 38400);
  host.ask(kInstallation);
  EXPECT_EQ(host.ask(sick::BaudRateRequest{500000}).code, 0xA0);
  EXPECT_EQ(device.baud(), 500000);
  // The host still at 38400 is not heard any more.
  host.send(sick::GetTypeRequest{});
  EXPECT_FALSE(host.next_reply());
  host.set_baud(500000);
  EXPECT_EQ(host.ask(sick::GetTypeRequest{}).code, 0xBA);
}

TEST(SickLms200Emulator, RatesAreNotModelledWhenAskedNotToOrOverTcp) {
  SickLms200Emulator unmodelled({.model_baud_rates = false});
  EXPECT_EQ(unmodelled.baud(), 0);
  TestHost host(unmodelled, 38400);
  EXPECT_EQ(host.ask(kInstallation).code, 0xA0);

  SickLms200Emulator tcp;
  TestHost tcp_host(tcp, 0);
  EXPECT_EQ(tcp_host.ask(kInstallation).code, 0xA0);
}

TEST(SickLms200Emulator, InstallationModeNeedsThePassword) {
  SickLms200Emulator device;
  TestHost host(device);
  const auto wrong = host.ask(sick::InstallationModeRequest{"SICK_PLS"});
  EXPECT_EQ(sick::parse_mode_reply(wrong).result, sick::ModeResult::wrong_password);
  EXPECT_EQ(wrong, (sick::Reply{0xA0, {0x01}, 0x10}));
  EXPECT_EQ(device.mode(), SickLaserEmulator::Mode::idle);
  EXPECT_EQ(host.ask(kInstallation), (sick::Reply{0xA0, {0x00}, 0x10}));
  EXPECT_EQ(device.mode(), SickLaserEmulator::Mode::installation);
}

TEST(SickLms200Emulator, AnswersAreTheSheetsBytes) {
  SickLms200Emulator device;
  TestHost host(device);
  host.send(kInstallation);
  EXPECT_EQ(host.writes().back().second.bytes, kOkBytes);
  // An unknown command, another 0x20 mode, and a known command of the wrong
  // length are all refused with 92 00.
  for (const char* body : {"10", "20 25", "3A 00", "20 00 53 49 43 4B"}) {
    host.write(sick::frame_request(bytes(body)));
    EXPECT_EQ(host.writes().back().second.bytes, kRefusalBytes) << body;
    EXPECT_EQ(host.writes()[host.writes().size() - 2].second.bytes,
              std::vector<std::uint8_t>{0x06}) << body;
  }
}

TEST(SickLms200Emulator, TheAckByteCanBeLeftOut) {
  SickLms200Emulator device({.send_ack = false});
  TestHost host(device);
  host.send(kInstallation);
  ASSERT_EQ(host.writes().size(), 1u);
  EXPECT_EQ(host.writes()[0].second.bytes, kOkBytes);
}

TEST(SickLms200Emulator, TypeTextIsConfigurable) {
  SickLms200Emulator device({.type = "LMS291;S05"});
  TestHost host(device);
  const auto type = sick::parse_type_reply(host.ask(sick::GetTypeRequest{}));
  EXPECT_EQ(type.type.size(), 20u);
  EXPECT_EQ(type.trimmed(), "LMS291;S05");
  EXPECT_NE(device.describe().find("LMS291;S05"), std::string::npos);
}

TEST(SickLms200Emulator, AcceptsTheFiveVariantsAndKeepsTheLastGoodOne) {
  SickLms200Emulator device;
  TestHost host(device);
  for (const sick::Variant& variant : sick::kLms200Variants) {
    const sick::Reply reply = host.ask(sick::SetVariantRequest{variant});
    const std::vector<std::uint8_t> expected = {
        0x01, static_cast<std::uint8_t>(variant.width_deg), 0x00,
        static_cast<std::uint8_t>(variant.resolution_cdeg), 0x00};
    EXPECT_EQ(reply, (sick::Reply{0xBB, expected, 0x10}));
    EXPECT_EQ(device.variant(), variant);
  }
  // Refused: BB 00 and the variant in force (the last one, 100 deg at 1 deg).
  for (const sick::Variant refused : {sick::Variant{180, 25}, sick::Variant{90, 50},
                                      sick::Variant{180, 0}}) {
    const auto reply = sick::parse_variant_reply(host.ask(sick::SetVariantRequest{refused}));
    EXPECT_FALSE(reply.accepted);
    EXPECT_EQ(reply.variant, (sick::Variant{100, 100}));
  }
  EXPECT_EQ(device.variant(), (sick::Variant{100, 100}));
}

TEST(SickLms200Emulator, ConfigurationRoundTripsInInstallationMode) {
  SickLms200Emulator device;
  TestHost host(device);
  const sick::Reply f4 = host.ask(sick::GetConfigRequest{});
  EXPECT_EQ(f4.code, 0xF4);
  EXPECT_EQ(f4.data.size(), 34u);  // LEN 36 with code and status
  const auto config = sick::parse_config_reply(f4).config;
  EXPECT_EQ(config.unit(), sick::Unit::millimetre);
  EXPECT_EQ(config.measuring_mode(), sick::MeasuringMode::fields_and_dazzle);

  // Not in installation mode: F7 00 and nothing changes.
  auto cm = configure(config, sick::MeasuringMode::reflector_levels, sick::Unit::centimetre);
  cm.config.bytes[20] = 0x5A;  // any other byte is stored as sent
  const auto refused = sick::parse_set_config_reply(host.ask(cm));
  EXPECT_FALSE(refused.accepted);
  EXPECT_EQ(refused.config, config);

  host.ask(kInstallation);
  const sick::Reply f7 = host.ask(cm);
  EXPECT_EQ(f7.code, 0xF7);
  EXPECT_EQ(f7.data.size(), 35u);  // LEN 37
  const auto accepted = sick::parse_set_config_reply(f7);
  EXPECT_TRUE(accepted.accepted);
  EXPECT_EQ(accepted.config, cm.config);
  EXPECT_EQ(device.config(), cm.config);
  EXPECT_EQ(device.unit(), sick::Unit::centimetre);
  EXPECT_EQ(sick::parse_config_reply(host.ask(sick::GetConfigRequest{})).config, cm.config);

  // Unit 0x02 (what sicklms200 sends for range_res 100) and unknown
  // measuring modes are refused.
  auto unit_02 = cm;
  unit_02.config.set_unit(static_cast<sick::Unit>(0x02));
  EXPECT_FALSE(sick::parse_set_config_reply(host.ask(unit_02)).accepted);
  auto mode_05 = cm;
  mode_05.config.set_measuring_mode(static_cast<sick::MeasuringMode>(0x05));
  EXPECT_FALSE(sick::parse_set_config_reply(host.ask(mode_05)).accepted);
  EXPECT_EQ(device.config(), cm.config);
}

TEST(SickLms200Emulator, RefusesSubrangesOutsideTheVariant) {
  SickLms200Emulator device;
  TestHost host(device);
  for (const sick::Subrange range : {sick::Subrange{0, 10}, sick::Subrange{5, 362},
                                     sick::Subrange{20, 10}}) {
    EXPECT_EQ(host.ask(sick::StreamSubrangeRequest{range}).code, 0x92)
        << range.first << ".." << range.last;
  }
  EXPECT_EQ(device.mode(), SickLaserEmulator::Mode::idle);
  EXPECT_EQ(host.ask(sick::StreamSubrangeRequest{{1, 361}}).code, 0xA0);
  // 401 values exist only at 100 deg / 0.25 deg.
  host.ask(sick::SetVariantRequest{{100, 25}});
  EXPECT_EQ(host.ask(sick::StreamSubrangeRequest{{1, 401}}).code, 0xA0);
}

TEST(SickLms200Emulator, BadCrcGetsANakAndNoAnswer) {
  SickLms200Emulator device;
  TestHost host(device);
  auto corrupt = sick::encode_request(kInstallation);
  corrupt.back() ^= 0xFF;
  host.write(corrupt);
  ASSERT_EQ(host.writes().size(), 1u);
  EXPECT_EQ(host.writes()[0].second.bytes, std::vector<std::uint8_t>{0x15});
  EXPECT_FALSE(host.writes()[0].second.has_checksum);
  EXPECT_EQ(device.mode(), SickLaserEmulator::Mode::idle);
}

TEST(SickLms200Emulator, ReadsRequestsSplitAnyhowAndSkipsGarbage) {
  SickLms200Emulator device;
  TestHost host(device);
  auto stream = bytes("FF 00 02 80");  // noise, and a reply header where requests go
  const auto t1 = sick::encode_request(kInstallation);
  stream.insert(stream.end(), t1.begin(), t1.end());
  for (const std::uint8_t byte : stream) host.write({byte});
  EXPECT_EQ(host.next_reply(), (sick::Reply{0xA0, {0x00}, 0x10}));
  EXPECT_EQ(device.requests_answered(), 1u);
}

TEST(SickLms200Emulator, DropsARequestLeftHalfWritten) {
  SickLms200Emulator device;
  TestHost host(device);
  const auto t3 = sick::encode_request(sick::GetTypeRequest{});
  host.write({t3.begin(), t3.begin() + 3});
  EXPECT_LT(device.next_deadline(), Duration::max());
  host.wait(SickLaserEmulator::kInterByteTimeout + 1ms);
  // The next request is read from its own STX, not as the rest of the old one.
  EXPECT_EQ(host.ask(sick::GetTypeRequest{}).code, 0xBA);
}

TEST(SickLms200Emulator, SendsNothingUnsolicited) {
  SickLms200Emulator device;
  EXPECT_EQ(device.next_deadline(), Duration::max());
  TestHost host(device);
  host.wait(10s);
  host.ask(kInstallation);
  const std::size_t after_answer = host.writes().size();
  host.wait(10s);
  EXPECT_TRUE(host.silent_since(after_answer));
}

TEST(SickLms200Emulator, RefusesOptionsNoDeviceHas) {
  EXPECT_THROW(SickLms200Emulator({.type = "LMS200;30106 and more"}), std::invalid_argument);
  EXPECT_THROW(SickLms200Emulator({.power_up_baud = 115200}), std::invalid_argument);
  EXPECT_THROW(SickLms200Emulator({.max_range_m = 0.0}), std::invalid_argument);
  EXPECT_THROW(SickLms200Emulator({.range_noise_sigma_m = -1.0}), std::invalid_argument);
  EXPECT_THROW(SickLms200Emulator({.reflectors = {{{0, 0}, {1, 0}, 8}}}), std::invalid_argument);
}

TEST(SickLms200Emulator, DescribesItself) {
  SickLms200Emulator device;
  EXPECT_EQ(device.describe(),
            "SICK LMS 200 (LMS200;30106), 9600 baud, idle, 180 deg at 50/100 deg");
  TestHost host(device);
  host.ask(sick::StreamAllRequest{});
  EXPECT_EQ(device.describe(),
            "SICK LMS 200 (LMS200;30106), 9600 baud, streaming B0 361 values in mm, 180 deg at "
            "50/100 deg");
}

}  // namespace sick_lms200_emulator_test
}  // namespace playerkit::emulators
