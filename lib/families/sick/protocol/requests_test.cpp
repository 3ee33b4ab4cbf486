#include "families/sick/protocol/requests.hpp"

#include "families/sick/protocol/telegram.hpp"
#include "families/sick/protocol/test_bytes.hpp"

#include <gtest/gtest.h>

#include <numbers>

namespace playerkit::hardware::sick {
namespace requests_test {

using testing::bytes;

struct TypedGolden {
  Request request;
  const char* telegram;  // from sicklms200.md §1.4 / sickpls.md §1
};

const TypedGolden kGoldens[] = {
    {InstallationModeRequest{"SICK_LMS"}, "02 00 0A 00 20 00 53 49 43 4B 5F 4C 4D 53 BE C5"},
    {InstallationModeRequest{"SICK_PLS"}, "02 00 0A 00 20 00 53 49 43 4B 5F 50 4C 53 CC FC"},
    {BaudRateRequest{38400}, "02 00 02 00 20 40 50 08"},
    {BaudRateRequest{9600}, "02 00 02 00 20 42 52 08"},
    {BaudRateRequest{500000}, "02 00 02 00 20 48 58 08"},
    {StreamAllRequest{}, "02 00 02 00 20 24 34 08"},
    {GetTypeRequest{}, "02 00 01 00 3A 1E 12"},
    {GetConfigRequest{}, "02 00 01 00 74 50 12"},
    {SetVariantRequest{{180, 50}}, "02 00 05 00 3B B4 00 32 00 3B 1F"},
    {SetVariantRequest{{100, 25}}, "02 00 05 00 3B 64 00 19 00 E7 72"},
    {SetVariantRequest{{180, 100}}, "02 00 05 00 3B B4 00 64 00 97 49"},
    {StreamSubrangeRequest{{1, 181}}, "02 00 06 00 20 27 01 00 B5 00 12 09"},
    {StreamSubrangeRequest{{1, 401}}, "02 00 06 00 20 27 01 00 91 01 5B 2D"},
};

TEST(SickRequests, EncodeToTheSheetsBytes) {
  for (const TypedGolden& golden : kGoldens) {
    EXPECT_EQ(encode_request(golden.request), bytes(golden.telegram)) << describe(golden.request);
  }
}

TEST(SickRequests, DecodeTheSheetsBytes) {
  for (const TypedGolden& golden : kGoldens) {
    EXPECT_EQ(decode_request(unframe_request(bytes(golden.telegram))), golden.request)
        << golden.telegram;
  }
}

TEST(SickRequests, PasswordsOfBothModels) {
  EXPECT_EQ(installation_password(Model::lms200), "SICK_LMS");
  EXPECT_EQ(installation_password(Model::pls), "SICK_PLS");
}

TEST(SickRequests, BaudRateCodes) {
  EXPECT_EQ(baud_code(9600), 0x42);
  EXPECT_EQ(baud_code(19200), 0x41);
  EXPECT_EQ(baud_code(38400), 0x40);
  EXPECT_EQ(baud_code(500000), 0x48);
  EXPECT_FALSE(baud_code(115200));
  for (const int baud : kBaudRates) EXPECT_EQ(baud_of_code(*baud_code(baud)), baud);
  EXPECT_FALSE(baud_of_code(0x24));
  EXPECT_EQ(decode_request(bytes("20 41")), Request(BaudRateRequest{19200}));
}

TEST(SickRequests, SetConfigurationCarriesTheWholeBlock) {
  SetConfigRequest request;
  for (std::size_t i = 0; i < kConfigBlockSize; ++i) {
    request.config.bytes[i] = static_cast<std::uint8_t>(0x40 + i);
  }
  request.config.set_measuring_mode(MeasuringMode::reflector_levels);
  request.config.set_unit(Unit::centimetre);
  const auto body = request_body(request);
  ASSERT_EQ(body.size(), 35u);
  EXPECT_EQ(body[0], 0x77);
  EXPECT_EQ(body[6], 0x01);  // block D, the sheet's body[6]
  EXPECT_EQ(body[7], 0x00);  // block E, the sheet's body[7]
  EXPECT_EQ(body[1], 0x40);
  EXPECT_EQ(body[34], 0x40 + 33);
  EXPECT_EQ(encode_request(request).size(), 4u + 35u + 2u);
  EXPECT_EQ(decode_request(body), Request(request));
}

TEST(SickRequests, UnknownCommandsAndModesAreOtherRequests) {
  EXPECT_EQ(decode_request(bytes("10")), Request(OtherRequest{{0x10}}));
  EXPECT_EQ(decode_request(bytes("20 25")), Request(OtherRequest{{0x20, 0x25}}));
  EXPECT_EQ(decode_request(bytes("30 01 02")), Request(OtherRequest{{0x30, 0x01, 0x02}}));
  EXPECT_EQ(encode_request(OtherRequest{{0x10}}), frame_request(bytes("10")));
}

void expect_decode_error(const char* body, const std::string& words) {
  try {
    const Request request = decode_request(bytes(body));
    ADD_FAILURE() << body << " decoded as " << describe(request);
  } catch (const TelegramError& error) {
    EXPECT_NE(std::string(error.what()).find(words), std::string::npos) << error.what();
  }
}

TEST(SickRequests, WrongLengthsAreClearErrors) {
  expect_decode_error("", "empty");
  expect_decode_error("20", "mode byte");
  expect_decode_error("20 00 53 49 43 4B", "20 00 (installation mode): expected 10 bytes, got 6");
  expect_decode_error("20 00 53 49 43 4B 5F 4C 4D 53 00", "expected 10 bytes, got 11");
  expect_decode_error("20 24 00", "stream all");
  expect_decode_error("20 27 01 00 B5", "20 27 (stream a subrange): expected 6 bytes, got 5");
  expect_decode_error("20 40 00", "baud rate");
  expect_decode_error("3A 00", "3A (get type)");
  expect_decode_error("3B B4 00 32", "3B (set variant): expected 5 bytes, got 4");
  expect_decode_error("74 00", "74 (get configuration)");
  expect_decode_error("77 00 00", "77 (set configuration): expected 35 bytes, got 3");
}

TEST(SickRequests, ValuesWithoutAnEncodingAreRefused) {
  EXPECT_THROW(request_body(InstallationModeRequest{"SICK"}), TelegramError);
  EXPECT_THROW(request_body(BaudRateRequest{115200}), TelegramError);
  EXPECT_THROW(request_body(OtherRequest{}), TelegramError);
}

TEST(SickRequests, Describe) {
  EXPECT_EQ(describe(InstallationModeRequest{"SICK_LMS"}), "T1 installation mode");
  EXPECT_EQ(describe(StreamSubrangeRequest{{1, 181}}), "T8 stream values 1..181");
  EXPECT_EQ(describe(OtherRequest{{0x10}}), "command 10");
}

TEST(SickVariant, FiveSupportedAndTheirValueCounts) {
  EXPECT_EQ((Variant{180, 50}.value_count()), 361);
  EXPECT_EQ((Variant{180, 100}.value_count()), 181);
  EXPECT_EQ((Variant{100, 25}.value_count()), 401);
  EXPECT_EQ((Variant{100, 50}.value_count()), 201);
  EXPECT_EQ((Variant{100, 100}.value_count()), 101);
  for (const Variant& variant : kLms200Variants) EXPECT_TRUE(variant.supported());
  EXPECT_FALSE((Variant{180, 25}.supported()));
  EXPECT_FALSE((Variant{90, 50}.supported()));
  EXPECT_EQ((Variant{180, 0}.value_count()), 0);
  EXPECT_TRUE(kPlsVariant.supported());
}

TEST(SickVariant, AnglesRunCounterClockwiseFromTheRight) {
  const Variant variant{100, 25};
  EXPECT_NEAR(variant.first_angle_rad(), -50.0 * std::numbers::pi / 180.0, 1e-12);
  EXPECT_NEAR(variant.step_rad(), 0.25 * std::numbers::pi / 180.0, 1e-12);
  EXPECT_NEAR(variant.first_angle_rad() + 400 * variant.step_rad(), 50.0 * std::numbers::pi / 180.0, 1e-12);
}

}  // namespace requests_test
}  // namespace playerkit::hardware::sick
