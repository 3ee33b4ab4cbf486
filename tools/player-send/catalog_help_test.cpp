#include "catalog_help.hpp"

#include <gtest/gtest.h>

#include <string>
#include <vector>

#include "field_assignments.hpp"
#include "protocol/interfaces.hpp"
#include "protocol/messages/all.hpp"
#include "protocol/payload_json.hpp"

namespace playerkit::player_send {
namespace catalog_help_test {

using Fields = std::vector<std::string>;

TEST(CatalogHelp, CommandFieldsAreTheStructsFieldsInWireOrder) {
  EXPECT_EQ(settable_fields(protocol::codec_of<protocol::PositionCommand>()),
            (Fields{"xpos", "ypos", "yaw", "xspeed", "yspeed", "yawspeed", "state", "type"}));
}

TEST(CatalogHelp, ListsShowTheirLengthAndVariableOnesNone) {
  EXPECT_EQ(settable_fields(protocol::codec_of<protocol::PositionGeom>()), (Fields{"subtype", "pose[3]", "size[2]"}));
  EXPECT_EQ(settable_fields(protocol::codec_of<protocol::CommsCommand>()), (Fields{"msg[]"}));
}

TEST(CatalogHelp, TheSubtypeFieldIsLeftOutOfRequests) {
  // mcom's subtype is called "command", the player device's is two bytes wide.
  EXPECT_EQ(settable_fields(protocol::codec_of<protocol::McomConfig>(), 1),
            (Fields{"type", "channel (text)", "data.full", "data.data (text)"}));
  EXPECT_EQ(settable_fields(protocol::codec_of<protocol::DriverInfo>(), 2),
            (Fields{"id.code", "id.index", "id.port", "driver_name (text)"}));
  EXPECT_EQ(settable_fields(protocol::codec_of<protocol::PositionSetOdomRequest>(), 1),
            (Fields{"x", "y", "theta"}));
}

TEST(CatalogHelp, AnInterfaceSectionShowsCommandsAndRequests) {
  const auto text = interface_help(*protocol::find_messages(protocol::kPositionCode));
  EXPECT_EQ(text.rfind("position\n", 0), 0u) << text;
  EXPECT_NE(text.find("  cmd: xpos ypos yaw xspeed yspeed yawspeed state type\n"), std::string::npos) << text;
  EXPECT_NE(text.find("  req get-geom: base pose and footprint (no fields)\n"), std::string::npos) << text;
  EXPECT_NE(text.find("  req set-odom: set the odometric pose; fields: x y theta\n"), std::string::npos) << text;
}

TEST(CatalogHelp, AnInterfaceWithNothingToSendHasNoSection) {
  EXPECT_EQ(interface_help(*protocol::find_messages(protocol::kGpsCode)), "");
}

TEST(CatalogHelp, TheCatalogNamesEveryRequestOfEveryInterface) {
  const auto text = catalog_help();
  for (const auto& messages : protocol::all_messages()) {
    const auto name = protocol::interface_name(messages.interface);
    const auto section = text.find("\n" + name + "\n");
    const bool first = text.rfind(name + "\n", 0) == 0;
    if (!messages.command && messages.requests.empty()) {
      EXPECT_NE(text.find("Nothing to send (data only):"), std::string::npos);
      EXPECT_NE(text.find(" " + name), std::string::npos) << name;
      continue;
    }
    ASSERT_TRUE(first || section != std::string::npos) << name;
    for (const auto& kind : messages.requests) {
      EXPECT_NE(text.find("  req " + std::string(kind.name) + ": " + std::string(kind.summary)), std::string::npos)
          << name << " " << kind.name;
    }
  }
}

// What the help lists must be what the parser takes: every listed field, set on
// its own, encodes.
std::string assignment_for(const std::string& listed) {
  const auto text_mark = listed.find(" (text)");
  if (text_mark != std::string::npos) return listed.substr(0, text_mark) + "=a";
  const auto bracket = listed.find('[');
  if (bracket == std::string::npos) return listed + "=1";
  std::string assignment = listed.substr(0, bracket);
  std::size_t at = bracket;
  while (at < listed.size() && listed[at] == '[') {
    assignment += ".0";
    at = listed.find(']', at) + 1;
  }
  if (listed.compare(at, 2, ".{") == 0) {
    assignment += "." + listed.substr(at + 2, listed.find_first_of(",}", at) - at - 2);
  }
  return assignment + "=1";
}

TEST(CatalogHelp, ListsOfListsAndOfStructsShowTheirShape) {
  EXPECT_EQ(settable_fields(protocol::codec_of<protocol::LocalizeSetPose>(), 1),
            (Fields{"mean[3]", "cov[3][3]"}));
  EXPECT_EQ(assignment_for("cov[3][3]"), "cov.0.0=1");
  const auto turret = settable_fields(protocol::codec_of<protocol::IdarTurretConfig>(), 1);
  ASSERT_EQ(turret.size(), 1u);
  EXPECT_EQ(turret[0].rfind("tx[8].{", 0), 0u) << turret[0];
  EXPECT_EQ(assignment_for(turret[0]).rfind("tx.0.", 0), 0u);
}

TEST(CatalogHelp, EveryListedFieldIsAccepted) {
  std::size_t checked = 0;
  for (const auto& messages : protocol::all_messages()) {
    if (messages.command) {
      for (const auto& field : settable_fields(*messages.command)) {
        const std::vector<std::string> words{assignment_for(field)};
        EXPECT_NO_THROW(messages.command->from_json(parse_field_assignments(words)))
            << protocol::interface_name(messages.interface) << " cmd " << words[0];
        ++checked;
      }
    }
    for (const auto& kind : messages.requests) {
      if (kind.form != protocol::RequestForm::kStruct || !kind.request) continue;
      for (const auto& field : settable_fields(*kind.request, messages.subtype_size)) {
        const std::vector<std::string> words{assignment_for(field)};
        EXPECT_NO_THROW(protocol::request_payload(messages, kind, parse_field_assignments(words)))
            << protocol::interface_name(messages.interface) << " req " << kind.name << " " << words[0];
        ++checked;
      }
    }
  }
  EXPECT_GT(checked, 100u);
}

}  // namespace catalog_help_test
}  // namespace playerkit::player_send
