#include "links/open_link.hpp"

#include <gtest/gtest.h>

#include "links/link_error.hpp"
#include "links/links_test_support.hpp"
#include "links/serial_link.hpp"
#include "links/tcp_link.hpp"
#include "links/tcp_listener.hpp"

namespace playerkit::links {
namespace open_link_test {

using namespace test_support;

TEST(OpenLink, TtyPathGivesASerialLink) {
  PseudoTerminal pty;
  auto link = open_link(pty.path(), {.baud = 38400});
  ASSERT_NE(dynamic_cast<SerialLink*>(link.get()), nullptr);
  EXPECT_EQ(link->describe(), pty.path() + " at 38400 8N1");
  EXPECT_EQ(pty.slave_baud(), 38400);
  EXPECT_TRUE(link->set_baud(9600));
  EXPECT_EQ(pty.slave_baud(), 9600);
}

TEST(OpenLink, TcpAddressGivesATcpLink) {
  TcpListener listener("127.0.0.1", 0);
  auto link = open_link(listener.address(), {.baud = 38400});
  ASSERT_NE(dynamic_cast<TcpLink*>(link.get()), nullptr);
  EXPECT_EQ(link->describe(), listener.address());
  auto device = listener.accept(deadline_in(kPatience));
  ASSERT_NE(device, nullptr);
  const Bytes hello = {0x02, 0x80};
  link->write_all(hello, deadline_in(kPatience));
  EXPECT_EQ(read_exactly(*device, hello.size()), hello);
}

TEST(OpenLink, MalformedPortIsABadAddress) {
  try {
    open_link("tcp:nowhere", {});
    FAIL();
  } catch (const LinkError& error) {
    EXPECT_EQ(error.kind(), LinkErrorKind::bad_address);
  }
}

TEST(OpenLink, MissingTtyIsMissing) {
  TemporaryDirectory directory;
  try {
    open_link((directory.path() / "ttyUSB0").string(), {});
    FAIL();
  } catch (const LinkError& error) {
    EXPECT_EQ(error.kind(), LinkErrorKind::missing);
  }
}

}  // namespace open_link_test
}  // namespace playerkit::links
