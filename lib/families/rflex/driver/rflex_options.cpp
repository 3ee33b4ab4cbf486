#include "families/rflex/driver/rflex_options.hpp"

#include <climits>
#include <cmath>
#include <span>

#include "core/option_reader.hpp"
#include "core/robot_option.hpp"
#include "links/port_option.hpp"

namespace playerkit::drivers::rflex {

namespace {

using core::OptionSpec;
using core::OptionType;

// The options every rflex section takes.
core::OptionSchema link_schema() {
  return {
      links::port_option(std::string(kDefaultRflexPort))
          .aliases({"rflex_serial_port"})
          .doc("serial port of the RFLEX controller, or tcp:HOST:PORT; on any one rflex section of the robot "
               "(1.5's name rflex_serial_port too)"),
      OptionSpec::integer("rflex_done", 0, INT_MIN, INT_MAX)
          .doc("accepted for 1.5's files, which needed 1 on the last rflex section or hung; nothing waits for it"),
      OptionSpec::number("connect_timeout", 3.0, 0.1, 600.0)
          .unit("s")
          .doc("how long the first subscription waits for the controller's first report (playerkit)"),
      OptionSpec::number("report_timeout", 1.0, 0.2, 60.0)
          .unit("s")
          .doc("no packet for this long: the robot counts as gone and is sought again (playerkit)"),
  };
}

// A list of numbers of any length: [a b c ...].
OptionSpec number_list(std::string name) { return OptionSpec::tuple(std::move(name), {}, {}); }

core::OptionSchema make_schema(RflexRole role) {
  core::OptionSchema schema = link_schema();
  switch (role) {
    case RflexRole::position:
      schema.add(OptionSpec::number("mm_length", 0.5, 0.0, 1e5).unit("mm").doc("body length, for GET_GEOM"));
      schema.add(OptionSpec::number("mm_width", 0.5, 0.0, 1e5).unit("mm").doc("body width, for GET_GEOM"));
      schema.add(OptionSpec::number("odo_distance_conversion", 103.0, 1e-6, 1e9)
                     .doc("controller distance units per mm (B21r 103, ATRV-Jr 90.81; 1.5's default 0 divided by zero)"));
      schema.add(OptionSpec::number("odo_angle_conversion", 35000.0, 1e-6, 1e12)
                     .doc("controller bearing units per radian (B21r 35000, ATRV-Jr 37000; 1.5's default 0 divided by zero)"));
      schema.add(OptionSpec::number("default_trans_acceleration", 0.1, 0.0, 1e6)
                     .unit("mm/s²")
                     .doc("translational acceleration sent with every velocity"));
      schema.add(OptionSpec::number("default_rot_acceleration", 0.1, 0.0, 1e3)
                     .unit("rad/s²")
                     .doc("rotational acceleration, sent at start-up"));
      schema.add(OptionSpec::integer("rflex_joystick", 0, INT_MIN, INT_MAX)
                     .doc("non-zero: poll the robot's joystick; with its button held it drives"));
      schema.add(OptionSpec::number("rflex_joy_pos_ratio", 0.0, -1e6, 1e6).doc("joystick y to mm/s"));
      schema.add(OptionSpec::number("rflex_joy_ang_ratio", 0.0, -1e6, 1e6).doc("joystick x to rad/s"));
      break;
    case RflexRole::sonar:
      schema.add(OptionSpec::number("range_distance_conversion", 1.476, 1e-6, 1e6)
                     .doc("sonar units per mm (the B21r's; 1.5's default was 1)"));
      schema.add(OptionSpec::integer("max_num_sonars", 64, 1, 256).doc("sonar ids the controller may report (16 per board)"));
      schema.add(OptionSpec::integer("num_sonars", 24, 0, 64).doc("transducers reported, in bank order"));
      schema.add(OptionSpec::integer("sonar_age", 1, 1, 64).doc("each range is the least of this many last echoes"));
      schema.add(OptionSpec::integer("num_sonar_banks", 8, 0, 16).doc("sonar boards"));
      schema.add(OptionSpec::integer("num_sonars_possible_per_bank", 16, 1, 256).doc("ids per board"));
      schema.add(number_list("num_sonars_in_bank").shown_default("[8 8 8 8 8 8 8 8]").doc("transducers on each board"));
      schema.add(OptionSpec::integer("sonar_echo_delay", 3000, 0, INT_MAX).unit("µs").doc("SONAR_RUN echo delay"));
      schema.add(OptionSpec::integer("sonar_ping_delay", 0, 0, INT_MAX).unit("µs").doc("SONAR_RUN ping delay"));
      schema.add(OptionSpec::integer("sonar_set_delay", 0, 0, INT_MAX).unit("µs").doc("SONAR_RUN set delay"));
      schema.add(number_list("mmrad_sonar_poses")
                     .doc("three numbers per transducer, in sonar_pose_order (1.5 read theta rad, x mm, y mm)"));
      schema.add(OptionSpec::word("sonar_pose_order", "theta_x_y", {"theta_x_y", "x_y_theta"})
                     .doc("how mmrad_sonar_poses is written: theta_x_y as 1.5 read it (its B21r file), x_y_theta "
                          "as the manual says (its ATRV-Jr file) (playerkit)"));
      break;
    case RflexRole::ir:
      schema.add(OptionSpec::integer("pose_count", 8, 0, 32).doc("IR sensors (the sum of rflex_banks when given)"));
      schema.add(OptionSpec::integer("rflex_base_bank", 0, 0, 255).doc("first IR bank used"));
      schema.add(OptionSpec::integer("rflex_bank_count", 0, 0, 255).doc("IR banks used"));
      schema.add(number_list("rflex_banks").doc("sensors read from each bank used"));
      schema.add(OptionSpec::integer("ir_min_range", 100, 0, 65535).unit("mm").doc("shorter ranges read 0"));
      schema.add(OptionSpec::integer("ir_max_range", 800, 0, 65535).unit("mm").doc("longer ranges read this"));
      schema.add(number_list("rflex_ir_calib").shown_default("[1 1]").doc("a b per sensor: range = (a x raw)^b mm"));
      schema.add(number_list("poses").doc("x mm, y mm, theta deg per sensor"));
      break;
    case RflexRole::bumper:
      schema.add(OptionSpec::integer("bumper_count", 0, 0, 32).doc("bumper panels"));
      schema.add(number_list("bumper_def").doc("x mm, y mm, theta deg, length mm, radius mm per panel"));
      schema.add(OptionSpec::integer("rflex_bumper_address", 0x40, 0, 255).doc("DIO address of the first panel"));
      break;
    case RflexRole::power:
      schema.add(OptionSpec::integer("rflex_power_offset", 0, -10000, 10000).unit("dV").doc("added to the charge"));
      break;
    case RflexRole::aio:
    case RflexRole::dio: break;
  }
  return schema;
}

const std::array<std::string_view, kRflexRoleCount>& every_driver() { return kRflexDriverNames; }

RflexRole role_of(std::string_view driver) {
  for (const RflexRole role : all_rflex_roles()) {
    if (driver_name(role) == driver) return role;
  }
  return RflexRole::aio;  // not reached: robot_sections_with only returns the family's
}

// The robot's value of `name`, read with `read(reader, name)` on the
// sections of the roles in `drivers` that write it.
template <class Read>
auto robot_value(const core::DriverContext& context, std::span<const std::string_view> drivers, std::string_view name,
                 Read read) {
  return core::robot_value(context, drivers, name, [&](const config::Section& section, const std::string& driver) {
    return read(core::OptionReader(section, driver, rflex_option_schema(role_of(driver))), name);
  });
}

class RobotReader {
 public:
  RobotReader(const core::DriverContext& context, RflexRole role) : context_(context), only_(driver_name(role)) {}

