#include "protocol/si_units.hpp"

#include <numbers>
#include <string>
#include <unordered_map>

#include "protocol/catalog.hpp"
#include "protocol/message_json.hpp"
#include "protocol/payload_json.hpp"

namespace playerkit::protocol {
namespace {

constexpr double kPi = std::numbers::pi;

// value_si = value_wire * numerator / denominator
struct Ratio {
  double numerator = 1;
  double denominator = 1;
};

Ratio ratio_of(WireUnit unit) {
  switch (unit) {
    case WireUnit::kMillimetre:
    case WireUnit::kMillimetrePerSecond: return {1, 1000};
    case WireUnit::kCentimetre: return {1, 100};
    case WireUnit::kHundredthDegree: return {kPi, 18000};
    case WireUnit::kDegree:
    case WireUnit::kDegreePerSecond: return {kPi, 180};
    case WireUnit::kArcSecond:
    case WireUnit::kArcSecondPerSecond: return {kPi, 648000};
    case WireUnit::kGpsAngle: return {1, 216000};
    case WireUnit::kDecivolt:
    case WireUnit::kTenth: return {1, 10};
    case WireUnit::kMillionth: return {1, 1e6};
    case WireUnit::kPixelPerKilometre: return {1, 1000};
  }
  return {};
}

SiFieldRule unit(std::string_view wire_struct, std::string_view field, WireUnit u) {
  return {wire_struct, field, SiRule::kUnit, {u}, {}};
}

SiFieldRule columns(std::string_view wire_struct, std::string_view field, std::vector<WireUnit> units) {
  return {wire_struct, field, SiRule::kPerColumn, std::move(units), {}};
}

SiFieldRule nested(std::string_view wire_struct, std::string_view field, std::string_view inner) {
  return {wire_struct, field, SiRule::kNested, {}, inner};
}

using enum WireUnit;

// x mm, y mm, yaw degrees: the pose arrays of every geometry reply.
const std::vector<WireUnit> kPlanarPose{kMillimetre, kMillimetre, kDegree};

std::vector<SiFieldRule> build_rules() {
  std::vector<SiFieldRule> rules{
      unit("player_power_data_t", "charge", kDecivolt),

      columns("player_position_geom_t", "pose", kPlanarPose),
      unit("player_position_geom_t", "size", kMillimetre),
      unit("player_position_set_odom_req_t", "x", kMillimetre),
      unit("player_position_set_odom_req_t", "y", kMillimetre),
      unit("player_position_set_odom_req_t", "theta", kDegree),

      unit("player_sonar_data_t", "ranges", kMillimetre),
      columns("player_sonar_geom_t", "poses", kPlanarPose),

      unit("player_laser_data_t", "min_angle", kHundredthDegree),
      unit("player_laser_data_t", "max_angle", kHundredthDegree),
      unit("player_laser_data_t", "resolution", kHundredthDegree),
      {"player_laser_data_t", "ranges", SiRule::kLaserRanges, {kMillimetre}, {}},
      columns("player_laser_geom_t", "pose", kPlanarPose),
      unit("player_laser_geom_t", "size", kMillimetre),
      unit("player_laser_config_t", "min_angle", kHundredthDegree),
      unit("player_laser_config_t", "max_angle", kHundredthDegree),
      unit("player_laser_config_t", "resolution", kHundredthDegree),

      nested("player_blobfinder_data_t", "blobs", "player_blobfinder_blob_elt_t"),
      unit("player_blobfinder_blob_elt_t", "range", kMillimetre),

      nested("player_fiducial_data_t", "fiducials", "player_fiducial_item_t"),
      columns("player_fiducial_item_t", "pose", {kMillimetre, kDegree, kDegree}),
      columns("player_fiducial_item_t", "upose", {kMillimetre, kDegree, kDegree}),
      columns("player_fiducial_geom_t", "pose", kPlanarPose),
      unit("player_fiducial_geom_t", "size", kMillimetre),
      unit("player_fiducial_geom_t", "fiducial_size", kMillimetre),
      unit("player_fiducial_fov_t", "min_range", kMillimetre),
      unit("player_fiducial_fov_t", "max_range", kMillimetre),
      unit("player_fiducial_fov_t", "view_angle", kDegree),

      unit("player_gps_data_t", "latitude", kGpsAngle),
      unit("player_gps_data_t", "longitude", kGpsAngle),
      unit("player_gps_data_t", "altitude", kMillimetre),
      unit("player_gps_data_t", "utm_e", kCentimetre),
      unit("player_gps_data_t", "utm_n", kCentimetre),
      unit("player_gps_data_t", "hdop", kTenth),
      unit("player_gps_data_t", "err_horz", kMillimetre),
      unit("player_gps_data_t", "err_vert", kMillimetre),

      nested("player_bumper_geom_t", "bumper_def", "player_bumper_define_t"),
      unit("player_bumper_define_t", "x_offset", kMillimetre),
      unit("player_bumper_define_t", "y_offset", kMillimetre),
      unit("player_bumper_define_t", "th_offset", kDegree),
      unit("player_bumper_define_t", "length", kMillimetre),
      unit("player_bumper_define_t", "radius", kMillimetre),

      unit("idarrx_t", "range", kMillimetre),
      nested("player_idarturret_reply_t", "rx", "idarrx_t"),

      unit("player_descartes_config_t", "speed", kMillimetrePerSecond),
      unit("player_descartes_config_t", "heading", kDegree),
      unit("player_descartes_config_t", "distance", kMillimetre),
      unit("player_descartes_data_t", "xpos", kMillimetre),
      unit("player_descartes_data_t", "ypos", kMillimetre),
      unit("player_descartes_data_t", "theta", kDegree),

      unit("player_ir_data_t", "ranges", kMillimetre),
      columns("player_ir_pose_t", "poses", kPlanarPose),
      nested("player_ir_pose_req_t", "poses", "player_ir_pose_t"),

      nested("player_localize_data_t", "hypoths", "player_localize_hypoth_t"),
      columns("player_localize_hypoth_t", "mean", {kMillimetre, kMillimetre, kArcSecond}),
      {"player_localize_hypoth_t", "cov", SiRule::kCovariance, {kMillimetre, kMillimetre, kArcSecond}, {}},
      unit("player_localize_hypoth_t", "alpha", kMillionth),
      columns("player_localize_set_pose_t", "mean", {kMillimetre, kMillimetre, kArcSecond}),
      {"player_localize_set_pose_t", "cov", SiRule::kCovariance, {kMillimetre, kMillimetre, kArcSecond}, {}},
      unit("player_localize_map_info_t", "scale", kPixelPerKilometre),

      unit("player_nomad_data_t", "x", kMillimetre),
      unit("player_nomad_data_t", "y", kMillimetre),
      unit("player_nomad_data_t", "a", kDegree),
      unit("player_nomad_data_t", "sonar", kMillimetre),
      unit("player_nomad_data_t", "ir", kMillimetre),
  };

  // Data and command share their layout and units in position, position3d, ptz and truth.
  for (std::string_view s : {"player_position_data_t", "player_position_cmd_t"}) {
    rules.push_back(unit(s, "xpos", kMillimetre));
    rules.push_back(unit(s, "ypos", kMillimetre));
    rules.push_back(unit(s, "yaw", kDegree));
    rules.push_back(unit(s, "xspeed", kMillimetrePerSecond));
    rules.push_back(unit(s, "yspeed", kMillimetrePerSecond));
    rules.push_back(unit(s, "yawspeed", kDegreePerSecond));
  }
  for (std::string_view s : {"player_position3d_data_t", "player_position3d_cmd_t"}) {
    for (std::string_view f : {"xpos", "ypos", "zpos"}) rules.push_back(unit(s, f, kMillimetre));
    for (std::string_view f : {"roll", "pitch", "yaw"}) rules.push_back(unit(s, f, kArcSecond));
    for (std::string_view f : {"xspeed", "yspeed", "zspeed"}) rules.push_back(unit(s, f, kMillimetrePerSecond));
    for (std::string_view f : {"rollspeed", "pitchspeed", "yawspeed"}) {
      rules.push_back(unit(s, f, kArcSecondPerSecond));
    }
  }
  for (std::string_view s : {"player_ptz_data_t", "player_ptz_cmd_t"}) {
    for (std::string_view f : {"pan", "tilt", "zoom"}) rules.push_back(unit(s, f, kDegree));
    for (std::string_view f : {"panspeed", "tiltspeed"}) rules.push_back(unit(s, f, kDegreePerSecond));
  }
  for (std::string_view s : {"player_truth_data_t", "player_truth_pose_t"}) {
    rules.push_back(unit(s, "px", kMillimetre));
    rules.push_back(unit(s, "py", kMillimetre));
    rules.push_back(unit(s, "pa", kDegree));
  }
  return rules;
}

const std::vector<SiFieldRule>& rules() {
  static const std::vector<SiFieldRule> table = build_rules();
  return table;
}

using RulesByStruct = std::unordered_map<std::string_view, std::vector<const SiFieldRule*>>;

const RulesByStruct& rules_by_struct() {
  static const RulesByStruct index = [] {
    RulesByStruct out;
    for (const auto& r : rules()) out[r.wire_struct].push_back(&r);
    return out;
  }();
  return index;
}

void convert_struct(std::string_view wire_struct, nlohmann::json& object);

// Every number at any depth of value.
void apply_unit(nlohmann::json& value, WireUnit u) {
  if (value.is_number()) {
    value = to_si(u, value.get<double>());
  } else if (value.is_array()) {
    for (auto& element : value) apply_unit(element, u);
  }
}

void apply_columns(nlohmann::json& value, const std::vector<WireUnit>& units) {
  if (!value.is_array()) return;
  for (std::size_t i = 0; i < value.size(); ++i) {
    auto& element = value[i];
    if (element.is_array()) {
      apply_columns(element, units);
    } else if (element.is_number() && i < units.size()) {
      element = to_si(units[i], element.get<double>());
    }
  }
}

void apply_covariance(nlohmann::json& matrix, const std::vector<WireUnit>& axes) {
  if (!matrix.is_array()) return;
  for (std::size_t r = 0; r < matrix.size() && r < axes.size(); ++r) {
    auto& row = matrix[r];
    if (!row.is_array()) continue;
    for (std::size_t c = 0; c < row.size() && c < axes.size(); ++c) {
      if (row[c].is_number()) row[c] = to_si(axes[c], to_si(axes[r], row[c].get<double>()));
    }
  }
}

void apply_laser_ranges(nlohmann::json& ranges, const nlohmann::json& owner) {
  double range_res = 1;
  if (const auto it = owner.find("range_res"); it != owner.end() && it->is_number()) {
    // A driver that leaves range_res unset means millimetres; times 0 would erase the scan.
    if (it->get<double>() != 0) range_res = it->get<double>();
  }
  if (!ranges.is_array()) return;
  for (auto& r : ranges) {
    if (r.is_number()) r = to_si(WireUnit::kMillimetre, r.get<double>() * range_res);
  }
}

void apply_rule(const SiFieldRule& rule, nlohmann::json& value, const nlohmann::json& owner) {
  switch (rule.rule) {
    case SiRule::kUnit: apply_unit(value, rule.units.front()); break;
    case SiRule::kPerColumn: apply_columns(value, rule.units); break;
    case SiRule::kCovariance: apply_covariance(value, rule.units); break;
    case SiRule::kLaserRanges: apply_laser_ranges(value, owner); break;
    case SiRule::kNested:
      if (value.is_object()) {
        convert_struct(rule.nested_struct, value);
      } else if (value.is_array()) {
        for (auto& element : value) convert_struct(rule.nested_struct, element);
      }
      break;
  }
}

void convert_struct(std::string_view wire_struct, nlohmann::json& object) {
  if (!object.is_object()) return;
  const auto it = rules_by_struct().find(wire_struct);
  if (it == rules_by_struct().end()) return;
  // Laser ranges read range_res from their owner; no rule converts range_res, so
  // the order of the rules does not matter.
  for (const SiFieldRule* rule : it->second) {
    const auto field = object.find(std::string(rule->field));
    if (field != object.end()) apply_rule(*rule, *field, object);
  }
}

// The struct payload_to_json chose for this payload, or nullptr (raw, empty, subtype only).
const PayloadCodec* codec_for(std::uint16_t interface, MessageType type, std::span<const std::uint8_t> payload,
                              std::optional<std::uint16_t> request_subtype) {
  const auto* messages = find_messages(interface);
  if (!messages) return nullptr;
  switch (type) {
    case MessageType::kData: return messages->data;
    case MessageType::kCommand: return messages->command;
    case MessageType::kRequest: {
      const RequestKind* kind = request_kind_of(interface, payload);
      if (!kind || payload.size() <= messages->subtype_size) return nullptr;
      return kind->request;
    }
    default: {
      if (!is_reply(type) || payload.empty()) return nullptr;
      const RequestKind* kind =
          request_subtype ? messages->find_request(*request_subtype) : request_kind_of(interface, payload);
      return kind ? kind->reply : nullptr;
    }
  }
}

void convert_payload_json(std::uint16_t interface, MessageType type, std::span<const std::uint8_t> payload,
                          std::optional<std::uint16_t> request_subtype, nlohmann::json& j) {
  if (is_raw_payload_json(j)) return;
  if (const PayloadCodec* codec = codec_for(interface, type, payload, request_subtype)) {
    convert_struct(codec->wire_name, j);
  }
}

}  // namespace

double to_si(WireUnit u, double wire_value) {
  const Ratio r = ratio_of(u);
  return wire_value * r.numerator / r.denominator;
}

double from_si(WireUnit u, double value_in_si) {
  const Ratio r = ratio_of(u);
  return value_in_si * r.denominator / r.numerator;
}

std::string_view si_symbol(WireUnit u) {
  switch (u) {
    case kMillimetre:
    case kCentimetre: return "m";
    case kMillimetrePerSecond: return "m/s";
    case kHundredthDegree:
    case kDegree:
    case kArcSecond: return "rad";
    case kDegreePerSecond:
    case kArcSecondPerSecond: return "rad/s";
    case kGpsAngle: return "deg";
    case kDecivolt: return "V";
    case kTenth:
    case kMillionth: return "1";
    case kPixelPerKilometre: return "px/m";
  }
  return "?";
}

std::span<const SiFieldRule> si_field_rules() { return rules(); }

nlohmann::json payload_to_si_json(std::uint16_t interface, MessageType type,
                                  std::span<const std::uint8_t> payload,
                                  std::optional<std::uint16_t> request_subtype) {
  nlohmann::json j = payload_to_json(interface, type, payload, request_subtype);
  convert_payload_json(interface, type, payload, request_subtype, j);
  return j;
}

nlohmann::json message_to_si_json(const Message& message, std::optional<std::uint16_t> request_subtype) {
  nlohmann::json j = message_to_json(message, request_subtype);
  convert_payload_json(message.header.device, message.type(), message.payload, request_subtype, j["data"]);
  return j;
}

}  // namespace playerkit::protocol
