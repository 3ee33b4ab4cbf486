// Options declared in a schema: each kind's checks with the value's
// file:line:col, the defaults, validation before a driver is made, and the
// documentation derived from the same declaration.
#include "core/option_schema.hpp"

#include <gtest/gtest.h>

#include <climits>
#include <numbers>
#include <optional>
#include <stdexcept>

#include "config/config_file.hpp"
#include "core/instantiate.hpp"
#include "core/option_reader.hpp"
#include "core/test_drivers.hpp"
#include "protocol/interfaces.hpp"

namespace playerkit::core {
namespace option_schema_test {

// One option of every kind.
const OptionSchema& every_kind() {
  static const OptionSchema schema{
      OptionSpec::integer("count", 3, 0, 10).doc("how many"),
      OptionSpec::number("gain", 0.5, 0.0, 1.0),
      OptionSpec::length("reach", 2.0, 0.0, 8.0),
      OptionSpec::angle("turn", 0.0, -std::numbers::pi / 2, std::numbers::pi / 2),
      OptionSpec::flag("on", true),
      OptionSpec::text("label", "lab"),
      OptionSpec::filename("map", "map.pgm"),
      OptionSpec::word("mode", "fast", {"fast", "slow"}),
      OptionSpec::choice("rate", 38400, {9600, 38400}).unit("baud"),
      OptionSpec::tuple("pose", {OptionType::length, OptionType::length, OptionType::angle}, {0.0, 0.1, 0.0}),
      OptionSpec::link_port("port", "/tmp/tty-default",
                            [](std::string_view text) -> std::string {
                              return text.starts_with("tcp:") && text.size() < 6 ? "is not a port" : "";
                            }),
      OptionSpec::integer("max_beams", 60, 1, 1000).aliases({"max_samples"}),
  };
  return schema;
}

struct SchemaFixture : ::testing::Test {
  // "laser:0 ( driver "x" <body> )" on line 1 of opts.cfg: the body starts at column 22.
  const config::Section& section(std::string_view body) {
    config::LoadOptions options;
    options.driver_exists = [](std::string_view) { return true; };
    file = config::ConfigFile::parse("laser:0 ( driver \"x\" " + std::string(body) + " )\n", "opts.cfg", options);
    return file->section(file->devices().front().section);
  }
  OptionReader reader(std::string_view body) { return OptionReader(section(body), "x", every_kind()); }
  template <typename Action>
  static std::string error_of(Action&& action) {
    try {
      action();
    } catch (const config::ConfigError& error) {
      return error.what();
    }
    return "no error";
  }
  std::optional<config::ConfigFile> file;
};

TEST_F(SchemaFixture, AbsentOptionsAreTheirDeclaredDefaults) {
  const OptionReader options = reader("");
  EXPECT_EQ(options.integer("count"), 3);
  EXPECT_DOUBLE_EQ(options.number("gain"), 0.5);
  EXPECT_DOUBLE_EQ(options.length("reach"), 2.0);
  EXPECT_DOUBLE_EQ(options.angle("turn"), 0.0);
  EXPECT_TRUE(options.flag("on"));
  EXPECT_EQ(options.text("label"), "lab");
  EXPECT_EQ(options.text("mode"), "fast");
  EXPECT_EQ(options.integer("rate"), 38400);
  EXPECT_DOUBLE_EQ(options.element("pose", 1), 0.1);
  EXPECT_EQ(options.text("port"), "/tmp/tty-default");
  EXPECT_EQ(options.integer("max_beams"), 60);
  EXPECT_FALSE(options.has("count"));
}

TEST_F(SchemaFixture, ValuesAreReadInTheFileUnits) {
  const OptionReader options = reader("count 7 reach 1.5 turn 45 on 0 mode \"slow\" pose [1 2 90] max_samples 30");
  EXPECT_EQ(options.integer("count"), 7);
  EXPECT_DOUBLE_EQ(options.length("reach"), 1.5);
  EXPECT_NEAR(options.angle("turn"), std::numbers::pi / 4, 1e-12);
  EXPECT_FALSE(options.flag("on"));
  EXPECT_EQ(options.text("mode"), "slow");
  EXPECT_NEAR(options.element("pose", 2), std::numbers::pi / 2, 1e-12);
  // A legacy name is read when the preferred one is absent.
  EXPECT_EQ(options.integer("max_beams"), 30);
  EXPECT_TRUE(options.has("max_beams"));
}

TEST_F(SchemaFixture, EachKindRefusesBadValuesAtTheValue) {
  // Column 22 is where the body starts: "laser:0 ( driver "x" " is 21 characters.
  const std::vector<std::pair<std::string, std::string>> cases = {
      {"count 11", "opts.cfg:1:28: x: count must be between 0 and 10 (got 11)"},
      {"gain 1.5", "opts.cfg:1:27: x: gain must be between 0 and 1 (got 1.5)"},
      {"reach 9", "opts.cfg:1:28: x: reach must be between 0 and 8 (got 9 m)"},
      {"turn 100", "opts.cfg:1:27: x: turn must be between -1.5708 and 1.5708 (got 1.74533 rad)"},
      {"on 2", "opts.cfg:1:25: x: on must be 0 or 1 (got 2)"},
      {"label \"\"", "opts.cfg:1:28: x: label must not be empty"},
      {"map \"\"", "opts.cfg:1:26: x: map must name a file"},
      {"mode \"warp\"", "opts.cfg:1:27: x: mode must be one of fast, slow (got \"warp\")"},
      {"rate 19200", "opts.cfg:1:27: x: rate must be one of 9600, 38400 (got 19200)"},
      {"pose [0 1" + std::string(400, '0') + " 0]", "opts.cfg:1:30: x: pose must be a finite length"},
      {"port \"tcp:\"", "opts.cfg:1:27: x: port is not a port"},
      {"max_samples 0", "opts.cfg:1:34: x: max_samples must be between 1 and 1000 (got 0)"},
  };
  for (const auto& [body, expected] : cases) {
    const std::string& written = body;  // clang 14 lambdas cannot capture structured bindings
    EXPECT_EQ(error_of([&] { reader(written).validate(); }), expected) << body;
  }
}

TEST_F(SchemaFixture, ValidationLeavesUndeclaredOptionsUnread) {
  const OptionReader options = reader("count 2 colour \"red\"");
  options.validate();
  const auto unused = file->unused_properties();
  ASSERT_EQ(unused.size(), 1u);
  EXPECT_NE(unused.front().to_string().find("colour"), std::string::npos) << unused.front().to_string();
}

TEST_F(SchemaFixture, ReadingWhatIsNotDeclaredIsAProgrammingError) {
  const OptionReader options = reader("");
  EXPECT_THROW((void)options.integer("colour"), std::logic_error);
  EXPECT_THROW((void)options.integer("label"), std::logic_error);  // declared as text
  EXPECT_THROW((void)options.element("pose", 3), std::logic_error);
  EXPECT_THROW((void)options.seconds("gain"), std::logic_error);  // not in seconds
  EXPECT_THROW(OptionSchema({OptionSpec::flag("on", true), OptionSpec::integer("x", 0, 0, 1).aliases({"on"})}),
               std::logic_error);
}

TEST(OptionSchema, DocsShowTypeDefaultUnitAndAllowedValues) {
  const std::vector<OptionDoc> rows = every_kind().docs();
  ASSERT_EQ(rows.size(), every_kind().options().size());
  EXPECT_EQ(rows[0].name, "count");
  EXPECT_EQ(rows[0].type, "int");
  EXPECT_EQ(rows[0].default_value, "3");
  EXPECT_EQ(rows[0].summary, "how many; 0 to 10");
  EXPECT_EQ(rows[3].type, "angle");
  EXPECT_EQ(rows[3].unit, "deg");
  EXPECT_EQ(rows[3].summary, "-90 to 90");  // ranges of angles in degrees, as written
  EXPECT_EQ(rows[5].default_value, "\"lab\"");
  EXPECT_EQ(rows[8].summary, "9600 or 38400");
  EXPECT_EQ(rows[8].unit, "baud");
  EXPECT_EQ(rows[9].type, "[length length angle]");
  EXPECT_EQ(rows[9].default_value, "[0 0.1 0]");
  EXPECT_EQ(rows[10].type, "port");
  EXPECT_EQ(rows[11].name, "max_beams/max_samples");
}

TEST(OptionSchema, MarkdownHasARowPerOption) {
  const std::string table = OptionSchema{OptionSpec::choice("rate", 38400, {9600, 38400}).unit("baud").doc("speed"),
                                         OptionSpec::flag("invert", false).doc("upside down | mirrored")}
                                .markdown();
  EXPECT_EQ(table,
            "| option | type | default | unit | values | what |\n"
            "|---|---|---|---|---|---|\n"
            "| `rate` | int | `38400` | baud | 9600 or 38400 | speed |\n"
            "| `invert` | int | `0` |  | 0 or 1 | upside down \\| mirrored |\n");
}

TEST(OptionSchema, EveryDocumentedDefaultReadsBackAsTheDefault) {
  // The default as documented, written in a section, is what the reader
  // falls back to: docs and behaviour agree.
  for (const OptionSpec& option : every_kind().options()) {
    config::LoadOptions load;
    load.driver_exists = [](std::string_view) { return true; };
    const auto file = config::ConfigFile::parse(
        "laser:0 ( driver \"x\" " + option.name() + " " + option.default_text() + " )\n", "d.cfg", load);
    const OptionReader written(file.section(file.devices().front().section), "x", every_kind());
    const auto empty = config::ConfigFile::parse("laser:0 ( driver \"x\" )\n", "e.cfg", load);
    const OptionReader absent(empty.section(empty.devices().front().section), "x", every_kind());
    switch (option.type()) {
      case OptionType::integer:
      case OptionType::choice: EXPECT_EQ(written.integer(option.name()), absent.integer(option.name())); break;
      case OptionType::number: EXPECT_DOUBLE_EQ(written.number(option.name()), absent.number(option.name())); break;
      case OptionType::length: EXPECT_DOUBLE_EQ(written.length(option.name()), absent.length(option.name())); break;
      case OptionType::angle: EXPECT_NEAR(written.angle(option.name()), absent.angle(option.name()), 1e-9); break;
      case OptionType::flag: EXPECT_EQ(written.flag(option.name()), absent.flag(option.name())); break;
      case OptionType::filename: break;  // made absolute against the file's folder
      case OptionType::text:
      case OptionType::word:
      case OptionType::link_port: EXPECT_EQ(written.text(option.name()), absent.text(option.name())); break;
      case OptionType::tuple:
        for (std::size_t i = 0; i < option.elements().size(); ++i) {
          EXPECT_NEAR(written.element(option.name(), i), absent.element(option.name(), i), 1e-9);
        }
        break;
    }
  }
}

TEST(OptionSchema, InstantiationValidatesEveryDeclaredOptionBeforeTheFactory) {
  Logger logger;
  logger.set_sink([](LogLevel, std::string_view) {});
  DriverRegistry registry;
  bool factory_ran = false;
  testing::CallCounts counts;
  DriverSpec spec;
  spec.name = "lazy";
  spec.interfaces = {protocol::kLaserCode};
  spec.access = protocol::Access::kRead;
  // Reads nothing: the schema alone refuses the bad value.
  spec.factory = [&](const DriverContext&) -> std::unique_ptr<Driver> {
    factory_ran = true;
    return std::make_unique<testing::CountingDriver>(counts);
  };
  spec.doc.schema = OptionSchema{OptionSpec::integer("count", 1, 0, 10)};
  registry.add(std::move(spec));
  const auto config =
      config::ConfigFile::parse("laser:0 ( driver \"lazy\" count 12 )\n", "v.cfg", load_options_for(registry, 7000));
  ServerClock clock;
  DeviceTable table;
  try {
    instantiate_devices(config, registry, table, clock, logger);
    FAIL() << "count 12 was accepted";
  } catch (const config::ConfigError& e) {
    EXPECT_EQ(std::string(e.what()), "v.cfg:1:31: lazy: count must be between 0 and 10 (got 12)");
  }
  EXPECT_FALSE(factory_ran);
  EXPECT_TRUE(config.unused_properties().empty());
}

}  // namespace option_schema_test
}  // namespace playerkit::core
