// The nomad family as the tools see it: no serial probe, the emulated robot
// on a loopback TCP port answering as Nomadic's server, and Nclient framing
// for traces.

#include "families/nomad/nomad_family.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <chrono>
#include <string>

#include "emulators/catalog/emulator_catalog.hpp"
#include "emulators/runner/emulator_runner.hpp"
#include "families/nomad/protocol/nomad_requests.hpp"
#include "links/framed_reader.hpp"
#include "links/tcp_link.hpp"

namespace playerkit::families {
namespace nomad_family_test {

using namespace std::chrono_literals;
namespace nomad = hardware::nomad;

emulators::EmulatorCatalog catalog() { return emulators::EmulatorCatalog(nomad_family().emulators); }

std::string refusal(const emulators::EmulatorOptionValues& options) {
  try {
    (void)catalog().make("nomad", options, {});
  } catch (const std::invalid_argument& e) {
    return e.what();
  }
  return "";
}

TEST(NomadFamily, OffersTheRobotAsAMobileBaseWithNoSerialProbe) {
  const FamilySpec spec = nomad_family();
  EXPECT_TRUE(spec.probes.empty());
  const emulators::EmulatorCatalog kinds = catalog();
  const emulators::EmulatorKind* robot = kinds.find("nomad");
  ASSERT_NE(robot, nullptr);
  EXPECT_EQ(robot->mount, emulators::EmulatorMount::robot);
  EXPECT_EQ(config_example(*robot, "tcp:127.0.0.1:7019"), "nomad:0 ( driver \"nomad\" port \"tcp:127.0.0.1:7019\" )");
  for (const std::string name : {"pose", "odometry_scale", "rotation_scale", "drift", "seed", "reply_delay"}) {
    EXPECT_TRUE(std::any_of(robot->options.begin(), robot->options.end(),
                            [&](const auto& option) { return option.name == name; }))
        << name;
  }
  EXPECT_NE(refusal({{"reply_delay", "-1"}}).find("reply_delay"), std::string::npos);
  EXPECT_EQ(refusal({{"pose", "1,2,90"}, {"ir_range", "24"}}), "");
}

TEST(NomadFamily, TheEmulatorAnswersAClientOnItsTcpPortAsTheServerDid) {
  emulators::EmulatorRunner server(catalog().make("nomad", {{"pose", "1,2,90"}}, {}), emulators::TcpEndpoint{});
  const std::string address = server.device_path();
  ASSERT_EQ(address.rfind("tcp:127.0.0.1:", 0), 0U) << address;
  const auto port = static_cast<std::uint16_t>(std::stoi(address.substr(address.rfind(':') + 1)));
  auto link = links::TcpLink::connect("127.0.0.1", port, links::deadline_in(2s));
  const nomad::NclientFormat format;
  links::FramedReader reader(*link, format);
  link->write_all(nomad::encode(nomad::connect_robot(42)), links::deadline_in(1s));
  const auto connected = reader.next(links::deadline_in(2s));
  ASSERT_TRUE(connected);
  EXPECT_EQ(nomad::decode(*connected)->type, nomad::message_type::kConnectRobot);
  EXPECT_NE(nomad::decode(*connected)->words.at(0), 0);
  link->write_all(nomad::encode(nomad::get_state()), links::deadline_in(1s));
  const auto state = reader.next(links::deadline_in(2s));
  ASSERT_TRUE(state);
  ASSERT_TRUE(nomad::parse_state(*nomad::decode(*state)));
  EXPECT_EQ(server.with_emulator<emulators::DeviceEmulator>([](auto& e) { return e.world_pose()->x; }), 1.0);
}

TEST(NomadFamily, TraceFramingCutsMessagesAtTheirWordCount) {
  const auto framing = nomad_family().framing;
  ASSERT_NE(framing.incoming, nullptr);
  ASSERT_NE(framing.outgoing, nullptr);
  auto bytes = nomad::encode(nomad::velocity(1, 2, 3));
  const auto state = nomad::encode(nomad::state_reply({}));
  bytes.insert(bytes.end(), state.begin(), state.end());
  const auto first = framing.outgoing->scan(bytes);
  EXPECT_EQ(first.kind, framing::FrameScan::Kind::frame);
  EXPECT_EQ(first.length, 16U);
  EXPECT_EQ(framing.incoming->scan(std::span(bytes).subspan(16)).length, state.size());
}

}  // namespace nomad_family_test
}  // namespace playerkit::families
