#include "log/carmen_log_parser.hpp"

#include <charconv>
#include <cmath>
#include <limits>
#include <optional>
#include <string>
#include <string_view>
#include <system_error>

#include "log/text_log_fields.hpp"
#include "text/decimal_number.hpp"
#include "text/printable.hpp"

namespace playerkit::log {
namespace {


// What a field is called in an error message ("odometry theta", "range 17"),
// put into a string only when there is an error: a 361-reading line costs none.
struct FieldName {
  FieldName(std::string_view field, std::string_view field_part = {},
            std::optional<std::size_t> field_index = std::nullopt)
      : what(field), part(field_part), index(field_index) {}
  FieldName(const char* field) : FieldName(std::string_view(field)) {}

  std::string str() const {
    std::string name(what);
    if (!part.empty()) name.append(" ").append(part);
    if (index) name.append(" ").append(std::to_string(*index));
    return name;
  }

  std::string_view what;
  std::string_view part;
  std::optional<std::size_t> index;
};

// The fields of one known record, read left to right.
class FieldCursor {
 public:
  explicit FieldCursor(const LineFields& fields) : fields_(fields) {}

  std::size_t position() const { return next_; }
  std::size_t remaining() const { return fields_.size() - next_; }

  double number(const FieldName& name) {
    if (next_ >= fields_.size()) fields_.at(next_, name.str());
    std::string_view text = fields_.text_view(next_);
    std::string_view digits = text;
    if (digits.size() > 1 && digits.front() == '+' && digits[1] != '-') digits.remove_prefix(1);
    double value = 0;
    const auto parsed = text::decimal_from_chars(digits.data(), digits.data() + digits.size(), value);
    if (parsed.ec != std::errc{} || parsed.ptr != digits.data() + digits.size() ||
        !std::isfinite(value)) {
      fields_.fail(next_, name.str() + ": expected a number, got " + quoted_excerpt(text));
    }
    ++next_;
    return value;
  }

  int whole(const std::string& what) {
    const int value = fields_.integer<int>(next_, what);
    ++next_;
    return value;
  }

  // A count of `count_what` followed by that many fields and then exactly
  // `tail` more (or, when tail_max > tail, between tail and tail_max more).
  std::size_t count(const std::string& count_what, const std::string& tail_what, std::size_t tail,
                    std::size_t tail_max = 0) {
    if (tail_max < tail) tail_max = tail;
    const std::size_t at = next_;
    const int value = whole("number of " + count_what);
    if (value < 0) fields_.fail(at, "number of " + count_what + " is negative: " + std::to_string(value));
    const auto announced = static_cast<std::size_t>(value);
    const std::size_t left = remaining();
    if (left < announced + tail || left - announced > tail_max) {
      const std::string expected =
          tail == tail_max                                   ? std::to_string(tail)
          : tail_max == std::numeric_limits<std::size_t>::max() ? "at least " + std::to_string(tail)
                                                             : std::to_string(tail) + " or " + std::to_string(tail_max);
      fields_.fail(at, std::to_string(announced) + " " + count_what + " announced, but " +
                           std::to_string(left) + " fields follow (expected " +
                           std::to_string(announced) + " " + count_what + " then " + expected +
                           ": " + tail_what + ")");
    }
    return announced;
  }

  std::vector<double> numbers(std::size_t n, std::string_view what) {
    std::vector<double> values;
    values.reserve(n);
    for (std::size_t i = 0; i < n; ++i) values.push_back(number(FieldName(what, {}, i)));
    return values;
  }

  CarmenPose pose(std::string_view what) {
    CarmenPose pose;
    pose.x = number(FieldName(what, "x"));
    pose.y = number(FieldName(what, "y"));
    pose.theta = number(FieldName(what, "theta"));
    return pose;
  }

  CarmenStamp stamp() {
    CarmenStamp stamp;
    stamp.ipc_timestamp = number("ipc timestamp");
    fields_.at(next_, "ipc host name");
    stamp.host = fields_.text(next_++);
    stamp.logger_timestamp = number("logger timestamp");
    return stamp;
  }

  std::string text(const std::string& what) {
    fields_.at(next_, what);
    return fields_.text(next_++);
  }

  void end() const { fields_.expect_end(next_, "the logger timestamp"); }

