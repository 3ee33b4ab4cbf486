// Stage 3 and 4 worlds (§2): floorplan models with stretched bitmaps,
// position models, ranger + sensor (4.x), laser and scount rangers (3.x).
#include <array>
#include <cmath>
#include <map>
#include <numbers>

#include "protocol/interfaces.hpp"
#include "sim/worldfile/world_loader_context.hpp"
#include "sim/worldfile/worldfile_error.hpp"
#include "sim/worldfile/worldfile_limits.hpp"
#include "text/printable.hpp"

namespace playerkit::sim::worldfile {
namespace {

constexpr std::array<std::string_view, 7> kStage4Types = {"model",    "position",   "ranger", "laser",
                                                          "fiducial", "blobfinder", "gripper"};
// Registered by Stage, not simulated here: plain objects with a warning.
constexpr std::array<std::string_view, 5> kStage4Unsimulated = {"bumper", "camera", "actuator", "blinkenlight",
                                                                "lightindicator"};
// Handled by their parent or ignored.
constexpr std::array<std::string_view, 3> kStage4Parts = {"block", "sensor", "window"};

template <std::size_t N>
bool one_of(const std::array<std::string_view, N>& names, std::string_view name) {
  return std::find(names.begin(), names.end(), name) != names.end();
}

// Drawing, controllers, power and other properties with no effect here.
bool is_stage4_ignorable(std::string_view name) {
  static constexpr std::array<std::string_view, 20> kIgnorable = {
      "stack_children", "map_resolution", "alwayson",   "ctrl",   "say",    "trail_length",    "trail_interval",
      "friction",       "debug",          "event_queue", "watts", "give_watts", "take_watts", "joules",
      "kjoules",        "joules_capacity", "kjoules_capacity", "blob_return", "ignore_zloc", "acceleration_bounds"};
  return is_gui_property(name) || one_of(kIgnorable, name);
}

struct Stage4Parent {
  int model = -1;
  std::string type;
  std::string name;
  geometry::Pose2 global_pose{};
  int robot = -1;
};

constexpr Quantity kLength = Quantity::length;
constexpr Quantity kAngle = Quantity::angle;
constexpr Quantity kPlain = Quantity::plain;

class Stage4Reader {
 public:
  explicit Stage4Reader(LoadContext& context) : context_(context) {}

  void run() {
    PropertyReader world(context_.tree.world, context_.units, context_.warnings);
    context_.map.resolution = world.number("resolution", 0.02);
    if (!(context_.map.resolution > 0.0)) {
      throw WorldFileError(world.take("resolution")->where, "the world's resolution must be more than 0 m");
    }
    context_.settings.step = world.number("interval_sim", 100.0) / 1000.0;
    if (!(context_.settings.step > 0.0)) {
      throw WorldFileError(world.take("interval_sim")->where, "interval_sim must be more than 0 ms");
    }
    world.skip({"name", "quit_time", "threads", "show_clock", "show_clock_interval", "speedup", "paused",
                "confirm_on_quit", "interval_real", "unit_length", "unit_angle", "size"});
    world.report_unread(is_stage4_ignorable);
    for (const Entity& entity : context_.tree.world.children) read(entity, Stage4Parent{});
  }