  template <class Read>
  auto value(std::string_view name, Read read) const {
    return robot_value(context_, std::span<const std::string_view>(&only_, 1), name, read);
  }

  int integer(std::string_view name, int fallback) const {
    return value(name, [](const core::OptionReader& r, std::string_view n) { return r.integer(n); }).value_or(fallback);
  }
  double number(std::string_view name, double fallback) const {
    return value(name, [](const core::OptionReader& r, std::string_view n) { return r.number(n); }).value_or(fallback);
  }
  std::string word(std::string_view name, std::string fallback) const {
    return value(name, [](const core::OptionReader& r, std::string_view n) { return r.text(n); }).value_or(fallback);
  }
  // A list whose length must be a multiple of `group`.
  std::optional<std::vector<double>> list(std::string_view name, std::size_t group = 1) const {
    return value(name, [group](const core::OptionReader& r, std::string_view n) {
      const std::size_t size = r.section().tuple_size(n);
      if (size % group != 0) {
        r.fail({n}, std::string(n) + " holds groups of " + std::to_string(group) + " numbers (got " +
                        std::to_string(size) + ")");
      }
      std::vector<double> values(size);
      for (std::size_t i = 0; i < size; ++i) values[i] = r.section().read_tuple_float(n, i, 0.0);
      return values;
    });
  }

