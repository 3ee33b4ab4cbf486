// The one `port` option of every link-opening driver, checked while the
// configuration is read.
#include "links/port_option.hpp"

#include <gtest/gtest.h>

#include "config/config_file.hpp"
#include "config/errors.hpp"
#include "core/option_reader.hpp"

namespace playerkit::links {
namespace port_option_test {

std::string error_of(std::string_view port) {
  config::LoadOptions load;
  load.driver_exists = [](std::string_view) { return true; };
  const auto file = config::ConfigFile::parse("laser:0 ( driver \"d\" port \"" + std::string(port) + "\" )\n",
                                              "ports.cfg", load);
  const core::OptionSchema schema{port_option("/tmp/playerkit-test/ttyDEFAULT")};
  try {
    core::OptionReader(file.section(file.devices().front().section), "d", schema).validate();
  } catch (const config::ConfigError& e) {
    return e.what();
  }
  return "no error";
}

TEST(PortOption, TtyPathsAndTcpAddressesAreAccepted) {
  EXPECT_EQ(error_of("/tmp/playerkit-test/ttyLASER"), "no error");
  EXPECT_EQ(error_of("tcp:127.0.0.1:4001"), "no error");
  EXPECT_EQ(error_of("tcp:[::1]:4001"), "no error");
}

TEST(PortOption, MalformedTcpAddressesAreRefusedAtTheValue) {
  // laser:0 ( driver "d" port "...": the value starts at column 27.
  EXPECT_EQ(error_of("tcp:localhost").rfind("ports.cfg:1:27: d: port is not a serial port or tcp:HOST:PORT: "
                                            "bad port 'tcp:localhost': missing ':PORT'",
                                            0),
            0u)
      << error_of("tcp:localhost");
  EXPECT_NE(error_of("tcp:localhost:99999").find("'99999' is not a TCP port (1..65535)"), std::string::npos);
  EXPECT_EQ(error_of("").rfind("ports.cfg:1:27: d: port must not be empty", 0), 0u) << error_of("");
}

TEST(PortOption, IsDocumentedAsAPort) {
  const auto rows = core::OptionSchema{port_option("/tmp/playerkit-test/ttyDEFAULT")}.docs();
  ASSERT_EQ(rows.size(), 1u);
  EXPECT_EQ(rows[0].name, "port");
  EXPECT_EQ(rows[0].type, "port");
  EXPECT_EQ(rows[0].default_value, "\"/tmp/playerkit-test/ttyDEFAULT\"");
}

}  // namespace port_option_test
}  // namespace playerkit::links
