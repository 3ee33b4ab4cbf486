// Stage 1.3 worlds (§3): Player 1.5's `player -s` worlds.
#include <array>
#include <cmath>
#include <numbers>

#include "protocol/interfaces.hpp"
#include "sim/worldfile/world_loader_context.hpp"
#include "sim/worldfile/worldfile_error.hpp"
#include "text/printable.hpp"

namespace playerkit::sim::worldfile {
namespace {

constexpr double kDegree = std::numbers::pi / 180.0;

enum class Visibility { invisible, visible, bright };

// The defaults of one entity type of Stage 1.3's library (§3.4).
struct Stage13Type {
  std::string_view name;
  std::uint16_t interface_code = 0;  // 0: not a Player device
  bool body = false;
  Shape shape = Shape::rectangle;
  double size_x = 0.0, size_y = 0.0;
  bool obstacle = false, sonar = false, vision = false;
  Visibility laser = Visibility::invisible;
  bool gripper = false;
  std::optional<Rgb> color;  // nullopt: the parent's (box), or red
};

constexpr Rgb kRed{255, 0, 0};
constexpr Rgb kBlue{0, 0, 255};
constexpr Rgb kYellow{255, 255, 0};
constexpr Rgb kGreen{0, 255, 0};
constexpr Rgb kMagenta{255, 0, 255};
constexpr Rgb kGray{190, 190, 190};

using protocol::kBlobfinderCode, protocol::kFiducialCode, protocol::kGripperCode, protocol::kLaserCode,
    protocol::kPositionCode, protocol::kPowerCode, protocol::kPtzCode, protocol::kSonarCode, protocol::kTruthCode;
constexpr auto kRect = Shape::rectangle;
constexpr auto kCircle = Shape::circle;
constexpr auto kSeen = Visibility::visible;
constexpr auto kUnseen = Visibility::invisible;

const std::array<Stage13Type, 16> kStage13Types = {{
    {"box", 0, true, kRect, 1.0, 1.0, true, true, true, kSeen, false, std::nullopt},
    {"puck", 0, true, kCircle, 0.08, 0.08, false, false, true, kUnseen, true, kGreen},
    {"position", kPositionCode, true, kRect, 0.44, 0.38, true, true, true, kUnseen, false, kRed},
    {"omniposition", kPositionCode, true, kCircle, 0.30, 0.30, true, true, false, kUnseen, false, kRed},
    {"laser", kLaserCode, true, kRect, 0.155, 0.155, false, false, false, kSeen, false, kBlue},
    {"sonar", kSonarCode, false, kRect, 0.0, 0.0, false, false, false, kUnseen, false, kRed},
    {"fiducialfinder", kFiducialCode, false, kRect, 0.0, 0.0, false, false, false, kUnseen, false, kRed},
    {"lbd", kFiducialCode, false, kRect, 0.0, 0.0, false, false, false, kUnseen, false, kRed},
    {"ptz", kPtzCode, true, kRect, 0.165, 0.145, false, false, true, kUnseen, false, kMagenta},
    {"blobfinder", kBlobfinderCode, false, kRect, 0.0, 0.0, false, false, false, kUnseen, false, kRed},
    {"vision", kBlobfinderCode, false, kRect, 0.0, 0.0, false, false, false, kUnseen, false, kRed},
    {"gripper", kGripperCode, true, kRect, 0.08, 0.30, true, false, false, kUnseen, false, kGray},
    {"truth", kTruthCode, false, kRect, 0.0, 0.0, false, false, false, kUnseen, false, kRed},
    {"power", kPowerCode, false, kRect, 0.0, 0.0, false, false, false, kUnseen, false, kRed},
    // Not models: read elsewhere or ignored.
    {"bitmap", 0, false, kRect, 0.0, 0.0, false, false, false, kUnseen, false, std::nullopt},
    {"gui", 0, false, kRect, 0.0, 0.0, false, false, false, kUnseen, false, std::nullopt},
}};

// Types of 1.3 this simulator does not model: skipped with a warning.
constexpr std::array<std::string_view, 6> kStage13Unsimulated = {"bumper", "broadcast", "mcom",
                                                                 "idar", "idarturret", "host"};

const Stage13Type* stage13_type(std::string_view name) {
  for (const Stage13Type& type : kStage13Types) {
    if (type.name == name) return &type;
  }
  return nullptr;
}

std::vector<std::string_view> stage13_type_names() {
  std::vector<std::string_view> names;
  for (const Stage13Type& type : kStage13Types) names.push_back(type.name);
  names.insert(names.end(), kStage13Unsimulated.begin(), kStage13Unsimulated.end());
  return names;
}

// The entity being read's surroundings.
struct Stage13Parent {
  int model = -1;                 // index in the context's models, -1 for the world
  std::string_view type;          // "" for the world
  std::uint16_t port = 0;         // inherited `port`
  int robot = -1;                 // the top-level position model it rides on
  geometry::Pose2 global_pose{};  // of the parent
  std::optional<Rgb> color;
};

class Stage13Reader {
 public:
  explicit Stage13Reader(LoadContext& context) : context_(context) {}

