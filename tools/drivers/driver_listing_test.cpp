#include "driver_listing.hpp"

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include <sstream>

#include "daemon/serve.hpp"
#include "driver_lookup.hpp"
#include "drivers_exit_status.hpp"
#include "protocol/interfaces.hpp"

namespace playerkit::player_drivers {
namespace driver_listing_test {

core::DriverSpec spec(std::string name, std::vector<std::uint16_t> interfaces, protocol::Access access,
                      std::string family = "") {
  core::DriverSpec made;
  made.name = std::move(name);
  made.interfaces = std::move(interfaces);
  made.access = access;
  made.summary = made.name + " summary";
  made.family = std::move(family);
  return made;
}

// A small robot family (documented), a documented laser and an undocumented driver.
core::DriverRegistry sample_registry() {
  core::DriverRegistry registry;
  auto laser = spec("toylaser", {protocol::kLaserCode}, protocol::Access::kRead, "toy");
  laser.doc.manual_section = "7.39";
  laser.doc.needs_hardware = true;
  laser.doc.options = {{"port", "string", "\"/dev/ttyS1\"", "", "the serial port"},
                       {"rate", "int", "38400", "baud", "line speed"}};
  laser.doc.requests = {"GET_GEOM: pose and size"};
  laser.doc.example = "laser:0 ( driver \"toylaser\" port \"/dev/ttyUSB0\" )";
  registry.add(laser);
  registry.add(spec("bot_compass", {protocol::kPositionCode}, protocol::Access::kRead, "bot"));
  registry.add(spec("bot_position", {protocol::kPositionCode}, protocol::Access::kAll, "bot"));
  registry.add(spec("bot_sonar", {protocol::kSonarCode}, protocol::Access::kRead, "bot"));
  registry.add(spec("plain", {protocol::kMcomCode}, protocol::Access::kAll));
  return registry;
}

std::string list_text(const core::DriverRegistry& registry, ListOptions options = {}) {
  std::ostringstream out;
  write_driver_list(registry, options, out);
  return out.str();
}

std::string info_text(const core::DriverRegistry& registry, std::string_view name, bool json = false) {
  std::ostringstream out;
  write_driver_info(registry, name, json, out);
  return out.str();
}

bool contains(const std::string& text, const std::string& part) { return text.find(part) != std::string::npos; }

TEST(DriverListing, TextHasOneAlignedRowPerDriverAndTheFamilies) {
  const std::string text = list_text(sample_registry());
  EXPECT_EQ(text,
            "DRIVER        INTERFACES  ACCESS  HARDWARE  SUMMARY\n"
            "bot_compass   position    r       no        bot_compass summary\n"
            "bot_position  position    a       no        bot_position summary\n"
            "bot_sonar     sonar       r       no        bot_sonar summary\n"
            "plain         mcom        a       no        plain summary\n"
            "toylaser      laser       r       yes       toylaser summary\n"
            "\nFamilies, run together on one link with `player-drivers run FAMILY`: bot (3 drivers)\n");
}

TEST(DriverListing, InterfaceFilter) {
  EXPECT_EQ(list_text(sample_registry(), {.interface = protocol::kPositionCode, .json = false}),
            "DRIVER        INTERFACES  ACCESS  HARDWARE  SUMMARY\n"
            "bot_compass   position    r       no        bot_compass summary\n"
            "bot_position  position    a       no        bot_position summary\n");
}

TEST(DriverListing, JsonLines) {
  const std::string text = list_text(sample_registry(), {.interface = protocol::kLaserCode, .json = true});
  const auto line = nlohmann::json::parse(text);
  EXPECT_EQ(line["name"], "toylaser");
  EXPECT_EQ(line["interfaces"], nlohmann::json::array({"laser"}));
  EXPECT_EQ(line["access"], "r");
  EXPECT_EQ(line["needs_hardware"], true);
  EXPECT_EQ(line["family"], "toy");
  EXPECT_EQ(line["documented"], true);
}

TEST(DriverListing, InfoShowsOptionsRequestsManualAndConfig) {
  const std::string text = info_text(sample_registry(), "toylaser");
  EXPECT_TRUE(contains(text, "toylaser: toylaser summary\n")) << text;
  EXPECT_TRUE(contains(text, "  interfaces      laser (6)\n")) << text;
  EXPECT_TRUE(contains(text, "  access          r (read: data and requests)\n")) << text;
  EXPECT_TRUE(contains(text, "  needs hardware  yes\n")) << text;
  EXPECT_TRUE(contains(text, "  manual          section 7.39 of the Player 1.5 manual\n")) << text;
  EXPECT_TRUE(contains(text, "  NAME  TYPE    DEFAULT       UNIT  SUMMARY\n")) << text;
  EXPECT_TRUE(contains(text, "  rate  int     38400         baud  line speed\n")) << text;
  EXPECT_TRUE(contains(text, "Requests:\n  GET_GEOM: pose and size\n")) << text;
  EXPECT_TRUE(contains(text, "Config:\n  laser:0 ( driver \"toylaser\" port \"/dev/ttyUSB0\" )\n")) << text;
  EXPECT_TRUE(contains(text, "player-drivers run toylaser port=/dev/ttyUSB0 -n 5")) << text;
  // A port that is a TCP port number (a Nomad's server) is tried with its default, not a tty.
  core::DriverRegistry networked;
  auto netbot = spec("netbot", {protocol::kPositionCode}, protocol::Access::kAll);
  netbot.doc.options = {{"host", "string", "\"localhost\"", "", "the robot's server"},
                        {"port", "int", "7019", "", "its TCP port"}};
  networked.add(netbot);
  EXPECT_TRUE(contains(info_text(networked, "netbot"), "player-drivers run netbot port=7019 -n 5"));
  // A driver that cannot run in any build says why instead of "Try it".
  auto refused = spec("oldbot", {protocol::kPositionCode}, protocol::Access::kAll);
  refused.doc.unavailable = "its middleware cannot be had; use newbot";
  networked.add(refused);
  const std::string text_of_refused = info_text(networked, "oldbot");
  EXPECT_TRUE(contains(text_of_refused, "Cannot run:\n  its middleware cannot be had; use newbot\n")) << text_of_refused;
  EXPECT_FALSE(contains(text_of_refused, "Try it")) << text_of_refused;
}

TEST(DriverListing, AnUndocumentedDriverStillHasAnInfoAndAConfig) {
  const std::string text = info_text(sample_registry(), "plain");
  EXPECT_TRUE(contains(text, "Options: not documented for this driver\n")) << text;
  EXPECT_TRUE(contains(text, "Requests: not documented for this driver\n")) << text;
  EXPECT_TRUE(contains(text, "Config:\n  mcom:0 ( driver \"plain\" )\n")) << text;
  EXPECT_TRUE(contains(text, "  manual          not documented\n")) << text;
}

TEST(DriverListing, AFamilyIsNumberedPerInterfaceTheDriverNamedAfterItFirst) {
  const std::string text = info_text(sample_registry(), "bot");
  EXPECT_TRUE(contains(text, "bot: a family of 3 drivers")) << text;
  EXPECT_TRUE(contains(text, "  position:0  bot_position  bot_position summary\n")) << text;
  EXPECT_TRUE(contains(text, "  sonar:0     bot_sonar     bot_sonar summary\n")) << text;
  EXPECT_TRUE(contains(text, "  position:1  bot_compass   bot_compass summary\n")) << text;
  const auto json = nlohmann::json::parse(info_text(sample_registry(), "bot", true));
  EXPECT_EQ(json["family"], "bot");
  EXPECT_EQ(json["drivers"][0]["device"], "position:0");
  EXPECT_EQ(json["drivers"][2]["name"], "bot_compass");
}

TEST(DriverListing, InfoJsonOfADriver) {
  const auto json = nlohmann::json::parse(info_text(sample_registry(), "toylaser", true));
  EXPECT_EQ(json["manual_section"], "7.39");
  EXPECT_EQ(json["options"][1]["unit"], "baud");
  EXPECT_EQ(json["config"], "laser:0 ( driver \"toylaser\" port \"/dev/ttyUSB0\" )");
}

TEST(DriverListing, UnknownNamesSuggestTheNearest) {
  try {
    info_text(sample_registry(), "toylazer");
    FAIL() << "no error";
  } catch (const UsageError& e) {
    EXPECT_EQ(std::string(e.what()),
              "no driver or driver family 'toylazer'; did you mean 'toylaser'? (player-drivers list shows them all)");
  }
  EXPECT_THROW(info_text(sample_registry(), "zzz"), UsageError);
}

TEST(DriverListing, EveryBuiltInDriverListsAndHasAnInfo) {
  core::Logger logger("test");
  const auto registry = daemon::load_drivers({}, logger);
  ASSERT_FALSE(registry.all().empty());
  const std::string text = list_text(registry);
  for (const auto* driver : registry.all()) {
    EXPECT_TRUE(contains(text, "\n" + driver->name + " ")) << driver->name;
    const std::string info = info_text(registry, driver->name);
    EXPECT_TRUE(contains(info, "Config:\n  ")) << info;
    EXPECT_TRUE(nlohmann::json::parse(info_text(registry, driver->name, true)).is_object()) << driver->name;
  }
  EXPECT_TRUE(contains(info_text(registry, "null"), "  null:0 ( driver \"null\" )\n"));
  // passthrough serves every interface.
  EXPECT_TRUE(contains(text, "\npassthrough  ") && contains(text, " any ")) << text;
}

}  // namespace driver_listing_test
}  // namespace playerkit::player_drivers
