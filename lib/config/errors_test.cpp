// Locations print compiler style, and ConfigError's what() starts with one.

#include "config/errors.hpp"

#include <gtest/gtest.h>

#include <sstream>

#include "config/source_location.hpp"

namespace playerkit::config {
namespace errors_test {

TEST(SourceLocation, PrintsFileLineColumn) {
  EXPECT_EQ(to_string(SourceLocation{"robot.cfg", 12, 7}), "robot.cfg:12:7");
  std::ostringstream out;
  out << SourceLocation{"/a/b.cfg", 1, 1};
  EXPECT_EQ(out.str(), "/a/b.cfg:1:1");
}

TEST(SourceLocation, WithoutALinePrintsJustTheFile) {
  EXPECT_EQ(to_string(SourceLocation{"missing.cfg", 0, 0}), "missing.cfg");
}

TEST(ConfigError, WhatIsLocationColonMessage) {
  const ConfigError error(SourceLocation{"robot.cfg", 3, 9}, "unknown interface 'lazer'");
  EXPECT_STREQ(error.what(), "robot.cfg:3:9: unknown interface 'lazer'");
  EXPECT_EQ(error.where(), (SourceLocation{"robot.cfg", 3, 9}));
  EXPECT_EQ(error.message(), "unknown interface 'lazer'");
}

TEST(ConfigError, IsARuntimeError) {
  try {
    throw ConfigError(SourceLocation{"x.cfg", 1, 2}, "bad");
  } catch (const std::runtime_error& error) {
    EXPECT_STREQ(error.what(), "x.cfg:1:2: bad");
  }
}

}  // namespace errors_test
}  // namespace playerkit::config