  void run() {
    world_properties();
    for (const Entity& entity : context_.tree.world.children) read(entity, Stage13Parent{});
  }

 private:
  void world_properties() {
    PropertyReader world(context_.tree.world, context_.units, context_.warnings);
    resolution_ = world.number("resolution", 0.05, Quantity::length);
    if (!(resolution_ > 0.0)) throw_at(world, "resolution", "the world's resolution must be more than 0 m");
    context_.map.resolution = resolution_;
    context_.map.positive_quadrant = true;
    context_.settings.step = world.number("sim_timestep", 0.1);
    if (!(context_.settings.step > 0.0)) throw_at(world, "sim_timestep", "sim_timestep must be more than 0 s");
    if (const auto size = world.tuple("size", {Quantity::length, Quantity::length}, "[x y]")) {
      context_.map.minimum_size = Eigen::Vector2d((*size)[0], (*size)[1]).cwiseMax(0.0);
    }
    range_anon_ = world.number("lbd_range_anon", 4.0, Quantity::length);
    range_id_ = world.number("lbd_range_id", 1.5, Quantity::length);
    if (world.integer("test", 0) != 0) {
      throw_at(world, "test", "the world sets `test`: Stage only dumps such a file and refuses to load it");
    }
    world.skip({"real_timestep", "auth_key", "unit_length", "unit_angle", "puck_friction", "name"});
    world.report_unread(is_gui_property);
  }

  [[noreturn]] static void throw_at(PropertyReader& reader, std::string_view name, const std::string& message) {
    const Property* property = reader.take(name);
    throw WorldFileError(property != nullptr ? property->where : reader.entity().where, message);
  }

  void read(const Entity& entity, const Stage13Parent& parent) {
    if (entity.type == "gui" || entity.type == "host") return;  // the GUI's view, distributed Stage
    if (std::find(kStage13Unsimulated.begin(), kStage13Unsimulated.end(), entity.type) != kStage13Unsimulated.end()) {
      context_.warnings.push_back(located(entity.where, "a " + entity.type + " is not simulated here: skipped"));
      return;
    }
    const Stage13Type* type = stage13_type(entity.type);
    if (type == nullptr) {
      const auto names = stage13_type_names();
      context_.unknown_type(entity, names);
    }
    PropertyReader properties(entity, context_.units, context_.warnings);
    if (entity.type == "bitmap") {
      bitmap(properties, parent);
      properties.report_unread(is_gui_property);
      return;
    }
    model(entity, *type, properties, parent);
  }

