// How `player-drivers probe` prints a port's result. Finding the device is
// tested with the probes (lib/families/port_probe_test.cpp and each family's
// test).

#include "probe_output.hpp"

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include <sstream>
#include <string>

namespace playerkit::player_drivers {
namespace probe_output_test {

families::ProbeResult found_robot(std::string note) {
  families::ProbeResult result;
  result.port = "/tmp/pk-robot";
  result.found = families::Identification{.driver = "p2os",
                                          .model = "Pioneer p3dx \"robot\"",
                                          .interface_name = "position",
                                          .config_driver = "p2os_position",
                                          .note = std::move(note)};
  result.baud = 9600;
  result.config_line = "position:0 ( driver \"p2os_position\" port \"/tmp/pk-robot\" )";
  return result;
}

families::ProbeResult missing_port() {
  families::ProbeResult result;
  result.port = "/tmp/pk-missing";
  result.problem = "no such port /tmp/pk-missing";
  result.port_unusable = true;
  return result;
}

std::string text_of(const families::ProbeResult& result) {
  std::ostringstream text;
  write_probe_result(result, false, text);
  return text.str();
}

nlohmann::json json_of(const families::ProbeResult& result) {
  std::ostringstream json;
  write_probe_result(result, true, json);
  EXPECT_EQ(json.str().find('\n'), json.str().size() - 1) << "one line: " << json.str();
  return nlohmann::json::parse(json.str());
}

TEST(ProbeOutput, TextReport) {
  EXPECT_EQ(text_of(found_robot("a note")),
            "/tmp/pk-robot: p2os at 9600 baud, Pioneer p3dx \"robot\"\n"
            "    position:0 ( driver \"p2os_position\" port \"/tmp/pk-robot\" )\n"
            "    (a note)\n");
}

TEST(ProbeOutput, TextReportWithoutANote) {
  EXPECT_EQ(text_of(found_robot("")),
            "/tmp/pk-robot: p2os at 9600 baud, Pioneer p3dx \"robot\"\n"
            "    position:0 ( driver \"p2os_position\" port \"/tmp/pk-robot\" )\n");
}

TEST(ProbeOutput, TextReportOfATcpPortHasNoBaud) {
  families::ProbeResult result;
  result.port = "tcp:127.0.0.1:4001";
  result.found = families::Identification{.driver = "sicklms200",
                                          .model = "LMS200;30106",
                                          .interface_name = "laser",
                                          .config_driver = "sicklms200",
                                          .note = ""};
  result.baud = 0;
  result.config_line = "laser:0 ( driver \"sicklms200\" port \"tcp:127.0.0.1:4001\" )";
  EXPECT_EQ(text_of(result), "tcp:127.0.0.1:4001: sicklms200, LMS200;30106\n    " + result.config_line + "\n");
}

TEST(ProbeOutput, TextReportOfAProblem) {
  EXPECT_EQ(text_of(missing_port()), "/tmp/pk-missing: no such port /tmp/pk-missing\n");
}

TEST(ProbeOutput, JsonReportOfAFind) {
  const auto line = json_of(found_robot("a note"));
  EXPECT_EQ(line["port"], "/tmp/pk-robot");
  EXPECT_EQ(line["found"], true);
  EXPECT_EQ(line["driver"], "p2os");
  EXPECT_EQ(line["model"], "Pioneer p3dx \"robot\"");
  EXPECT_EQ(line["baud"], 9600);
  EXPECT_EQ(line["config"], "position:0 ( driver \"p2os_position\" port \"/tmp/pk-robot\" )");
  EXPECT_EQ(line["note"], "a note");
  EXPECT_FALSE(line.contains("problem"));
  EXPECT_FALSE(json_of(found_robot("")).contains("note"));
}

TEST(ProbeOutput, JsonReportOfAProblem) {
  const auto line = json_of(missing_port());
  EXPECT_EQ(line["port"], "/tmp/pk-missing");
  EXPECT_EQ(line["found"], false);
  EXPECT_EQ(line["port_unusable"], true);
  EXPECT_EQ(line["problem"], "no such port /tmp/pk-missing");
  EXPECT_FALSE(line.contains("driver"));
}

}  // namespace probe_output_test
}  // namespace playerkit::player_drivers