 private:
  const LineFields& fields_;
  std::size_t next_ = 1;  // past the keyword
};

constexpr std::string_view kStampWhat = "ipc timestamp, host, logger timestamp";

CarmenParam parse_param(const LineFields& fields) {
  // The value is everything between the name and the last three fields: CARMEN
  // writes it with "%s", spaces and all.
  FieldCursor cursor(fields);
  CarmenParam param;
  param.name = cursor.text("parameter name");
  if (fields.size() == 5) {
    // `PARAM name value host logger_timestamp`: the short stamp of Radish's
    // corrected logs (`PARAM robot_use_laser on nohost 0`). A full stamp needs
    // six fields with a value, and CARMEN writes no empty values.
    param.value = cursor.text("parameter value");
    param.stamp.host = cursor.text("host");
    param.stamp.logger_timestamp = cursor.number("logger timestamp");
    param.stamp.ipc_timestamp = param.stamp.logger_timestamp;
    cursor.end();
    return param;
  }
  if (cursor.remaining() < 3) {
    fields.fail_at_end("line ends before the " + std::string(kStampWhat) + " of PARAM " + param.name);
  }
  while (cursor.remaining() > 3) {
    if (!param.value.empty()) param.value += ' ';
    param.value += cursor.text("parameter value");
  }
  param.stamp = cursor.stamp();
  cursor.end();
  return param;
}

CarmenOdometry parse_odometry(const LineFields& fields) {
  FieldCursor cursor(fields);
  CarmenOdometry odometry;
  odometry.pose = cursor.pose("odometry");
  odometry.tv = cursor.number("tv");
  odometry.rv = cursor.number("rv");
  odometry.acceleration = cursor.number("accel");
  odometry.stamp = cursor.stamp();
  cursor.end();
  return odometry;
}

CarmenTruePos parse_true_pos(const LineFields& fields) {
  FieldCursor cursor(fields);
  CarmenTruePos true_pos;
  true_pos.true_pose = cursor.pose("true pose");
  true_pos.odometry_pose = cursor.pose("odometry");
  true_pos.stamp = cursor.stamp();
  cursor.end();
  return true_pos;
}

CarmenLaserConfig parse_config(FieldCursor& cursor) {
  CarmenLaserConfig config;
  config.laser_type = cursor.whole("laser_type");
  config.start_angle = cursor.number("start_angle");
  config.fov = cursor.number("field_of_view");
  config.angular_resolution = cursor.number("angular_resolution");
  config.maximum_range = cursor.number("maximum_range");
  config.accuracy = cursor.number("accuracy");
  config.remission_mode = cursor.whole("remission_mode");
  return config;
}

CarmenLaser parse_laser(const LineFields& fields, CarmenLaserKind kind) {
  FieldCursor cursor(fields);
  CarmenLaser laser;
  laser.kind = kind;
  switch (kind) {
    case CarmenLaserKind::kFlaser:
    case CarmenLaserKind::kRlaser: {
      const auto n = cursor.count("readings", "laser pose, odometry pose, " + std::string(kStampWhat), 9);
      laser.ranges = cursor.numbers(n, "range");
      laser.laser_pose = cursor.pose("laser pose");
      laser.robot_pose = cursor.pose("odometry");
      laser.config = guess_carmen_laser_config(n);
      laser.config_guessed = true;
      break;
    }
    case CarmenLaserKind::kLaser3:
    case CarmenLaserKind::kLaser4: {
      const auto n = cursor.count("readings", std::string(kStampWhat), 3);
      laser.ranges = cursor.numbers(n, "range");
      laser.config = guess_carmen_laser_config(n);
      laser.config_guessed = true;
      break;
    }
    case CarmenLaserKind::kRawLaser1:
    case CarmenLaserKind::kRawLaser2:
    case CarmenLaserKind::kRawLaser3:
    case CarmenLaserKind::kRawLaser4: {
      laser.config = parse_config(cursor);
      const std::string tail = "num_remissions, remissions, " + std::string(kStampWhat);
      const auto n = cursor.count("readings", tail, 4, std::numeric_limits<std::size_t>::max());
      laser.ranges = cursor.numbers(n, "range");
      const auto m = cursor.count("remissions", std::string(kStampWhat), 3);
      laser.remissions = cursor.numbers(m, "remission");
      break;
    }
    case CarmenLaserKind::kRobotLaser1:
    case CarmenLaserKind::kRobotLaser2: {
      laser.config = parse_config(cursor);
      const std::string motion = "laser pose, robot pose, tv, rv, forward_safety_dist, "
                                 "side_safety_dist, [turn_axis], " + std::string(kStampWhat);
      const auto n = cursor.count("readings", "num_remissions, remissions, " + motion, 14,
                                  std::numeric_limits<std::size_t>::max());
      laser.ranges = cursor.numbers(n, "range");
      const auto m = cursor.count("remissions", motion, 13, 14);
      laser.remissions = cursor.numbers(m, "remission");
      laser.laser_pose = cursor.pose("laser pose");
      laser.robot_pose = cursor.pose("robot pose");
      CarmenLaserMotion moving;
      moving.tv = cursor.number("tv");
      moving.rv = cursor.number("rv");
      moving.forward_safety_dist = cursor.number("forward_safety_dist");
      moving.side_safety_dist = cursor.number("side_safety_dist");
      if (cursor.remaining() > 3) moving.turn_axis = cursor.number("turn_axis");
      laser.motion = moving;
      break;
    }
  }
  laser.stamp = cursor.stamp();
  cursor.end();
  return laser;
}

}  // namespace

bool is_carmen_record_keyword(std::string_view keyword) {
  return keyword == "PARAM" || keyword == "ODOM" || keyword == "TRUEPOS" ||
         carmen_laser_kind(keyword).has_value();
}

CarmenLine parse_carmen_line(std::string_view text, std::string_view file, int line_number) {
  const LineFields fields(text, file, line_number);
  if (fields.size() == 0 || fields.text_view(0).front() == '#') return CarmenBlankLine{};
  const std::string_view keyword = fields.text_view(0);
  if (keyword == "PARAM") return CarmenRecord{parse_param(fields)};
  if (keyword == "ODOM") return CarmenRecord{parse_odometry(fields)};
  if (keyword == "TRUEPOS") return CarmenRecord{parse_true_pos(fields)};
  if (const auto kind = carmen_laser_kind(keyword)) return CarmenRecord{parse_laser(fields, *kind)};
  return CarmenUnknownLine{std::string(keyword)};
}

}  // namespace playerkit::log