  void bitmap(PropertyReader& properties, const Stage13Parent& parent) {
    const Property* file = properties.take("file");
    if (file == nullptr || file->values.empty()) {
      throw WorldFileError(properties.entity().where, "a bitmap needs a `file` (a .pnm image)");
    }
    BitmapPlacement placement;
    placement.file = world_relative(context_.directory, file->values.front().text);
    placement.where = file->where;
    placement.walls = WallPixels::non_zero;
    double metres_per_pixel = properties.number("resolution", 0.0, Quantity::length);
    if (!properties.has("resolution")) {
      if (const Property* scale = properties.take("scale")) {
        properties.warn(scale->where, "`scale` is the old name of a bitmap's `resolution`");
        metres_per_pixel = properties.number("scale", 0.0, Quantity::length);
      } else {
        properties.warn(properties.entity().where,
                        "the bitmap has no `resolution`: the world's, " + std::to_string(resolution_) + " m, is used");
        metres_per_pixel = resolution_;
      }
    }
    if (!(metres_per_pixel > 0.0)) {
      throw WorldFileError(properties.entity().where, "a bitmap's resolution must be more than 0 m per pixel");
    }
    placement.metres_per_pixel = metres_per_pixel;
    // Without a pose the image's bottom-left corner is at the origin;
    // with one, its centre is at the pose.
    placement.centred = properties.has("pose");
    placement.pose = parent.global_pose.compose(pose_of(properties));
    if (const Property* crop = properties.take("crop")) {
      properties.warn(crop->where, "`crop` is not supported: the whole bitmap is used");
    }
    properties.skip({"color", "name"});
    add_bitmap_walls(placement, context_.map, context_.warnings);
  }

  geometry::Pose2 pose_of(PropertyReader& properties) {
    const auto pose = properties.tuple("pose", {Quantity::length, Quantity::length, Quantity::angle}, "[x y th]");
    return pose ? geometry::Pose2{(*pose)[0], (*pose)[1], geometry::normalize_angle((*pose)[2])} : geometry::Pose2{};
  }

  Visibility visibility(PropertyReader& properties, std::string_view name, Visibility fallback, bool bright_allowed) {
    const Property* property = properties.take(name);
    if (property == nullptr || property->values.empty()) return fallback;
    const std::string& word = property->values.front().text;
    if (word == "visible") return Visibility::visible;
    if (word == "bright" && bright_allowed) return Visibility::bright;
    if (word != "invisible") {
      properties.warn(property->values.front().where,
                      "\"" + text::excerpt(word) + "\" is not \"visible\"" + (bright_allowed ? ", \"bright\"" : "") +
                          " or \"invisible\": invisible, as in Stage");
    }
    return Visibility::invisible;
  }

  void model(const Entity& entity, const Stage13Type& type, PropertyReader& properties, const Stage13Parent& parent) {
    ModelSpec spec;
    spec.type = entity.type;
    spec.name = context_.model_name(properties.text("name", ""), entity.type, parent.model, entity.where);
    spec.parent = parent.model;
    spec.pose = pose_of(properties);

    Body& body = spec.body;
    body.present = type.body;
    body.shape = type.shape;
    body.size = {type.size_x, type.size_y};
    if (const auto size = properties.tuple("size", {Quantity::length, Quantity::length}, "[x y]")) {
      body.size = {(*size)[0], (*size)[1]};
      body.present = body.present || (body.size.x() > 0.0 && body.size.y() > 0.0);
    }
    if (const auto offset = properties.tuple("offset", {Quantity::length, Quantity::length}, "[x y]")) {
      body.offset = {(*offset)[0], (*offset)[1], 0.0};
    }
    if (const Property* shape = properties.take("shape"); shape != nullptr && !shape->values.empty()) {
      const std::string& word = shape->values.front().text;
      if (word == "rect") {
        body.shape = Shape::rectangle;
      } else if (word == "circle") {
        body.shape = Shape::circle;
      } else {
        properties.warn(shape->values.front().where,
                        "shape \"" + text::excerpt(word) + "\" is not \"rect\" or \"circle\": the default is kept");
      }
    }

    // A box takes its parent's colour unless it has its own.
    spec.color = type.color.value_or(parent.color.value_or(kYellow));
    if (const Property* color = properties.take("color"); color != nullptr && !color->values.empty()) {
      spec.color = color_named(color->values.front(), context_);
    }

    Returns& returns = spec.returns;
    returns.obstacle = visibility(properties, "obstacle_return", type.obstacle ? kSeen : kUnseen, false) != kUnseen;
    const bool sonar = visibility(properties, "sonar_return", type.sonar ? kSeen : kUnseen, false) != kUnseen;
    const Visibility laser = visibility(properties, "laser_return", type.laser, true);
    // One ranger return for both: a model either ranger sees, both see.
    returns.ranger = (sonar || laser != kUnseen) ? 1.0 : -1.0;
    returns.laser_bright = laser == Visibility::bright;
    returns.blob = visibility(properties, "vision_return", type.vision ? kSeen : kUnseen, false) != kUnseen;
    returns.gripper = visibility(properties, "gripper_return", type.gripper ? kSeen : kUnseen, false) != kUnseen;
    returns.fiducial_id = properties.integer("fiducial_id", 0);

    Stage13Parent here;
    here.type = type.name;
    here.port = parent.port;
    if (const Property* port = properties.take("port")) {
      const int number = properties.integer("port", 0);
      if (number < 0 || number > 65535) throw WorldFileError(port->where, "a port must be between 0 and 65535");
      if (number != 0) here.port = static_cast<std::uint16_t>(number);
    }
    if (const Property* index = properties.take("index")) {
      const int number = properties.integer("index", 0);
      if (number < 0 || number > 65535) throw WorldFileError(index->where, "an index must be between 0 and 65535");
      spec.index = number;
    }
    spec.port = here.port;
    const double interval = properties.number("interval", -1.0);
    properties.skip({"mass", "idar_return"});

    spec.params = params(entity, type, properties, parent);
    if (interval > 0.0) set_interval(spec.params, interval);
    properties.report_unread(is_gui_property);

    here.model = context_.add_model(std::move(spec));
    const ModelSpec& added = context_.models.back();
    here.global_pose = parent.global_pose.compose(added.pose);
    here.color = added.color;
    const bool robot = parent.model < 0 && type.interface_code == kPositionCode;
    here.robot = robot ? here.model : parent.robot;
    context_.map.must_cover.push_back(here.global_pose.translation());
    if (type.interface_code != 0) {
      context_.devices.push_back(DeviceEntity{here.model, type.interface_code, entity.type, here.robot, here.port,
                                              added.index, entity.where});
    }
    for (const Entity& child : entity.children) read(child, here);
    if (robot) add_truth_unless_present(here, entity.where);
  }