 private:
  void read(const Entity& entity, const Stage4Parent& parent) {
    if (entity.type == "window" || entity.type == "block") return;  // the GUI's view; the parent's shape
    if (entity.type == "sensor") {
      if (parent.type != "ranger") throw WorldFileError(entity.where, "a sensor must sit inside a ranger");
      return;  // read with its ranger
    }
    const bool unsimulated = one_of(kStage4Unsimulated, entity.type);
    if (!unsimulated && !one_of(kStage4Types, entity.type)) {
      std::vector<std::string_view> names(kStage4Types.begin(), kStage4Types.end());
      names.insert(names.end(), kStage4Unsimulated.begin(), kStage4Unsimulated.end());
      names.insert(names.end(), kStage4Parts.begin(), kStage4Parts.end());
      context_.unknown_type(entity, names);
    }
    if (unsimulated) {
      context_.warnings.push_back(
          located(entity.where, "a " + entity.type + " is not simulated here: it is a plain object"));
    }
    PropertyReader properties(entity, context_.units, context_.warnings);
    ModelSpec spec;
    spec.type = entity.type;
    spec.parent = parent.model;
    spec.name = context_.model_name(properties.text("name", ""), entity.type, parent.model, entity.where);
    if (const auto pose = properties.tuple("pose", {kLength, kLength, kLength, kAngle}, "[x y z a]")) {
      spec.pose = {(*pose)[0], (*pose)[1], geometry::normalize_angle((*pose)[3])};
    }
    body_and_looks(entity, properties, parent, spec);
    returns(properties, spec.returns);
    const double interval = properties.number("update_interval", 100.0) / 1000.0;

    const bool robot = parent.model < 0 && entity.type == "position";
    std::uint16_t code = 0;
    spec.params = params(entity, properties, interval, code);
    properties.report_unread(is_stage4_ignorable);

    Stage4Parent here;
    here.type = entity.type;
    here.name = spec.name;
    here.global_pose = parent.global_pose.compose(spec.pose);
    here.robot = robot ? robots_++ : parent.robot;
    here.model = context_.add_model(std::move(spec));
    if (parent.model < 0) context_.map.must_cover.push_back(here.global_pose.translation());
    if (code != 0) {
      context_.devices.push_back(
          DeviceEntity{here.model, code, entity.type, here.robot, 0, std::nullopt, entity.where});
    }
    for (const Entity& child : entity.children) read(child, here);
    if (robot) add_truth(here, entity.where);
  }

  void body_and_looks(const Entity& entity, PropertyReader& properties, const Stage4Parent& parent, ModelSpec& spec) {
    const std::string& type = entity.type;
    Body& body = spec.body;
    Eigen::Vector2d size(0.4, 0.4);
    if (type == "ranger" || type == "laser") size = {0.15, 0.15};
    if (type == "gripper") size = {0.2, 0.3};
    const bool has_blocks = std::any_of(entity.children.begin(), entity.children.end(),
                                        [](const Entity& child) { return child.type == "block"; });
    // Rangers, fiducial finders and blobfinders have no body unless blocks give one.
    body.present = has_blocks || !(type == "ranger" || type == "fiducial" || type == "blobfinder");
    if (const auto given = properties.tuple("size", {kLength, kLength, kLength}, "[x y z]")) {
      size = {(*given)[0], (*given)[1]};
    }
    body.size = size;
    if (const auto origin = properties.tuple("origin", {kLength, kLength, kLength, kAngle}, "[x y z a]")) {
      body.offset = {(*origin)[0], (*origin)[1], geometry::normalize_angle((*origin)[3])};
    }
    if (properties.integer("noblocks", 0) != 0) body.present = false;
    const geometry::Pose2 body_pose = parent.global_pose.compose(spec.pose).compose(body.offset);
    if (const Property* bitmap = properties.take("bitmap"); bitmap != nullptr && !bitmap->values.empty()) {
      BitmapPlacement placement;
      placement.file = world_relative(context_.directory, bitmap->values.front().text);
      placement.where = bitmap->where;
      placement.walls = WallPixels::dark;
      placement.stretch_to = size;
      if (!(size.x() > 0.0 && size.y() > 0.0)) {
        throw WorldFileError(bitmap->where, "a model with a bitmap needs a size above 0 in x and y");
      }
      placement.pose = body_pose;
      add_bitmap_walls(placement, context_.map, context_.warnings);
      body.present = false;  // its walls are the map's
    }
    if (properties.integer("boundary", 0) != 0) {
      // Four 0.01 m walls just inside the body's bounding box.
      constexpr double thickness = 0.01;
      const Eigen::Vector2d half = size / 2.0;
      const std::array<std::pair<Eigen::Vector2d, Eigen::Vector2d>, 4> sides = {{
          {{-half.x() + thickness / 2, 0.0}, {thickness, size.y()}},
          {{half.x() - thickness / 2, 0.0}, {thickness, size.y()}},
          {{0.0, -half.y() + thickness / 2}, {size.x(), thickness}},
          {{0.0, half.y() - thickness / 2}, {size.x(), thickness}},
      }};
      for (const auto& [centre, extent] : sides) {
        const Eigen::Vector2d at = body_pose.transform(centre);
        context_.map.walls.push_back(WallRectangle{{at.x(), at.y(), body_pose.yaw}, extent});
      }
    }

    spec.color = Rgb{255, 0, 0};
    if (type == "ranger") spec.color = Rgb{0, 0, 128};
    if (type == "laser") spec.color = Rgb{0, 0, 255};
    if (type == "gripper") spec.color = Rgb{77, 77, 77};
    if (const Property* color = properties.take("color"); color != nullptr && !color->values.empty()) {
      spec.color = color_named(color->values.front(), context_);
    } else if (const auto rgba = properties.tuple("color_rgba", {kPlain, kPlain, kPlain, kPlain}, "[r g b a]")) {
      const auto channel = [](double value) {
        return static_cast<std::uint8_t>(std::lround(std::clamp(value, 0.0, 1.0) * 255.0));
      };
      spec.color = Rgb{channel((*rgba)[0]), channel((*rgba)[1]), channel((*rgba)[2])};
    }
  }

