#include "run_plan.hpp"

#include <gtest/gtest.h>

#include <filesystem>

#include "drivers_exit_status.hpp"
#include "protocol/interfaces.hpp"

namespace playerkit::player_drivers {
namespace run_plan_test {

core::DriverSpec spec(std::string name, std::vector<std::uint16_t> interfaces, protocol::Access access,
                      std::string family = "", std::vector<std::string> documented = {}) {
  core::DriverSpec made;
  made.name = std::move(name);
  made.interfaces = std::move(interfaces);
  made.access = access;
  made.family = std::move(family);
  for (auto& option : documented) made.doc.options.push_back({std::move(option), "int", "0", "", "an option"});
  return made;
}

core::DriverRegistry sample_registry() {
  core::DriverRegistry registry;
  registry.add(spec("bot_position", {protocol::kPositionCode}, protocol::Access::kAll, "bot", {"port", "max_xspeed"}));
  registry.add(spec("bot_compass", {protocol::kPositionCode}, protocol::Access::kRead, "bot", {"port"}));
  registry.add(spec("bot_gyro", {protocol::kPositionCode}, protocol::Access::kRead, "bot", {"port"}));
  registry.add(spec("bot_sonar", {protocol::kSonarCode}, protocol::Access::kRead, "bot", {"port", "sonar_rate/rate"}));
  registry.add(spec("bot_sound", {protocol::kSoundCode}, protocol::Access::kWrite, "bot", {"port"}));
  registry.add(spec("logger", {protocol::kPowerCode, protocol::kLaserCode}, protocol::Access::kRead));
  registry.add(spec("speaker", {protocol::kSoundCode}, protocol::Access::kWrite));
  return registry;
}

std::string usage_error_of(const std::function<void()>& action) {
  try {
    action();
  } catch (const UsageError& e) {
    return e.what();
  }
  return "";
}

TEST(RunPlan, OptionAssignments) {
  EXPECT_EQ(parse_option_assignment("port=/dev/ttyUSB0"), (OptionAssignment{"port", "/dev/ttyUSB0"}));
  EXPECT_EQ(parse_option_assignment("pose=[0.1 0 90]"), (OptionAssignment{"pose", "[0.1 0 90]"}));
  EXPECT_EQ(parse_option_assignment("name="), (OptionAssignment{"name", ""}));
  EXPECT_EQ(parse_option_assignment("a=b=c"), (OptionAssignment{"a", "b=c"}));
  EXPECT_EQ(usage_error_of([] { parse_option_assignment("verbose"); }),
            "'verbose' is not OPTION=VALUE (e.g. port=/dev/ttyUSB0)");
  EXPECT_EQ(usage_error_of([] { parse_option_assignment("=3"); }),
            "'=3': '' is not an option name (letters, digits and '_')");
  EXPECT_NE(usage_error_of([] { parse_option_assignment("2x=3"); }), "");
  EXPECT_NE(usage_error_of([] { parse_option_assignment("my-rate=3"); }), "");
}

TEST(RunPlan, ValuesAreWrittenAsTheConfigurationReadsThem) {
  EXPECT_EQ(config_value("38400"), "38400");
  EXPECT_EQ(config_value("-0.5"), "-0.5");
  EXPECT_EQ(config_value("+2"), "2");
  EXPECT_EQ(config_value("1e3"), "1e3");
  EXPECT_EQ(config_value("[0.1 0 90]"), "[0.1 0 90]");
  EXPECT_EQ(config_value("\"quoted\""), "\"quoted\"");
  EXPECT_EQ(config_value("/dev/ttyUSB0"), "\"/dev/ttyUSB0\"");
  EXPECT_EQ(config_value("tcp:127.0.0.1:4001"), "\"tcp:127.0.0.1:4001\"");
  EXPECT_EQ(config_value("inf"), "\"inf\"");
  EXPECT_EQ(config_value(""), "\"\"");
  EXPECT_EQ(usage_error_of([] { config_value("say \"hi\""); }),
            "'say \"hi\"': a configuration string cannot hold '\"'");
  EXPECT_EQ(usage_error_of([] { config_value("a\nb"); }), "a value cannot span lines: 'a\nb'");
}

TEST(RunPlan, OneDriverOneSectionOneOptionPerLine) {
  const RunPlan plan =
      make_run_plan(sample_registry(), {"bot_position", {{"port", "/tmp/robot"}, {"max_xspeed", "300"}}, {}, {}});
  EXPECT_FALSE(plan.family);
  EXPECT_EQ(plan.config_text,
            "# player-drivers run bot_position\n"
            "position:0 ( driver \"bot_position\"\n"
            "  port \"/tmp/robot\"\n"
            "  max_xspeed 300\n"
            ")\n");
  ASSERT_EQ(plan.devices.size(), 1u);
  EXPECT_EQ(plan.line_sources.at(2), "bot_position (position:0)");
  EXPECT_EQ(plan.line_sources.at(3), "option port=/tmp/robot");
  EXPECT_EQ(plan.option_lines.at(4), (OptionAssignment{"max_xspeed", "300"}));
}

TEST(RunPlan, ADriverOfSeveralInterfacesServesItsFirstOrTheOneAsked) {
  EXPECT_EQ(make_run_plan(sample_registry(), {"logger", {}, {}, {}}).devices[0].address,
            (protocol::DeviceAddress{protocol::kPowerCode, 0}));
  const protocol::DeviceAddress laser{protocol::kLaserCode, 2};
  EXPECT_EQ(make_run_plan(sample_registry(), {"logger", {}, laser, {}}).devices[0].address, laser);
  EXPECT_EQ(usage_error_of([] {
              make_run_plan(sample_registry(), {"logger", {}, protocol::DeviceAddress{protocol::kSonarCode, 0}, {}});
            }),
            "--device sonar:0: logger serves power, laser");
  EXPECT_EQ(usage_error_of([] {
              make_run_plan(sample_registry(), {"bot", {}, protocol::DeviceAddress{protocol::kSonarCode, 0}, {}});
            }),
            "--device sonar:0: bot is a family; its devices are numbered for you (player-drivers info bot)");
}

TEST(RunPlan, AFamilyIsNumberedPerInterfaceAndOptionsGoWhereTheyAreRead) {
  const RunPlan plan = make_run_plan(
      sample_registry(), {"bot", {{"port", "/tmp/robot"}, {"rate", "5"}, {"max_xspeed", "200"}, {"other", "1"}}, {}, {}});
  EXPECT_TRUE(plan.family);
  ASSERT_EQ(plan.devices.size(), 5u);
  EXPECT_EQ(plan.config_text,
            "# player-drivers run bot\n"
            "position:0 ( driver \"bot_position\"\n"
            "  port \"/tmp/robot\"\n"
            "  max_xspeed 200\n"
            "  other 1\n"
            ")\n"
            "sonar:0 ( driver \"bot_sonar\"\n"
            "  rate 5\n"
            ")\n"
            "sound:0 ( driver \"bot_sound\"\n"
            ")\n"
            "position:1 ( driver \"bot_compass\"\n"
            ")\n"
            "position:2 ( driver \"bot_gyro\"\n"
            ")\n");
}

TEST(RunPlan, RecordAddsAWritelogOfTheReadableDevices) {
  const RunPlan plan = make_run_plan(sample_registry(), {"bot", {}, {}, std::string("out/run.log")});
  const std::string file = (std::filesystem::current_path() / "out/run.log").lexically_normal().string();
  EXPECT_EQ(plan.recorder, (protocol::DeviceAddress{protocol::kNullCode, 0}));
  EXPECT_NE(plan.config_text.find("null:0 ( driver \"writelog\" filename \"" + file +
                                  "\" devices [\"position:0\" \"sonar:0\" \"position:1\" \"position:2\"] alwayson 1 )\n"),
            std::string::npos)
      << plan.config_text;
  EXPECT_EQ(usage_error_of([] { make_run_plan(sample_registry(), {"speaker", {}, {}, std::string("x.log")}); }),
            "--record: speaker has no device to read from, so nothing to record");
}

TEST(RunPlan, RefusesWhatCannotBeWrittenBeforeAnythingStarts) {
  EXPECT_EQ(usage_error_of([] { make_run_plan(sample_registry(), {"bot_position", {{"port", "a"}, {"port", "b"}}, {}, {}}); }),
            "option 'port' is given twice (port=a, port=b)");
  EXPECT_NE(usage_error_of([] { make_run_plan(sample_registry(), {"bot_position", {{"port", "a\"b"}}, {}, {}}); }), "");
  EXPECT_EQ(usage_error_of([] { make_run_plan(sample_registry(), {"bot_positon", {}, {}, {}}); }),
            "no driver or driver family 'bot_positon'; did you mean 'bot_position'? (player-drivers list shows them all)");
}

TEST(RunPlan, MessagesAtGeneratedLinesNameWhatWasTyped) {
  const RunPlan plan = make_run_plan(sample_registry(), {"bot_position", {{"max_xspeed", "fast"}}, {}, {}});
  EXPECT_EQ(explain_config_message(plan, "<run>", "<run>:3:14: bot_position: max_xspeed must be a number"),
            "option max_xspeed=fast: bot_position: max_xspeed must be a number");
  EXPECT_EQ(explain_config_message(plan, "<run>", "<run>:2:1: bot_position: cannot work"),
            "bot_position (position:0): bot_position: cannot work");
  EXPECT_EQ(explain_config_message(plan, "<run>", "<run>:9: something"), "<run>:9: something");
  EXPECT_EQ(explain_config_message(plan, "<run>", "listening on port 7"), "listening on port 7");
  const auto split = split_config_message("<run>", "<run>:3:3: warning: property 'x' is defined but not used");
  ASSERT_TRUE(split);
  EXPECT_EQ(split->line, 3);
  EXPECT_EQ(split->text, "warning: property 'x' is defined but not used");
  EXPECT_FALSE(split_config_message("<run>", "<run>:x:3: text"));
}

}  // namespace run_plan_test
}  // namespace playerkit::player_drivers