  // Every robot has a truth device, whether the world gives one or not.
  void add_truth_unless_present(const Stage13Parent& robot, const SourceLocation& where) {
    for (const DeviceEntity& device : context_.devices) {
      if (device.robot == robot.model && device.interface_code == kTruthCode) return;
    }
    ModelSpec truth;
    truth.type = "truth";
    truth.parent = robot.model;
    truth.name = context_.model_name("", truth.type, robot.model, where);
    truth.port = robot.port;
    truth.body.present = false;
    truth.returns.obstacle = false;
    truth.returns.ranger = -1.0;
    truth.returns.blob = false;
    truth.params = TruthSpec{};
    const int model = context_.add_model(std::move(truth));
    context_.devices.push_back(DeviceEntity{model, kTruthCode, "truth", robot.model, robot.port, std::nullopt, where});
  }

  static void set_interval(ModelParams& params, double interval) {
    std::visit(
        [interval](auto& kind) {
          if constexpr (requires { kind.interval; }) kind.interval = interval;
        },
        params);
  }

  ModelParams params(const Entity& entity, const Stage13Type& type, PropertyReader& properties,
                     const Stage13Parent& parent) {
    const std::string_view name = type.name;
    if (name == "position" || name == "omniposition") {
      PositionSpec position;
      position.drive = name == "omniposition" ? Drive::omnidirectional : Drive::differential;
      // Stage 1.3 has no velocity limits and exact odometry from the start pose.
      const double infinity = std::numeric_limits<double>::infinity();
      position.min_velocity = Eigen::Vector3d::Constant(-infinity);
      position.max_velocity = Eigen::Vector3d::Constant(infinity);
      position.localization = Localization::odometry;
      position.odom_error = Eigen::Vector3d::Zero();
      properties.skip({"odometry"});
      return position;
    }
    if (name == "laser") {
      LaserSpec laser;
      laser.range_max = properties.number("max_range", 8.0, Quantity::length);
      laser.fov = std::numbers::pi;
      laser.samples = 361;
      laser.interval = 0.2;
      properties.skip({"min_res", "scan_rate"});
      return laser;
    }
    if (name == "sonar") return sonar(entity, properties);
    if (name == "fiducialfinder" || name == "lbd") {
      if (parent.type != "laser") {
        throw WorldFileError(entity.where, "a " + entity.type + " must sit inside a laser (it uses the laser's scan)");
      }
      FiducialSpec fiducial;
      fiducial.range_max = properties.number("range_anon", range_anon_, Quantity::length);
      fiducial.range_max_id = properties.number("range_id", range_id_, Quantity::length);
      fiducial.fov = std::get<LaserSpec>(context_.models.at(static_cast<std::size_t>(parent.model)).params).fov;
      fiducial.interval = 0.2;
      return fiducial;
    }
    if (name == "ptz") {
      PtzSpec ptz;
      if (const Property* lens = properties.take("lens"); lens != nullptr && !lens->values.empty()) {
        const std::string& word = lens->values.front().text;
        if (word == "wide") {
          ptz.max_fov = 120.0 * kDegree;
        } else if (word != "normal") {
          properties.warn(lens->values.front().where,
                          "lens \"" + text::excerpt(word) + "\" is not \"normal\" or \"wide\": normal (60 degrees)");
        }
      }
      ptz.min_fov = ptz.max_fov / 12.0;
      ptz.pan_limit = 100.0 * kDegree;
      return ptz;
    }
    if (name == "blobfinder" || name == "vision") {
      BlobfinderSpec blobfinder;
      blobfinder.image_width = 160;
      blobfinder.image_height = 120;
      blobfinder.range = 8.0;
      blobfinder.fov = 60.0 * kDegree;
      if (parent.type == "ptz") {
        blobfinder.fov = std::get<PtzSpec>(context_.models.at(static_cast<std::size_t>(parent.model)).params).max_fov;
      }
      if (const Property* channels = properties.take("channels")) {
        for (const Value& channel : channels->values) blobfinder.channels.push_back(color_named(channel, context_));
      } else {
        blobfinder.channels = {kRed, kGreen, kBlue, kYellow, Rgb{0, 255, 255}, kMagenta};
      }
      return blobfinder;
    }
    if (name == "gripper") {
      GripperSpec gripper;
      const std::string consume = properties.text("consume", "false");
      gripper.consume = consume == "true";
      return gripper;
    }
    if (name == "truth") return TruthSpec{};
    if (name == "power") {
      PowerSpec power;  // 1.3's power device reports a fixed 12 V
      power.full_volts = power.empty_volts = 12.0;
      power.idle_watts = power.watts_per_mps = 0.0;
      power.interval = 1.0;
      return power;
    }
    properties.skip({"friction"});
    return ObjectSpec{};
  }

