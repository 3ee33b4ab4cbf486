// SI conversion of payload JSON: golden conversions per interface (wire JSON in,
// SI JSON out, every value worked out by hand), and a check of the unit table
// against the spec's "Unit / meaning" column (tests/data/wire-format-units.tsv).

#include "protocol/si_units.hpp"

#include <algorithm>
#include <cmath>
#include <fstream>
#include <map>
#include <regex>
#include <set>
#include <sstream>
#include <tuple>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "protocol/catalog.hpp"
#include "protocol/errors.hpp"
#include "protocol/interfaces.hpp"
#include "protocol/message_json.hpp"
#include "protocol/messages/all.hpp"
#include "protocol/payload_json.hpp"

namespace playerkit::protocol {
namespace si_units_test {

using nlohmann::json;

// ---------------------------------------------------------------------------
// Golden conversions

struct Golden {
  std::uint16_t interface = 0;
  MessageType type = MessageType::kData;
  std::optional<std::uint16_t> subtype;  // requests and replies
  json wire;                             // the payload, in wire units
  json si_values;                        // JSON pointer -> expected SI value(s)
};

// Compares actual with expected. Inside a converted subtree numbers must be floating
// point and equal within 4 ulps; everywhere else values must be identical, type included
// (a field without a unit keeps its integer).
void expect_same(const json& actual, const json& expected, const std::string& path, bool converted) {
  SCOPED_TRACE(path);
  if (expected.is_number() && converted) {
    ASSERT_TRUE(actual.is_number_float()) << "expected a converted value, got " << actual.dump();
    EXPECT_DOUBLE_EQ(actual.get<double>(), expected.get<double>());
    return;
  }
  ASSERT_EQ(actual.type(), expected.type()) << actual.dump() << " vs " << expected.dump();
  if (expected.is_object()) {
    ASSERT_EQ(actual.size(), expected.size()) << actual.dump();
    for (const auto& [key, value] : expected.items()) {
      ASSERT_TRUE(actual.contains(key)) << key;
      expect_same(actual.at(key), value, path + "/" + key, converted);
    }
  } else if (expected.is_array()) {
    ASSERT_EQ(actual.size(), expected.size()) << actual.dump();
    for (std::size_t i = 0; i < expected.size(); ++i) {
      expect_same(actual[i], expected[i], path + "/" + std::to_string(i), converted);
    }
  } else {
    EXPECT_EQ(actual, expected);
  }
}

// expected = the wire JSON with the converted values put in; pointers listed in
// si_values are the converted subtrees.
void expect_conversion(const Golden& g) {
  const auto payload = payload_from_json(g.interface, g.type, g.wire, g.subtype);
  const json wire = payload_to_json(g.interface, g.type, payload, g.subtype);
  const json si = payload_to_si_json(g.interface, g.type, payload, g.subtype);
  json expected = wire;
  std::set<std::string> converted;
  for (const auto& [pointer, value] : g.si_values.items()) {
    ASSERT_TRUE(wire.contains(json::json_pointer(pointer))) << pointer << " not in " << wire.dump();
    expected[json::json_pointer(pointer)] = value;
    converted.insert(pointer);
  }
  // Compare converted subtrees and the rest separately.
  for (const auto& pointer : converted) {
    expect_same(si.at(json::json_pointer(pointer)), expected.at(json::json_pointer(pointer)), pointer, true);
    expected[json::json_pointer(pointer)] = nullptr;
  }
  json rest = si;
  for (const auto& pointer : converted) rest[json::json_pointer(pointer)] = nullptr;
  expect_same(rest, expected, "", false);
}

constexpr double kHalfPi = 1.5707963267948966;  // 90 deg
constexpr double kPi = 3.141592653589793;
constexpr double kQuarterPi = 0.7853981633974483;  // 45 deg
constexpr double kOneDegree = 0.017453292519943295;

std::vector<Golden> goldens() {
  using T = MessageType;
  return {
      {kPowerCode, T::kData, {}, {{"charge", 125}}, {{"/charge", 12.5}}},
      {kPowerCode, T::kAck, kMainPowerReq, {{"charge", 131}}, {{"/charge", 13.1}}},

      {kPositionCode, T::kData, {},
       {{"xpos", 1500}, {"ypos", -250}, {"yaw", 90}, {"xspeed", 300}, {"yspeed", -20}, {"yawspeed", -45}, {"stall", 1}},
       {{"/xpos", 1.5}, {"/ypos", -0.25}, {"/yaw", kHalfPi}, {"/xspeed", 0.3}, {"/yspeed", -0.02},
        {"/yawspeed", -kQuarterPi}}},
      {kPositionCode, T::kCommand, {},
       {{"xpos", 7}, {"yaw", 180}, {"xspeed", 500}, {"yawspeed", 30}, {"state", 1}, {"type", 0}},
       {{"/xpos", 0.007}, {"/ypos", 0.0}, {"/yaw", kPi}, {"/xspeed", 0.5}, {"/yspeed", 0.0},
        {"/yawspeed", 0.5235987755982988}}},
      {kPositionCode, T::kAck, kPositionGetGeomReq, {{"pose", {-100, 50, -90}}, {"size", {450, 380}}},
       {{"/pose", {-0.1, 0.05, -kHalfPi}}, {"/size", {0.45, 0.38}}}},
      {kPositionCode, T::kRequest, kPositionSetOdomReq, {{"x", 1000}, {"y", 2000}, {"theta", 45}},
       {{"/x", 1.0}, {"/y", 2.0}, {"/theta", kQuarterPi}}},

      {kPosition3dCode, T::kData, {},
       {{"xpos", 1000}, {"ypos", 2000}, {"zpos", -500}, {"roll", 3600}, {"pitch", -1296000}, {"yaw", 648000},
        {"xspeed", 100}, {"zspeed", -10}, {"yawspeed", 324000}, {"stall", 1}},
       {{"/xpos", 1.0}, {"/ypos", 2.0}, {"/zpos", -0.5}, {"/roll", kOneDegree}, {"/pitch", -6.283185307179586},
        {"/yaw", kPi}, {"/xspeed", 0.1}, {"/yspeed", 0.0}, {"/zspeed", -0.01}, {"/rollspeed", 0.0},
        {"/pitchspeed", 0.0}, {"/yawspeed", kHalfPi}}},
      {kPosition3dCode, T::kCommand, {},
       {{"xpos", -1}, {"roll", -162000}, {"xspeed", 2500}, {"pitchspeed", 36000}},
       {{"/xpos", -0.001}, {"/ypos", 0.0}, {"/zpos", 0.0}, {"/roll", -kQuarterPi}, {"/pitch", 0.0}, {"/yaw", 0.0},
        {"/xspeed", 2.5}, {"/yspeed", 0.0}, {"/zspeed", 0.0}, {"/rollspeed", 0.0},
        {"/pitchspeed", 0.17453292519943295}, {"/yawspeed", 0.0}}},

      {kSonarCode, T::kData, {}, {{"range_count", 3}, {"ranges", {0, 5000, 123}}},
       {{"/ranges", {0.0, 5.0, 0.123}}}},
      {kSonarCode, T::kAck, kSonarGetGeomReq, {{"pose_count", 2}, {"poses", {{100, 0, 0}, {-100, 50, 180}}}},
       {{"/poses", {{0.1, 0.0, 0.0}, {-0.1, 0.05, kPi}}}}},

      {kLaserCode, T::kData, {},
       {{"min_angle", -9000}, {"max_angle", 9000}, {"resolution", 50}, {"range_res", 10}, {"range_count", 3},
        {"ranges", {100, 1234, 0}}, {"intensity", {0, 1, 7}}},
       {{"/min_angle", -kHalfPi}, {"/max_angle", kHalfPi}, {"/resolution", 0.008726646259971648},
        {"/ranges", {1.0, 12.34, 0.0}}}},
      {kLaserCode, T::kAck, kLaserGetGeom, {{"pose", {120, 0, 0}}, {"size", {155, 185}}},
       {{"/pose", {0.12, 0.0, 0.0}}, {"/size", {0.155, 0.185}}}},
      {kLaserCode, T::kRequest, kLaserSetConfig,
       {{"min_angle", -4500}, {"max_angle", 4500}, {"resolution", 25}, {"range_res", 1}, {"intensity", 1}},
       {{"/min_angle", -kQuarterPi}, {"/max_angle", kQuarterPi}, {"/resolution", 0.004363323129985824}}},

      {kBlobfinderCode, T::kData, {},
       {{"width", 80}, {"height", 60}, {"blobs", {{{"color", 0xFF0000}, {"area", 12}, {"x", 40}, {"range", 1500}}}}},
       {{"/blobs/0/range", 1.5}}},

      {kPtzCode, T::kData, {},
       {{"pan", -30}, {"tilt", 10}, {"zoom", 60}, {"panspeed", 15}, {"tiltspeed", -5}},
       {{"/pan", -0.5235987755982988}, {"/tilt", 0.17453292519943295}, {"/zoom", 1.0471975511965976},
        {"/panspeed", 0.2617993877991494}, {"/tiltspeed", -0.08726646259971647}}},
      {kPtzCode, T::kCommand, {}, {{"pan", 90}, {"tilt", -90}, {"zoom", 120}},
       {{"/pan", kHalfPi}, {"/tilt", -kHalfPi}, {"/zoom", 2.0943951023931953}, {"/panspeed", 0.0},
        {"/tiltspeed", 0.0}}},

      {kFiducialCode, T::kData, {},
       {{"count", 2},
        {"fiducials",
         {{{"id", 7}, {"pose", {2500, -30, 90}}, {"upose", {10, 1, 5}}},
          {{"id", -1}, {"pose", {800, 45, 0}}, {"upose", {0, 0, 0}}}}}},
       {{"/fiducials/0/pose", {2.5, -0.5235987755982988, kHalfPi}},
        {"/fiducials/0/upose", {0.01, kOneDegree, 0.08726646259971647}},
        {"/fiducials/1/pose", {0.8, kQuarterPi, 0.0}},
        {"/fiducials/1/upose", {0.0, 0.0, 0.0}}}},
      {kFiducialCode, T::kAck, kFiducialGetGeom,
       {{"pose", {200, -100, 180}}, {"size", {50, 60}}, {"fiducial_size", {300, 400}}},
       {{"/pose", {0.2, -0.1, kPi}}, {"/size", {0.05, 0.06}}, {"/fiducial_size", {0.3, 0.4}}}},
      {kFiducialCode, T::kRequest, kFiducialSetFov, {{"min_range", 300}, {"max_range", 8000}, {"view_angle", 180}},
       {{"/min_range", 0.3}, {"/max_range", 8.0}, {"/view_angle", kPi}}},

      {kGpsCode, T::kData, {},
       {{"time_sec", 1086000000}, {"time_usec", 500000}, {"latitude", 7776000}, {"longitude", -26352000},
        {"altitude", 12345}, {"utm_e", 58012345}, {"utm_n", 398765432}, {"quality", 1}, {"num_sats", 7},
        {"hdop", 12}, {"err_horz", 2500}, {"err_vert", 4000}},
       {{"/latitude", 36.0}, {"/longitude", -122.0}, {"/altitude", 12.345}, {"/utm_e", 580123.45},
        {"/utm_n", 3987654.32}, {"/hdop", 1.2}, {"/err_horz", 2.5}, {"/err_vert", 4.0}}},

      {kBumperCode, T::kAck, kBumperGetGeomReq,
       {{"bumper_count", 1},
        {"bumper_def", {{{"x_offset", -50}, {"y_offset", 120}, {"th_offset", 90}, {"length", 200}, {"radius", 0}}}}},
       {{"/bumper_def/0/x_offset", -0.05}, {"/bumper_def/0/y_offset", 0.12}, {"/bumper_def/0/th_offset", kHalfPi},
        {"/bumper_def/0/length", 0.2}, {"/bumper_def/0/radius", 0.0}}},

      {kTruthCode, T::kData, {}, {{"px", 1000}, {"py", -2000}, {"pa", -180}},
       {{"/px", 1.0}, {"/py", -2.0}, {"/pa", -kPi}}},
      {kTruthCode, T::kAck, kTruthGetPose, {{"px", 5}, {"py", 0}, {"pa", 45}},
       {{"/px", 0.005}, {"/py", 0.0}, {"/pa", kQuarterPi}}},

      {kIdarCode, T::kAck, kIdarReceive, {{"len", 2}, {"intensity", 9}, {"timestamp_sec", 3}, {"range", 1500}},
       {{"/range", 1.5}}},
      {kIdarturretCode, T::kAck, kIdarReceive, {{"rx", {{{"range", 250}}, {{"range", 4000}}}}},
       {{"/rx/0/range", 0.25}, {"/rx/1/range", 4.0}, {"/rx/2/range", 0.0}, {"/rx/3/range", 0.0},
        {"/rx/4/range", 0.0}, {"/rx/5/range", 0.0}, {"/rx/6/range", 0.0}, {"/rx/7/range", 0.0}}},

      {kDescartesCode, T::kCommand, {}, {{"speed", 250}, {"heading", -90}, {"distance", 1000}},
       {{"/speed", 0.25}, {"/heading", -kHalfPi}, {"/distance", 1.0}}},
      {kDescartesCode, T::kData, {}, {{"xpos", 300}, {"ypos", -400}, {"theta", 45}, {"bumpers", {1, 0}}},
       {{"/xpos", 0.3}, {"/ypos", -0.4}, {"/theta", kQuarterPi}}},

      {kIrCode, T::kData, {}, {{"range_count", 2}, {"voltages", {512, 1023}}, {"ranges", {150, 800}}},
       {{"/ranges", {0.15, 0.8}}}},
      {kIrCode, T::kAck, kIrPoseReq, {{"poses", {{"pose_count", 2}, {"poses", {{10, 20, 90}, {-10, 20, -90}}}}}},
       {{"/poses/poses", {{0.01, 0.02, kHalfPi}, {-0.01, 0.02, -kHalfPi}}}}},

      {kLocalizeCode, T::kData, {},
       {{"pending_count", 0}, {"pending_time_sec", 5}, {"hypoth_count", 1},
        {"hypoths",
         {{{"mean", {1000, -500, 324000}},
           {"cov", {{1000000, 0, 3600}, {0, 250000, 0}, {3600, 0, 1296000000}}},
           {"alpha", 750000}}}}},
       {{"/hypoths/0/mean", {1.0, -0.5, kHalfPi}},
        {"/hypoths/0/cov",
         {{1.0, 0.0, 1.7453292519943296e-05}, {0.0, 0.25, 0.0}, {1.7453292519943296e-05, 0.0, 0.030461741978670857}}},
        {"/hypoths/0/alpha", 0.75}}},
      {kLocalizeCode, T::kRequest, kLocalizeSetPoseReq,
       {{"mean", {0, 0, -648000}}, {"cov", {{4000000, 0, 0}, {0, 4000000, 0}, {0, 0, 0}}}},
       {{"/mean", {0.0, 0.0, -kPi}}, {"/cov", {{4.0, 0.0, 0.0}, {0.0, 4.0, 0.0}, {0.0, 0.0, 0.0}}}}},
      {kLocalizeCode, T::kAck, kLocalizeGetMapInfoReq, {{"scale", 10000}, {"width", 400}, {"height", 300}},
       {{"/scale", 10.0}}},

      {kNomadCode, T::kData, {},
       {{"x", 100}, {"y", -100}, {"a", 270}, {"vel_trans", 5}, {"sonar", {1000, 2000}}, {"ir", {300}}},
       {{"/x", 0.1}, {"/y", -0.1}, {"/a", 4.71238898038469},
        {"/sonar", {1.0, 2.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0}},
        {"/ir", {0.3, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0}}}},
  };
}

TEST(SiUnits, GoldenConversionPerInterface) {
  for (const auto& g : goldens()) {
    SCOPED_TRACE(interface_name(g.interface) + " " + std::string(to_string(g.type)) + " " + g.wire.dump());
    expect_conversion(g);
  }
}

TEST(SiUnits, LaserRangeResolutionScalesRanges) {
  LaserData scan;
  scan.range_count = 2;
  scan.ranges = {};
  scan.ranges[0] = 435;
  scan.ranges[1] = 8191;
  for (const auto& [range_res, first, second] :
       std::vector<std::tuple<std::uint16_t, double, double>>{{1, 0.435, 8.191}, {100, 43.5, 819.1},
                                                              // unset (0) means millimetres
                                                              {0, 0.435, 8.191}}) {
    scan.range_res = range_res;
    const json si = payload_to_si_json(kLaserCode, MessageType::kData, encode(scan));
    EXPECT_EQ(si["range_res"], range_res);
    EXPECT_DOUBLE_EQ(si["ranges"][0].get<double>(), first) << range_res;
    EXPECT_DOUBLE_EQ(si["ranges"][1].get<double>(), second) << range_res;
  }
}

TEST(SiUnits, InterfacesWithoutUnitsAndRawPayloadsAreUnchanged) {
  const std::vector<std::uint8_t> dio{5, 0x00, 0x00, 0x01, 0x02};
  EXPECT_EQ(payload_to_si_json(kDioCode, MessageType::kData, dio),
            payload_to_json(kDioCode, MessageType::kData, dio));
  // An unknown request subtype stays raw bytes; a bare query stays its subtype.
  const std::vector<std::uint8_t> unknown{99, 1, 2};
  EXPECT_EQ(payload_to_si_json(kLaserCode, MessageType::kRequest, unknown), (json{{"raw", {99, 1, 2}}}));
  const std::vector<std::uint8_t> query{kLaserGetGeom};
  EXPECT_EQ(payload_to_si_json(kLaserCode, MessageType::kRequest, query), (json{{"subtype", 1}}));
  EXPECT_EQ(payload_to_si_json(kPositionCode, MessageType::kAck, {}), json::object());
}

TEST(SiUnits, BadPayloadsThrowLikeWireJson) {
  const std::vector<std::uint8_t> short_position(10, 0);
  EXPECT_THROW(payload_to_si_json(kPositionCode, MessageType::kData, short_position), DecodeError);
}

TEST(SiUnits, MessageKeepsItsEnvelope) {
  PositionData odom;
  odom.xpos = -1234;
  odom.yaw = 45;
  Message m;
  m.payload = encode(odom);
  m.header = make_header(MessageType::kData, {kPositionCode, 2}, {1086000000, 250000}, {1086000000, 200000});
  m.header.size = static_cast<std::uint32_t>(m.payload.size());
  const json si = message_to_si_json(m);
  json wire = message_to_json(m);
  EXPECT_DOUBLE_EQ(si["data"]["xpos"].get<double>(), -1.234);
  EXPECT_DOUBLE_EQ(si["data"]["yaw"].get<double>(), kQuarterPi);
  EXPECT_EQ(si["data"]["stall"], 0);
  wire.erase("data");
  json envelope = si;
  envelope.erase("data");
  EXPECT_EQ(envelope, wire);

  // A reply whose struct does not start with its subtype is found through the request's.
  Message reply;
  reply.payload = encode(PowerData{.charge = 120});
  reply.header = make_header(MessageType::kAck, {kPowerCode, 0}, {}, {});
  EXPECT_DOUBLE_EQ(message_to_si_json(reply, kMainPowerReq)["data"]["charge"].get<double>(), 12.0);
}

TEST(SiUnits, ConversionsInvertEachOther) {
  for (const auto& rule : si_field_rules()) {
    for (const WireUnit u : rule.units) {
      for (const double wire : {-648000.0, -1.0, 0.0, 7.0, 12345.0}) {
        EXPECT_NEAR(from_si(u, to_si(u, wire)), wire, 1e-9 * std::max(1.0, std::abs(wire)))
            << rule.wire_struct << "." << rule.field << " " << si_symbol(u);
      }
    }
  }
}

// ---------------------------------------------------------------------------
// The table against the spec

struct SpecField {
  std::string name;
  std::string ctype;
  std::string meaning;
};

std::map<std::string, std::vector<SpecField>> load_spec_units() {
  std::ifstream in(std::string(PLAYERKIT_TEST_DATA_DIR) + "/wire-format-units.tsv");
  std::map<std::string, std::vector<SpecField>> out;
  std::string line;
  while (std::getline(in, line)) {
    if (line.empty() || line[0] == '#') continue;
    std::istringstream row(line);
    std::string wire_struct;
    SpecField f;
    std::getline(row, wire_struct, '\t');
    std::getline(row, f.name, '\t');
    std::getline(row, f.ctype, '\t');
    std::getline(row, f.meaning, '\t');
    out[wire_struct].push_back(f);
  }
  return out;
}

// What each unit is called in the spec's unit column.
std::regex spec_words_for(WireUnit u) {
  switch (u) {
    case WireUnit::kMillimetre: return std::regex(R"(\bmm\b(?!/))");
    case WireUnit::kCentimetre: return std::regex(R"(\bcm\b)");
    case WireUnit::kMillimetrePerSecond: return std::regex(R"(\bmm/s\b)");
    case WireUnit::kHundredthDegree: return std::regex(R"(\b0\.01 deg\b)");
    case WireUnit::kDegree: return std::regex(R"(\bdeg\b(?!/)|\bdegrees\b)");
    case WireUnit::kDegreePerSecond: return std::regex(R"(\bdeg/s\b)");
    case WireUnit::kArcSecond: return std::regex(R"(\barc-seconds\b|\barcsec\b(?!/))");
    case WireUnit::kArcSecondPerSecond: return std::regex(R"(\barcsec/s\b)");
    case WireUnit::kGpsAngle: return std::regex(R"(1/216000 deg|1/60 arc-second)");
    case WireUnit::kDecivolt: return std::regex(R"(\bdecivolts\b)");
    case WireUnit::kTenth: return std::regex(R"(\btimes 10\b)");
    case WireUnit::kMillionth: return std::regex(R"(\btimes 1e6\b)");
    case WireUnit::kPixelPerKilometre: return std::regex(R"(\bpixels per kilometre\b)");
  }
  return std::regex("$^");
}

// Any length, angle, speed, voltage or scale wording.
bool names_a_unit(const std::string& meaning) {
  static const std::regex unit_words(
      R"(\b(mm|cm|deg|degrees|arc-seconds?|arcsec|decivolts|kilometre)\b|\btimes 1(0|e6)\b)");
  return std::regex_search(meaning, unit_words);
}

using FieldKey = std::pair<std::string, std::string>;  // struct, field

// Named a unit in the spec, deliberately left as on the wire (si_units.hpp says why).
const std::set<FieldKey> kKeptOnPurpose{
    {"player_position_speed_prof_req_t", "speed"},  // "driver units, mm/s on P2OS"
    {"player_laser_config_t", "range_res"},         // a multiplier, like the data's range_res
};
// Converted though the spec names its unit only through another field.
const std::set<FieldKey> kUnitByReference{
    {"player_fiducial_item_t", "upose"},  // "uncertainty of the same three" (range mm, bearing deg, orientation deg)
};

// Every struct a message can carry (through the catalog), and the structs nested in them.
std::set<std::string> reachable_structs(const std::map<std::string, std::vector<SpecField>>& spec) {
  std::vector<std::string> todo;
  for (const auto& m : all_messages()) {
    for (const PayloadCodec* c : {m.data, m.command}) {
      if (c) todo.emplace_back(c->wire_name);
    }
    for (const auto& kind : m.requests) {
      for (const PayloadCodec* c : {kind.request, kind.reply}) {
        if (c) todo.emplace_back(c->wire_name);
      }
    }
  }
  std::set<std::string> seen;
  while (!todo.empty()) {
    const std::string name = todo.back();
    todo.pop_back();
    if (!seen.insert(name).second) continue;
    const auto it = spec.find(name);
    if (it == spec.end()) continue;
    for (const auto& f : it->second) {
      if (spec.contains(f.ctype)) todo.push_back(f.ctype);
    }
  }
  return seen;
}

TEST(SiUnitsTable, EveryFieldWithAUnitInTheSpecIsConverted) {
  const auto spec = load_spec_units();
  ASSERT_EQ(spec.size(), 111u) << "tests/data/wire-format-units.tsv not found or incomplete";
  const auto reachable = reachable_structs(spec);

  std::map<FieldKey, const SiFieldRule*> table;
  for (const auto& rule : si_field_rules()) {
    const FieldKey key{std::string(rule.wire_struct), std::string(rule.field)};
    EXPECT_TRUE(table.emplace(key, &rule).second) << "two rules for " << key.first << "." << key.second;
  }

  // A field bears a unit when its text names one or it is a struct with such a field.
  std::map<std::string, bool> struct_bears_unit;
  auto bears_unit = [&](auto&& self, const std::string& wire_struct) -> bool {
    if (const auto it = struct_bears_unit.find(wire_struct); it != struct_bears_unit.end()) return it->second;
    bool any = false;
    for (const auto& f : spec.at(wire_struct)) {
      if (names_a_unit(f.meaning) || (spec.contains(f.ctype) && self(self, f.ctype))) any = true;
    }
    return struct_bears_unit[wire_struct] = any;
  };

  std::size_t checked = 0;
  for (const auto& wire_struct : reachable) {
    ASSERT_TRUE(spec.contains(wire_struct)) << wire_struct << " is not in the spec table";
    for (const auto& f : spec.at(wire_struct)) {
      const FieldKey key{wire_struct, f.name};
      const bool nested_units = spec.contains(f.ctype) && bears_unit(bears_unit, f.ctype);
      const bool unit = names_a_unit(f.meaning) || nested_units;
      const bool in_table = table.contains(key);
      if (kKeptOnPurpose.contains(key)) {
        EXPECT_TRUE(unit) << wire_struct << "." << f.name << " is listed as kept but names no unit";
        EXPECT_FALSE(in_table) << wire_struct << "." << f.name << " is listed as kept but converted";
        continue;
      }
      if (kUnitByReference.contains(key)) {
        EXPECT_TRUE(in_table) << wire_struct << "." << f.name;
        continue;
      }
      EXPECT_EQ(in_table, unit) << wire_struct << "." << f.name << " (\"" << f.meaning << "\") "
                                << (unit ? "carries a unit but has no SI rule" : "has a rule but no unit");
      ++checked;
    }
  }
  EXPECT_GT(checked, 200u);

  for (const auto& rule : si_field_rules()) {
    const std::string wire_struct(rule.wire_struct);
    SCOPED_TRACE(wire_struct + "." + std::string(rule.field));
    EXPECT_TRUE(reachable.contains(wire_struct)) << "no message carries this struct";
    ASSERT_TRUE(spec.contains(wire_struct));
    const auto& fields = spec.at(wire_struct);
    const auto f = std::find_if(fields.begin(), fields.end(), [&](const SpecField& s) { return s.name == rule.field; });
    ASSERT_NE(f, fields.end()) << "no such field in the spec";
    if (rule.rule == SiRule::kNested) {
      EXPECT_EQ(f->ctype, rule.nested_struct);
      continue;
    }
    ASSERT_FALSE(rule.units.empty());
    if (kUnitByReference.contains({wire_struct, f->name})) continue;
    // The spec's wording names every unit the rule applies, and the rule's shape fits.
    for (const WireUnit u : rule.units) {
      EXPECT_TRUE(std::regex_search(f->meaning, spec_words_for(u)))
          << "\"" << f->meaning << "\" does not name the rule's wire unit (converted to " << si_symbol(u) << ")";
    }
    if (rule.rule == SiRule::kLaserRanges) {
      EXPECT_NE(f->meaning.find("times range_res"), std::string::npos);
    }
    if (rule.rule == SiRule::kCovariance) {
      EXPECT_NE(f->meaning.find("3x3 covariance"), std::string::npos);
    }
    if (rule.rule == SiRule::kPerColumn) {
      EXPECT_EQ(rule.units.size(), 3u);
    }
  }
}

TEST(SiUnitsTable, EveryInterfaceWithUnitsHasAGoldenConversion) {
  std::set<std::string> with_units;
  for (const auto& rule : si_field_rules()) with_units.emplace(rule.wire_struct);
  std::set<std::uint16_t> interfaces_with_units;
  for (const auto& m : all_messages()) {
    std::vector<const PayloadCodec*> codecs{m.data, m.command};
    for (const auto& kind : m.requests) {
      codecs.push_back(kind.request);
      codecs.push_back(kind.reply);
    }
    for (const PayloadCodec* c : codecs) {
      if (c && with_units.contains(std::string(c->wire_name))) interfaces_with_units.insert(m.interface);
    }
  }
  std::set<std::uint16_t> covered;
  for (const auto& g : goldens()) covered.insert(g.interface);
  for (const auto code : interfaces_with_units) {
    EXPECT_TRUE(covered.contains(code)) << interface_name(code) << " has units but no golden conversion";
  }
  EXPECT_EQ(interfaces_with_units.size(), 17u);
}

}  // namespace si_units_test
}  // namespace playerkit::protocol
