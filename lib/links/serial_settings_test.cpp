#include "links/serial_settings.hpp"

#include <gtest/gtest.h>

#include "links/link_error.hpp"

namespace playerkit::links {
namespace serial_settings_test {

TEST(SerialSettings, DefaultsAre9600RawEightNoneOneExclusive) {
  const SerialSettings settings;
  EXPECT_EQ(to_string(settings), "9600 8N1");
  EXPECT_TRUE(settings.exclusive);
  EXPECT_TRUE(settings.flush_on_open);
}

TEST(SerialSettings, FramingRoundTrips) {
  for (const char* framing : {"8N1", "8E1", "7O2", "5N2", "8N2"}) {
    EXPECT_EQ(framing_name(with_framing(framing)), framing);
  }
  const SerialSettings pls = with_framing("8e1", {.baud = 38400});
  EXPECT_EQ(pls.parity, Parity::even);
  EXPECT_EQ(pls.baud, 38400);
  EXPECT_EQ(to_string(pls), "38400 8E1");
}

TEST(SerialSettings, BadFramingIsRefused) {
  for (const char* framing : {"", "8N", "9N1", "4N1", "8X1", "8N3", "8N1 "}) {
    EXPECT_THROW(with_framing(framing), LinkError) << framing;
  }
  try {
    with_framing("8X1");
  } catch (const LinkError& error) {
    EXPECT_EQ(error.kind(), LinkErrorKind::bad_settings);
    EXPECT_NE(std::string(error.what()).find("'8X1'"), std::string::npos);
  }
}

TEST(SerialSettings, ValidateNamesThePortAndTheField) {
  EXPECT_NO_THROW(validate({.baud = 500000}, "/dev/ttyUSB0"));
  EXPECT_NO_THROW(validate({.baud = 250000}, "/dev/ttyUSB0"));  // not standard, still valid (BOTHER)
  try {
    validate({.baud = 0}, "/dev/ttyUSB0");
    FAIL();
  } catch (const LinkError& error) {
    EXPECT_EQ(error.kind(), LinkErrorKind::bad_settings);
    EXPECT_EQ(error.port(), "/dev/ttyUSB0");
    EXPECT_NE(std::string(error.what()).find("/dev/ttyUSB0: baud rate 0"), std::string::npos) << error.what();
  }
  EXPECT_THROW(validate({.data_bits = 9}, "p"), LinkError);
  EXPECT_THROW(validate({.stop_bits = 3}, "p"), LinkError);
  EXPECT_THROW(validate({.baud = -9600}, "p"), LinkError);
}

TEST(SerialSettings, StandardBauds) {
  EXPECT_TRUE(is_standard_baud(9600));
  EXPECT_TRUE(is_standard_baud(500000));
  EXPECT_FALSE(is_standard_baud(250000));
  EXPECT_EQ(to_string(SerialSettings{.baud = 115200, .flow_control = FlowControl::hardware}), "115200 8N1 rtscts");
}

}  // namespace serial_settings_test
}  // namespace playerkit::links