  SonarSpec sonar(const Entity& entity, PropertyReader& properties) {
    SonarSpec sonar;
    const int count = properties.integer("scount", 64);
    if (count < 0 || count > 64) {
      const Property* scount = properties.take("scount");
      throw WorldFileError(scount != nullptr ? scount->where : entity.where,
                           "scount must be between 0 and 64 (Player 1.5 carries at most 64 sonar readings)");
    }
    for (int i = 0; i < count; ++i) {
      const std::string name = "spose[" + std::to_string(i) + "]";
      const auto pose = properties.tuple(name, {Quantity::length, Quantity::length, Quantity::angle}, "[x y th]");
      sonar.transducers.push_back(pose ? geometry::Pose2{(*pose)[0], (*pose)[1], geometry::normalize_angle((*pose)[2])}
                                       : geometry::Pose2{0.0, 0.0, geometry::normalize_angle(2.0 * std::numbers::pi * i / count)});
    }
    sonar.range_max = properties.number("max_range", 5.0, Quantity::length);
    sonar.range_min = 0.0;  // 1.3 stores min_range and never applies it
    properties.skip({"min_range", "power_on"});
    sonar.interval = 0.1;
    return sonar;
  }

  LoadContext& context_;
  double resolution_ = 0.05;
  double range_anon_ = 4.0;
  double range_id_ = 1.5;
};

}  // namespace

void read_stage13_world(LoadContext& context) { Stage13Reader(context).run(); }

}  // namespace playerkit::sim::worldfile
