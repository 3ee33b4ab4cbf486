#include "core/option_reader.hpp"

#include <gtest/gtest.h>

#include <numbers>
#include <optional>

#include "config/config_file.hpp"

namespace playerkit::core {
namespace option_reader_test {

struct OptionReaderFixture : ::testing::Test {
  // One device section "laser:0 ( <body> )" on line 1 of opts.cfg.
  const config::Section& section(std::string_view body) {
    config::LoadOptions options;
    options.driver_exists = [](std::string_view) { return true; };
    file = config::ConfigFile::parse("laser:0 ( driver \"x\" " + std::string(body) + " )\n",
                                     "opts.cfg", options);
    return file->section(file->devices().front().section);
  }
  template <typename Action>
  std::string error_of(Action&& action) {
    try {
      action();
    } catch (const config::ConfigError& error) {
      return error.what();
    }
    return "no error";
  }
  std::optional<config::ConfigFile> file;
};

TEST_F(OptionReaderFixture, ReadsValuesAndFallsBack) {
  const OptionReader options(section("rate 38400 name \"bob\" on 1 range 2.5"), "sick");
  EXPECT_EQ(options.choice({"rate"}, 9600, {9600, 38400, 500000}), 38400);
  EXPECT_EQ(options.text({"name"}, "x"), "bob");
  EXPECT_TRUE(options.flag({"on"}, false));
  EXPECT_DOUBLE_EQ(options.number({"range"}, 1.0, 0.0, 10.0), 2.5);
  EXPECT_EQ(options.integer({"absent"}, 7, 0, 10), 7);
  EXPECT_EQ(options.index({"laser_index"}, 2), 2);
  EXPECT_EQ(options.network_port({"port"}, 6665), 6665);
}

TEST_F(OptionReaderFixture, ErrorsPointAtTheValue) {
  const OptionReader options(section("rate 19200"), "sicklms200");
  // laser:0 ( driver "x" rate 19200 ): the value starts at column 27.
  EXPECT_EQ(error_of([&] { (void)options.choice({"rate"}, 9600, {9600, 38400, 500000}); }),
            "opts.cfg:1:27: sicklms200: rate must be one of 9600, 38400, 500000 (got 19200)");
}

TEST_F(OptionReaderFixture, RangesFlagsAndWordsAreChecked) {
  const OptionReader options(section("n 11 on 2 unit \"km\" idx -1 port 70000 x -0.5 s \"\""), "d");
  EXPECT_NE(error_of([&] { (void)options.integer({"n"}, 0, 0, 10); }).find("d: n must be between 0 and 10 (got 11)"),
            std::string::npos);
  EXPECT_NE(error_of([&] { (void)options.flag({"on"}, false); }).find("on must be 0 or 1 (got 2)"),
            std::string::npos);
  EXPECT_NE(error_of([&] { (void)options.word({"unit"}, "mm", {"mm", "cm", "dm"}); })
                .find("unit must be one of mm, cm, dm (got \"km\")"),
            std::string::npos);
  EXPECT_NE(error_of([&] { (void)options.index({"idx"}, 0); }).find("idx must be a device index"),
            std::string::npos);
  EXPECT_NE(error_of([&] { (void)options.network_port({"port"}, 1); }).find("port must be between 1 and 65535"),
            std::string::npos);
  EXPECT_NE(error_of([&] { (void)options.number({"x"}, 0.0, 0.0, 1.0); }).find("x must be between 0 and 1 (got -0.5)"),
            std::string::npos);
  EXPECT_NE(error_of([&] { (void)options.text({"s"}, "x"); }).find("s must not be empty"), std::string::npos);
  EXPECT_EQ(options.text({"s"}, "x", true), "");
}

TEST_F(OptionReaderFixture, LegacyAliasesAreReadWhenThePreferredNameIsAbsent) {
  const OptionReader options(section("laser_max_samples 30"), "amcl");
  EXPECT_EQ(options.integer({"laser_max_beams", "laser_max_samples"}, 60, 1, 1000), 30);
  const OptionReader both(section("laser_max_beams 20 laser_max_samples 30"), "amcl");
  EXPECT_EQ(both.integer({"laser_max_beams", "laser_max_samples"}, 60, 1, 1000), 20);
}

TEST_F(OptionReaderFixture, LengthsAndAnglesUseTheFileUnits) {
  const OptionReader options(section("pose [0.1 0.2 90] size 0.5"), "d");
  EXPECT_EQ(options.tuple_size({"pose"}), 3u);
  EXPECT_DOUBLE_EQ(options.tuple_length({"pose"}, 1, 0.0), 0.2);
  EXPECT_NEAR(options.tuple_angle({"pose"}, 2, 0.0), std::numbers::pi / 2, 1e-12);
  EXPECT_DOUBLE_EQ(options.length({"size"}, 0.0, 0.0, 1.0), 0.5);
  EXPECT_NE(error_of([&] { (void)options.length({"size"}, 0.0, 0.0, 0.4); }).find("(got 0.5 m)"),
            std::string::npos);
}

}  // namespace option_reader_test
}  // namespace playerkit::core