 private:
  const core::DriverContext& context_;
  std::string_view only_;
};

std::vector<int> whole_numbers(const std::vector<double>& values) {
  std::vector<int> out;
  for (const double v : values) out.push_back(static_cast<int>(v));
  return out;
}

std::vector<MountPose> poses_of(const std::vector<double>& values, bool theta_first, double angle_scale) {
  std::vector<MountPose> poses;
  for (std::size_t i = 0; i + 2 < values.size(); i += 3) {
    poses.push_back(theta_first ? MountPose{values[i + 1], values[i + 2], values[i] * angle_scale}
                                : MountPose{values[i], values[i + 1], values[i + 2] * angle_scale});
  }
  return poses;
}

}  // namespace

const core::OptionSchema& rflex_option_schema(RflexRole role) {
  static const std::array<core::OptionSchema, kRflexRoleCount> schemas = [] {
    std::array<core::OptionSchema, kRflexRoleCount> all;
    for (const RflexRole r : all_rflex_roles()) all[static_cast<std::size_t>(r)] = make_schema(r);
    return all;
  }();
  return schemas[static_cast<std::size_t>(role)];
}

RflexSettings read_rflex_settings(const core::DriverContext& context) {
  RflexSettings s;
  const auto every = std::span<const std::string_view>(every_driver());
  s.port = robot_value(context, every, "port", [](const core::OptionReader& r, std::string_view n) {
             return r.text(n);
           }).value_or(std::string(kDefaultRflexPort));
  // 1.5's name: robot_sections_with looks names up as written.
  if (const auto legacy = robot_value(context, every, "rflex_serial_port",
                                      [](const core::OptionReader& r, std::string_view) { return r.text("port"); })) {
    s.port = *legacy;
  }
  for (const auto* name : {"connect_timeout", "report_timeout"}) {
    if (const auto value = robot_value(context, every, name,
                                       [](const core::OptionReader& r, std::string_view n) { return r.seconds(n); })) {
      (std::string_view(name) == "connect_timeout" ? s.connect_timeout : s.report_timeout) = *value;
    }
  }
  (void)robot_value(context, every, "rflex_done",
                    [](const core::OptionReader& r, std::string_view n) { return r.integer(n); });

  const RobotReader position(context, RflexRole::position);
  s.mm_length = position.number("mm_length", s.mm_length);
  s.mm_width = position.number("mm_width", s.mm_width);
  s.odo_distance_conversion = position.number("odo_distance_conversion", s.odo_distance_conversion);
  s.odo_angle_conversion = position.number("odo_angle_conversion", s.odo_angle_conversion);
  s.default_trans_acceleration = position.number("default_trans_acceleration", s.default_trans_acceleration);
  s.default_rot_acceleration = position.number("default_rot_acceleration", s.default_rot_acceleration);
  s.joystick = position.integer("rflex_joystick", 0) != 0;
  s.joy_pos_ratio = position.number("rflex_joy_pos_ratio", 0.0);
  s.joy_ang_ratio = position.number("rflex_joy_ang_ratio", 0.0);

  const RobotReader sonar(context, RflexRole::sonar);
  s.range_distance_conversion = sonar.number("range_distance_conversion", s.range_distance_conversion);
  s.max_num_sonars = sonar.integer("max_num_sonars", s.max_num_sonars);
  s.num_sonars = sonar.integer("num_sonars", s.num_sonars);
  s.sonar_age = sonar.integer("sonar_age", s.sonar_age);
  s.num_sonar_banks = sonar.integer("num_sonar_banks", s.num_sonar_banks);
  s.num_sonars_possible_per_bank = sonar.integer("num_sonars_possible_per_bank", s.num_sonars_possible_per_bank);
  if (const auto in_bank = sonar.list("num_sonars_in_bank")) s.num_sonars_in_bank = whole_numbers(*in_bank);
  s.sonar_echo_delay = sonar.integer("sonar_echo_delay", s.sonar_echo_delay);
  s.sonar_ping_delay = sonar.integer("sonar_ping_delay", s.sonar_ping_delay);
  s.sonar_set_delay = sonar.integer("sonar_set_delay", s.sonar_set_delay);
  const bool theta_first = sonar.word("sonar_pose_order", "theta_x_y") == "theta_x_y";
  if (const auto poses = sonar.list("mmrad_sonar_poses", 3)) s.sonar_poses = poses_of(*poses, theta_first, 1.0);

  const RobotReader bumper(context, RflexRole::bumper);
  s.bumper_count = bumper.integer("bumper_count", 0);
  if (const auto defs = bumper.list("bumper_def", 5)) {
    for (std::size_t i = 0; i + 4 < defs->size(); i += 5) {
      const auto& d = *defs;
      s.bumper_def.push_back({d[i], d[i + 1], d[i + 2], d[i + 3], d[i + 4]});
    }
  }
  s.bumper_address = bumper.integer("rflex_bumper_address", s.bumper_address);

  s.power_offset = RobotReader(context, RflexRole::power).integer("rflex_power_offset", 0);

  const RobotReader ir(context, RflexRole::ir);
  s.ir_pose_count = ir.integer("pose_count", s.ir_pose_count);
  s.ir_base_bank = ir.integer("rflex_base_bank", 0);
  s.ir_bank_count = ir.integer("rflex_bank_count", 0);
  if (const auto banks = ir.list("rflex_banks")) s.ir_banks = whole_numbers(*banks);
  s.ir_min_range = ir.integer("ir_min_range", s.ir_min_range);
  s.ir_max_range = ir.integer("ir_max_range", s.ir_max_range);
  if (const auto calibration = ir.list("rflex_ir_calib", 2)) {
    for (std::size_t i = 0; i + 1 < calibration->size(); i += 2) {
      s.ir_calibration.push_back({(*calibration)[i], (*calibration)[i + 1]});
    }
  }
  if (const auto poses = ir.list("poses", 3)) s.ir_poses = poses_of(*poses, false, std::acos(-1.0) / 180.0);
  // As 1.5: the banks' sensors are what is read, whatever pose_count says.
  if (!s.ir_banks.empty()) {
    int sum = 0;
    for (const int n : s.ir_banks) sum += n;
    s.ir_pose_count = std::min(sum, 32);
  }
  return s;
}

std::string connection_key(const RflexSettings& settings) { return "rflex " + settings.port; }

}  // namespace playerkit::drivers::rflex