  void returns(PropertyReader& properties, Returns& returns) {
    returns.obstacle = properties.integer("obstacle_return", 1) != 0;
    returns.ranger = properties.number("ranger_return", 1.0);
    returns.fiducial_id = properties.integer("fiducial_return", 0);
    returns.fiducial_key = properties.integer("fiducial_key", 0);
    returns.gripper = properties.integer("gripper_return", 0) != 0;
    if (context_.dialect == Dialect::stage3) {
      const int laser = properties.integer("laser_return", 1);
      returns.laser_bright = laser >= 2;
      if (laser == 0) returns.ranger = -1.0;
    } else {
      properties.skip({"laser_return"});  // read, unused in 4.x
    }
  }

  ModelParams params(const Entity& entity, PropertyReader& properties, double interval, std::uint16_t& code) {
    const std::string& type = entity.type;
    if (type == "position") {
      code = protocol::kPositionCode;
      return position(properties);
    }
    if (type == "ranger") return ranger(entity, properties, interval, code);
    if (type == "laser") {
      code = protocol::kLaserCode;
      LaserSpec laser;
      laser.samples = properties.integer("samples", 180);
      laser.range_min = properties.number("range_min", 0.0, kLength);
      laser.range_max = properties.number("range_max", 8.0, kLength);
      laser.fov = properties.number("fov", 180.0, kAngle);
      laser.interval = interval;
      properties.skip({"resolution"});
      check_samples(entity, laser.samples);
      return laser;
    }
    if (type == "fiducial") {
      code = protocol::kFiducialCode;
      FiducialSpec fiducial;
      fiducial.range_min = properties.number("range_min", 0.0, kLength);
      fiducial.range_max = properties.number("range_max", 8.0, kLength);
      fiducial.range_max_id = properties.number("range_max_id", 5.0, kLength);
      fiducial.fov = properties.number("fov", 180.0, kAngle);
      fiducial.key = properties.integer("fiducial_key", 0);
      fiducial.interval = interval;
      return fiducial;
    }
    if (type == "blobfinder") {
      code = protocol::kBlobfinderCode;
      BlobfinderSpec blobfinder;
      const int count = properties.integer("colors_count", 0);
      const Property* colors = properties.take("colors");
      for (int i = 0; colors != nullptr && i < count && i < static_cast<int>(colors->values.size()); ++i) {
        blobfinder.channels.push_back(color_named(colors->values[static_cast<std::size_t>(i)], context_));
      }
      if (const auto image = properties.tuple("image", {kPlain, kPlain}, "[w h]")) {
        if (!((*image)[0] >= 1 && (*image)[0] <= kMaxSensorSamples && (*image)[1] >= 1 &&
              (*image)[1] <= kMaxSensorSamples)) {
          throw WorldFileError(properties.take("image")->where,
                               "a blobfinder's image must be between 1 and " + std::to_string(kMaxSensorSamples) +
                                   " pixels each way");
        }
        blobfinder.image_width = static_cast<int>((*image)[0]);
        blobfinder.image_height = static_cast<int>((*image)[1]);
      }
      blobfinder.range = properties.number("range", 12.0);
      blobfinder.fov = properties.number("fov", 60.0, kAngle);
      blobfinder.interval = interval;
      properties.skip({"pan"});
      return blobfinder;
    }
    if (type == "gripper") {
      code = protocol::kGripperCode;
      properties.skip({"paddle_size", "paddle_state", "autosnatch"});
      return GripperSpec{};
    }
    return ObjectSpec{};
  }

