#include "families/khepera/driver/khepera_options.hpp"

#include <array>
#include <cmath>
#include <numbers>

#include "core/option_reader.hpp"
#include "core/robot_option.hpp"
#include "links/port_option.hpp"

namespace playerkit::drivers::khepera {

namespace {

using core::OptionSpec;
using core::OptionType;

constexpr int kMaxIrSensors = 32;  // player_ir_data_t holds 32
constexpr std::size_t kDefaultIrCount = 8;

constexpr std::array<std::string_view, 2> kFamilyDrivers{kPositionDriver, kIrDriver};

// khepera.md §3.4: x mm, y mm, heading degrees.
constexpr std::array<std::array<double, 3>, kDefaultIrCount> kDefaultIrPoses{{
    {10, 24, 90}, {19, 17, 45}, {25, 6, 0}, {25, -6, 0}, {19, -17, -45}, {10, -24, -90}, {-24, -10, 180},
    {-24, 10, 180}}};

double radians(double degrees) { return degrees * std::numbers::pi / 180.0; }

std::vector<double> default_pose_elements() {
  std::vector<double> elements;
  for (const auto& pose : kDefaultIrPoses) elements.insert(elements.end(), pose.begin(), pose.end());
  return elements;
}

core::OptionSchema make_robot_schema() {
  return {
      links::port_option(std::string(kDefaultKheperaPort))
          .doc("serial port of the robot (38400 baud), or tcp:HOST:PORT; may be written on either khepera section"),
      OptionSpec::number("scale_factor", 10.0, 0.001, 1000.0)
          .aliases({"scale"})
          .doc("geometry (GET_GEOM, IR poses) and IR ranges are reported multiplied by this, as in 1.5, so the "
               "tiny robot shows at a useful size; odometry is never scaled (the manual's name: scale)"),
      OptionSpec::number("reply_timeout", 0.2, 0.01, 5.0)
          .unit("s")
          .doc("how long each command waits for its reply, asked three times before the robot counts as lost "
               "(1.5 read once after 10 ms) (playerkit)"),
      OptionSpec::number("cycle_time", 0.05, 0.01, 1.0)
          .unit("s")
          .doc("one round of speed, proximity, counters and speeds every so long (1.5: as fast as the line "
               "allowed, about 40 ms) (playerkit)"),
      OptionSpec::number("connect_timeout", 2.0, 0.1, 600.0)
          .unit("s")
          .doc("how long setup waits for the robot's first answer (playerkit)"),
  };
}

core::OptionSchema make_position_schema() {
  core::OptionSchema schema = khepera_robot_schema();
  schema.add(OptionSpec::number("encoder_res", 1.0 / 12.0, 1e-6, 100.0)
                 .unit("mm/pulse")
                 .doc("distance a wheel travels per encoder pulse (Khepera I: 12 pulses a millimetre)"));
  schema.add(OptionSpec::tuple("pose", {OptionType::number, OptionType::number, OptionType::number}, {0, 0, 0})
                 .unit("mm mm deg")
                 .doc("the body's centre in the robot's frame, for GET_GEOM (reported x scale_factor)"));
  schema.add(OptionSpec::tuple("size", {OptionType::number, OptionType::number}, {57, 57})
                 .unit("mm mm")
                 .doc("length and width of the body, for GET_GEOM (reported x scale_factor); the length is also the "
                      "distance between the wheels, as in 1.5"));
  return schema;
}

core::OptionSchema make_ir_schema() {
  core::OptionSchema schema = khepera_robot_schema();
  schema.add(OptionSpec::integer("pose_count", static_cast<int>(kDefaultIrCount), 1, kMaxIrSensors)
                 .doc("number of IR sensors: the values N answers with"));
  schema.add(OptionSpec::tuple("poses", std::vector<OptionType>(3 * kDefaultIrCount, OptionType::number),
                               default_pose_elements())
                 .unit("mm mm deg ...")
                 .doc("x, y, heading of each sensor in turn (reported x scale_factor); needed when pose_count is "
                      "not 8"));
  schema.add(OptionSpec::tuple("ir_calib_a", std::vector<OptionType>(kDefaultIrCount, OptionType::number),
                               std::vector<double>(kDefaultIrCount, 64.158))
                 .doc("per sensor: range in mm = scale_factor x a x reading^b"));
  schema.add(OptionSpec::tuple("ir_calib_b", std::vector<OptionType>(kDefaultIrCount, OptionType::number),
                               std::vector<double>(kDefaultIrCount, -0.1238))
                 .doc("per sensor: the exponent b of the range's power law"));
  return schema;
}

template <class Read>
auto robot_value(const core::DriverContext& context, std::string_view name, Read read) {
  return core::robot_value(context, kFamilyDrivers, name,
                           [&](const config::Section& section, const std::string& driver) {
                             return read(core::OptionReader(section, driver, khepera_robot_schema()), name);
                           });
}

std::chrono::milliseconds seconds_option(const core::DriverContext& context, std::string_view name) {
  const auto value = robot_value(
      context, name, [](const core::OptionReader& options, std::string_view n) { return options.seconds(n); });
  const double fallback = khepera_robot_schema().find(name)->number_fallback();
  return value.value_or(std::chrono::milliseconds(std::lround(fallback * 1000.0)));
}

}  // namespace

const core::OptionSchema& khepera_robot_schema() {
  static const core::OptionSchema schema = make_robot_schema();
  return schema;
}

const core::OptionSchema& khepera_position_schema() {
  static const core::OptionSchema schema = make_position_schema();
  return schema;
}

const core::OptionSchema& khepera_ir_schema() {
  static const core::OptionSchema schema = make_ir_schema();
  return schema;
}

std::vector<KheperaIrSensor> default_ir_sensors() {
  std::vector<KheperaIrSensor> sensors;
  for (const auto& pose : kDefaultIrPoses) sensors.push_back({{pose[0], pose[1], radians(pose[2])}, {}});
  return sensors;
}

KheperaRobotOptions read_khepera_robot_options(const core::DriverContext& context) {
  KheperaRobotOptions options;
  options.port = robot_value(context, "port", [](const core::OptionReader& reader, std::string_view n) {
                   return reader.text(n);
                 }).value_or(std::string(kDefaultKheperaPort));
  options.scale = robot_value(context, "scale_factor", [](const core::OptionReader& reader, std::string_view n) {
                    return reader.number(n);
                  }).value_or(options.scale);
  options.reply_timeout = seconds_option(context, "reply_timeout");
  options.cycle = seconds_option(context, "cycle_time");
  options.connect_timeout = seconds_option(context, "connect_timeout");
  return options;
}

KheperaPositionOptions read_khepera_position_options(const core::DriverContext& context) {
  const core::OptionReader options(context.section, std::string(kPositionDriver), khepera_position_schema());
  KheperaPositionOptions position;
  position.wheels.millimetres_per_pulse = options.number("encoder_res");
  position.pose = {options.element("pose", 0), options.element("pose", 1), radians(options.element("pose", 2))};
  position.length_mm = options.element("size", 0);
  position.width_mm = options.element("size", 1);
  if (!(position.length_mm > 0.0)) options.fail({"size"}, "must be positive: its x is the distance between the wheels");
  position.wheels.wheelbase_mm = position.length_mm;
  return position;
}

KheperaIrOptions read_khepera_ir_options(const core::DriverContext& context) {
  const core::OptionReader options(context.section, std::string(kIrDriver), khepera_ir_schema());
  const auto count = static_cast<std::size_t>(options.integer("pose_count"));
  const config::Section& section = context.section;
  if (count != kDefaultIrCount && section.tuple_size("poses") < 3 * count) {
    options.fail({"poses"}, "needs x, y and heading for each of the " + std::to_string(count) +
                                " sensors of pose_count (" + std::to_string(3 * count) + " numbers)");
  }
  std::vector<KheperaIrSensor> defaults = default_ir_sensors();
  KheperaIrOptions ir;
  for (std::size_t i = 0; i < count; ++i) {
    KheperaIrSensor sensor = i < defaults.size() ? defaults[i] : KheperaIrSensor{};
    if (section.has("poses")) {
      sensor.pose = {section.read_tuple_float("poses", 3 * i, sensor.pose.x),
                     section.read_tuple_float("poses", 3 * i + 1, sensor.pose.y),
                     radians(section.read_tuple_float("poses", 3 * i + 2, sensor.pose.yaw * 180.0 / std::numbers::pi))};
    }
    sensor.calibration.a = section.read_tuple_float("ir_calib_a", i, sensor.calibration.a);
    sensor.calibration.b = section.read_tuple_float("ir_calib_b", i, sensor.calibration.b);
    if (!(sensor.calibration.a > 0.0)) options.fail({"ir_calib_a"}, "must be positive", i);
    if (!(sensor.calibration.b < 0.0)) options.fail({"ir_calib_b"}, "must be negative: nearer is brighter", i);
    ir.sensors.push_back(sensor);
  }
  return ir;
}

std::string connection_key(const KheperaRobotOptions& options) { return "khepera " + options.port; }

}  // namespace playerkit::drivers::khepera
