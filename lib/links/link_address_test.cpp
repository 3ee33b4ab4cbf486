#include "links/link_address.hpp"

#include <gtest/gtest.h>

#include "links/link_error.hpp"

namespace playerkit::links {
namespace link_address_test {

std::string rejection(std::string_view text) {
  try {
    parse_link_address(text);
  } catch (const LinkError& error) {
    EXPECT_EQ(error.kind(), LinkErrorKind::bad_address);
    return error.what();
  }
  ADD_FAILURE() << "'" << text << "' was accepted";
  return "";
}

TEST(LinkAddress, TtyPathsAreSerial) {
  EXPECT_EQ(parse_link_address("/dev/ttyUSB0"), LinkAddress::serial("/dev/ttyUSB0"));
  EXPECT_EQ(parse_link_address("/dev/serial/by-id/usb-FTDI_FT232R-if00-port0"),
            LinkAddress::serial("/dev/serial/by-id/usb-FTDI_FT232R-if00-port0"));
  EXPECT_EQ(parse_link_address("ttyS0"), LinkAddress::serial("ttyS0"));
  // Only the lower-case prefix means TCP; anything else is a file name.
  EXPECT_FALSE(parse_link_address("TCP:host:1").is_tcp());
}

TEST(LinkAddress, TcpWithNameIpv4AndBracketedIpv6) {
  EXPECT_EQ(parse_link_address("tcp:127.0.0.1:4001"), LinkAddress::tcp("127.0.0.1", 4001));
  EXPECT_EQ(parse_link_address("tcp:robot-1.local:7019"), LinkAddress::tcp("robot-1.local", 7019));
  EXPECT_EQ(parse_link_address("tcp:[::1]:4001"), LinkAddress::tcp("::1", 4001));
  EXPECT_EQ(parse_link_address("tcp:[fe80::1:2]:65535"), LinkAddress::tcp("fe80::1:2", 65535));
}

TEST(LinkAddress, PrintsWhatItParses) {
  for (const char* text : {"/dev/ttyS0", "tcp:127.0.0.1:4001", "tcp:[::1]:1", "tcp:host:80"}) {
    EXPECT_EQ(to_string(parse_link_address(text)), text);
  }
}

TEST(LinkAddress, MalformedValuesSayWhatIsWrong) {
  EXPECT_NE(rejection("").find("empty"), std::string::npos);
  EXPECT_NE(rejection("tcp:host").find("missing ':PORT'"), std::string::npos);
  EXPECT_NE(rejection("tcp::4001").find("missing HOST"), std::string::npos);
  EXPECT_NE(rejection("tcp:host:0").find("not a TCP port"), std::string::npos);
  EXPECT_NE(rejection("tcp:host:65536").find("not a TCP port"), std::string::npos);
  EXPECT_NE(rejection("tcp:host:40x1").find("'40x1'"), std::string::npos);
  EXPECT_NE(rejection("tcp:host:").find("not a TCP port"), std::string::npos);
  EXPECT_NE(rejection("tcp:::1:4001").find("brackets"), std::string::npos);
  EXPECT_NE(rejection("tcp:[::1:4001").find("']'"), std::string::npos);
  EXPECT_NE(rejection("tcp:[::1]4001").find("':PORT'"), std::string::npos);
  EXPECT_NE(rejection("tcp:[not-v6]:4001").find("not an IPv6 address"), std::string::npos);
  EXPECT_NE(rejection("tcp://host:4001").find("without '//'"), std::string::npos);
  EXPECT_NE(rejection("tcp:ho st:4001").find("not a host name"), std::string::npos);
  EXPECT_NE(rejection("rfc2217://host:4001").find("only tcp:HOST:PORT"), std::string::npos);
  EXPECT_NE(rejection(" /dev/ttyS0").find("whitespace"), std::string::npos);
  const std::string with_nul = rejection(std::string_view("/dev/tty\0S0", 11));
  EXPECT_NE(with_nul.find("'/dev/tty\\x00S0': it contains a NUL byte"), std::string::npos) << with_nul;
}

TEST(LinkAddress, ErrorsNameTheValueAndTheExpectedForms) {
  const std::string message = rejection("tcp:host");
  EXPECT_NE(message.find("'tcp:host'"), std::string::npos) << message;
  EXPECT_NE(message.find("tcp:HOST:PORT"), std::string::npos) << message;
}

}  // namespace link_address_test
}  // namespace playerkit::links