  PositionSpec position(PropertyReader& properties) {
    PositionSpec position;
    const Property* drive = properties.take("drive");
    const std::string drive_name = properties.text("drive", "diff");
    if (drive_name == "omni") {
      position.drive = Drive::omnidirectional;
    } else if (drive_name == "car") {
      position.drive = Drive::car;
    } else if (drive_name != "diff") {
      properties.warn(drive->values.front().where,
                      "drive \"" + text::excerpt(drive_name) + "\" is not \"diff\", \"omni\" or \"car\": diff");
    }
    position.wheelbase = properties.number("wheelbase", 1.0, kLength);
    if (const auto velocity = properties.tuple("velocity", {kLength, kLength, kLength, kAngle}, "[x y z a]")) {
      position.initial_velocity = {(*velocity)[0], (*velocity)[1], (*velocity)[3]};
    }
    if (const auto bounds = properties.tuple("velocity_bounds",
                                             {kLength, kLength, kLength, kLength, kLength, kLength, kAngle, kAngle},
                                             "[xmin xmax ymin ymax zmin zmax amin amax]")) {
      position.min_velocity = {(*bounds)[0], (*bounds)[2], (*bounds)[6]};
      position.max_velocity = {(*bounds)[1], (*bounds)[3], (*bounds)[7]};
    }
    const Property* localization = properties.take("localization");
    const std::string mode = properties.text("localization", "gps");
    if (mode == "odom") {
      position.localization = Localization::odometry;
      if (const auto origin =
              properties.tuple("localization_origin", {kLength, kLength, kLength, kAngle}, "[x y z a]")) {
        position.localization_origin = geometry::Pose2{(*origin)[0], (*origin)[1], (*origin)[3]};
      }
    } else {
      if (mode != "gps") {
        properties.warn(localization->values.front().where,
                        "localization \"" + text::excerpt(mode) + "\" is not \"gps\" or \"odom\": gps");
      }
      // Stage 4.3 reports the true global pose and ignores localization_origin.
      position.localization = Localization::gps;
      position.localization_origin = geometry::Pose2{};
      properties.skip({"localization_origin"});
    }
    // Taken as written: Stage reads the fourth element as an angle (0.05
    // becomes 0.05 degrees in radians), which no world means.
    position.odom_error.reset();
    if (const auto error = properties.tuple("odom_error", {kPlain, kPlain, kPlain, kPlain}, "[x y z a]")) {
      position.odom_error = Eigen::Vector3d((*error)[0], (*error)[1], (*error)[3]);
    }
    if (const Property* odom = properties.take("odom")) {
      properties.warn(odom->where, "`odom` is obsolete (Stage ignores it): use localization \"odom\"");
    }
    position.mass_kg = properties.number("mass", 0.0);
    return position;
  }

  static void check_samples(const Entity& entity, int samples) {
    if (samples < 1 || samples > kMaxSensorSamples) {
      throw WorldFileError(entity.where, "samples must be between 1 and " + std::to_string(kMaxSensorSamples) +
                                             ", not " + std::to_string(samples));
    }
  }

  // 4.x: the sensors decide; 3.x: a ring of scount transducers.
  ModelParams ranger(const Entity& entity, PropertyReader& properties, double interval, std::uint16_t& code) {
    std::vector<const Entity*> sensors;
    for (const Entity& child : entity.children) {
      if (child.type == "sensor") sensors.push_back(&child);
    }
    if (sensors.empty() && (context_.dialect == Dialect::stage3 || properties.has("scount"))) {
      code = protocol::kSonarCode;
      return scount_ranger(properties, interval);
    }
    if (sensors.empty()) {
      context_.warnings.push_back(located(entity.where, "a ranger with no sensor gives no data: not served"));
      return ObjectSpec{};
    }
    struct Transducer {
      geometry::Pose2 pose;
      double range_min = 0.0, range_max = 5.0, fov = 0.1;
      int samples = 1;
      Eigen::Vector3d noise = Eigen::Vector3d::Zero();
    };
    std::vector<Transducer> read;
    for (const Entity* sensor : sensors) {
      PropertyReader reader(*sensor, context_.units, context_.warnings);
      Transducer transducer;
      if (const auto pose = reader.tuple("pose", {kLength, kLength, kLength, kAngle}, "[x y z a]")) {
        transducer.pose = {(*pose)[0], (*pose)[1], geometry::normalize_angle((*pose)[3])};
      }
      if (const auto range = reader.tuple("range", {kLength, kLength}, "[min max]")) {
        transducer.range_min = (*range)[0];
        transducer.range_max = (*range)[1];
      }
      if (reader.has("fov")) transducer.fov = reader.number("fov", 0.0, kAngle);
      transducer.samples = reader.integer("samples", 1);
      check_samples(*sensor, transducer.samples);
      if (const auto noise = reader.tuple("noise", {kLength, kPlain, kAngle}, "[c p a]")) {
        transducer.noise = {(*noise)[0], (*noise)[1], (*noise)[2]};
      }
      reader.skip({"size", "color", "color_rgba", "name"});
      reader.report_unread(is_stage4_ignorable);
      read.push_back(transducer);
    }
    const Transducer& first = read.front();
    if (read.size() == 1 && first.samples > 1) {
      code = protocol::kLaserCode;
      LaserSpec laser;
      laser.pose = first.pose;
      laser.range_min = first.range_min;
      laser.range_max = first.range_max;
      laser.fov = first.fov;
      laser.samples = first.samples;
      laser.noise_sd = std::sqrt(std::max(first.noise.x(), 0.0));  // Stage's c is a variance
      laser.noise_proportional = first.noise.y();
      laser.angle_jitter = first.noise.z();
      laser.interval = interval;
      return laser;
    }
    code = protocol::kSonarCode;
    SonarSpec sonar;
    for (const Transducer& transducer : read) sonar.transducers.push_back(transducer.pose);
    sonar.range_max = first.range_max;
    sonar.range_min = 0.0;  // Stage 4 keeps readings below range.min
    sonar.noise_sd = std::sqrt(std::max(first.noise.x(), 0.0));
    sonar.interval = interval;
    return sonar;
  }

  SonarSpec scount_ranger(PropertyReader& properties, double interval) {
    SonarSpec sonar;
    const int count = properties.integer("scount", 16);
    if (count < 0 || count > 1024) {
      throw WorldFileError(properties.take("scount")->where, "scount must be between 0 and 1024");
    }
    double range_min = 0.0, range_max = 5.0;
    if (const auto view = properties.tuple("sview", {kLength, kLength, kAngle}, "[min max fov]")) {
      range_min = (*view)[0];
      range_max = (*view)[1];
    }
    for (int i = 0; i < count; ++i) {
      const std::string index = "[" + std::to_string(i) + "]";
      geometry::Pose2 pose{0.0, 0.0, geometry::normalize_angle(2.0 * std::numbers::pi * i / count)};
      if (const auto planar = properties.tuple("spose" + index, {kLength, kLength, kAngle}, "[x y a]")) {
        pose = {(*planar)[0], (*planar)[1], geometry::normalize_angle((*planar)[2])};
      }
      if (const auto spatial = properties.tuple("spose3" + index, {kLength, kLength, kLength, kAngle}, "[x y z a]")) {
        pose = {(*spatial)[0], (*spatial)[1], geometry::normalize_angle((*spatial)[3])};
      }
      sonar.transducers.push_back(pose);
    }
    sonar.range_min = range_min;  // Stage 3 raises shorter readings to it
    sonar.range_max = range_max;
    sonar.interval = interval;
    properties.skip({"ssize", "sraycount"});
    return sonar;
  }

  // Every robot has a truth device (Stage 3/4 have none; Player 1.5 clients use it).
  void add_truth(const Stage4Parent& robot, const SourceLocation& where) {
    ModelSpec truth;
    truth.type = "truth";
    truth.parent = robot.model;
    truth.name = context_.model_name("", truth.type, robot.model, where);
    truth.body.present = false;
    truth.returns.obstacle = false;
    truth.returns.ranger = -1.0;
    truth.returns.blob = false;
    truth.params = TruthSpec{};
    const int model = context_.add_model(std::move(truth));
    context_.devices.push_back(
        DeviceEntity{model, protocol::kTruthCode, "truth", robot.robot, 0, std::nullopt, where});
  }

  LoadContext& context_;
  int robots_ = 0;
};

}  // namespace

void read_stage4_world(LoadContext& context) { Stage4Reader(context).run(); }

}  // namespace playerkit::sim::worldfile
