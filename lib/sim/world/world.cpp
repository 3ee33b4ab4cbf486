#include "sim/world/world.hpp"

#include <algorithm>
#include <cmath>
#include <string>
#include <utility>

#include "sim/world/noise.hpp"
#include "sim/world/sonar.hpp"
#include "sim/world/world_state.hpp"

namespace playerkit::sim {

namespace {

// Stage's default odom_error bounds (stage-worlds.md §2.5).
constexpr double kOdomErrorXY = 0.015;
constexpr double kOdomErrorYaw = 0.025;

// The word a model of this kind is named after when its spec has no type.
std::string_view kind_word(const ModelParams& params) {
  constexpr std::string_view words[] = {"model",      "position", "laser",   "sonar", "fiducial",
                                        "blobfinder", "ptz",      "gripper", "power", "truth"};
  static_assert(std::size(words) == std::variant_size_v<ModelParams>);
  return words[params.index()];
}

// What a model of this spec keeps while the world runs.
DeviceState initial_device_state(const ModelSpec& spec, std::uint64_t seed, ModelId id,
                                 const geometry::Pose2& start) {
  if (const auto* position = std::get_if<PositionSpec>(&spec.params)) {
    PositionState state;
    state.origin = position->localization_origin.value_or(start);
    state.odometry = state.origin.between(start);
    if (position->odom_error) {
      state.odom_error = *position->odom_error;
    } else {
      NoiseDraws draws(seed, id, 0);
      state.odom_error.x() = draws.uniform(-kOdomErrorXY, kOdomErrorXY);
      state.odom_error.y() = draws.uniform(-kOdomErrorXY, kOdomErrorXY);
      state.odom_error.z() = draws.uniform(-kOdomErrorYaw, kOdomErrorYaw);
    }
    state.command = state.velocity = position->initial_velocity;
    state.always_on = !position->initial_velocity.isZero(0.0);
    return state;
  }
  if (const auto* laser = std::get_if<LaserSpec>(&spec.params)) {
    LaserState state;
    state.spec = *laser;
    return state;
  }
  if (const auto* sonar = std::get_if<SonarSpec>(&spec.params)) {
    SonarState state;
    state.headings = transducer_headings(*sonar);
    return state;
  }
  if (std::holds_alternative<FiducialSpec>(spec.params)) return FiducialState{};
  if (std::holds_alternative<BlobfinderSpec>(spec.params)) return BlobfinderState{};
  if (const auto* ptz = std::get_if<PtzSpec>(&spec.params)) {
    PtzState state;
    state.fov = ptz->max_fov;
    return state;
  }
  if (std::holds_alternative<GripperSpec>(spec.params)) return GripperState{};
  if (const auto* power = std::get_if<PowerSpec>(&spec.params)) {
    PowerState state;
    state.joules = std::max(power->capacity_joules, 0.0);
    return state;
  }
  return std::monostate{};
}

}  // namespace

// ---- State: access, naming of errors, placing ----

ModelRecord& World::State::record(ModelId id) {
  return const_cast<ModelRecord&>(std::as_const(*this).record(id));
}

const ModelRecord& World::State::record(ModelId id) const {
  if (id < 0 || static_cast<std::size_t>(id) >= models.size()) {
    throw ModelError("no model " + std::to_string(id) + " (the world has " + std::to_string(models.size()) +
                     (models.size() == 1 ? " model)" : " models)"));
  }
  return models[static_cast<std::size_t>(id)];
}

std::string World::State::describe(ModelId id) const {
  return "model " + std::to_string(id) + " (\"" + record(id).spec.name + "\")";
}

void World::State::throw_wrong_kind(ModelId id, std::string_view wanted) const {
  const ModelRecord& model = record(id);
  throw ModelError(describe(id) + " is a " + std::string(kind_word(model.spec.params)) + ", not a " +
                   std::string(wanted));
}

geometry::Pose2 World::State::parent_global(ModelId id) const {
  const ModelRecord& model = record(id);
  if (model.carried_by != kNoModel) return global(model.carried_by);
  if (model.spec.parent != kNoModel) return global(model.spec.parent);
  return {};
}

void World::State::place(ModelId id, const geometry::Pose2& pose) {
  for_each_riding(id, pose, false,
                  [this](ModelId riding, const geometry::Pose2& at, bool) { scene.update(riding, at); });
}

void World::State::set_scene_root(ModelId id, ModelId root) {
  for_each_riding(id, global(id), false,
                  [this, root](ModelId riding, const geometry::Pose2&, bool) { scene.set_root(riding, root); });
}

// ---- World ----

World::World(WorldSettings settings, grid::OccupancyGrid map)
    : state_(std::make_unique<State>(settings, std::move(map))) {
  if (!(settings.step > 0.0) || !std::isfinite(settings.step)) {
    throw std::invalid_argument("World: the step must be a positive number of seconds, not " +
                                std::to_string(settings.step));
  }
}

World::~World() = default;
World::World(World&&) noexcept = default;
World& World::operator=(World&&) noexcept = default;

ModelId World::add(ModelSpec spec) {
  State& world = *state_;
  const auto id = static_cast<ModelId>(world.models.size());
  if (spec.parent != kNoModel && (spec.parent < 0 || static_cast<std::size_t>(spec.parent) >= world.models.size())) {
    throw ModelError("model \"" + spec.name + "\": its parent " + std::to_string(spec.parent) + " does not exist");
  }
  if (spec.type.empty()) spec.type = std::string(kind_word(spec.params));
  const std::vector<ModelId>& siblings =
      spec.parent == kNoModel ? world.top_level : world.models[static_cast<std::size_t>(spec.parent)].children;
  if (spec.name.empty()) {
    // Stage's generated names (stage-worlds.md §2.1): <type>:<n>, n counting
    // earlier siblings of the type, under the parent's name for a child.
    const auto same_type = std::count_if(siblings.begin(), siblings.end(), [&](ModelId sibling) {
      return world.models[static_cast<std::size_t>(sibling)].spec.type == spec.type;
    });
    const std::string prefix =
        spec.parent == kNoModel ? "" : world.models[static_cast<std::size_t>(spec.parent)].spec.name + ".";
    for (auto n = same_type;; ++n) {
      spec.name = prefix + spec.type + ":" + std::to_string(n);
      if (!world.names.contains(spec.name)) break;
    }
  } else if (world.names.contains(spec.name)) {
    throw ModelError("model \"" + spec.name + "\": the name is taken by model " +
                     std::to_string(world.names.find(spec.name)->second));
  }

  ModelRecord model;
  model.local = spec.pose;
  const ModelRecord* parent = spec.parent == kNoModel ? nullptr : &world.models[static_cast<std::size_t>(spec.parent)];
  model.root = parent ? parent->root : id;
  const geometry::Pose2 start = parent ? world.global(spec.parent).compose(spec.pose) : spec.pose;
  model.device = initial_device_state(spec, world.settings.seed, id, start);
  model.spec = std::move(spec);

  // Scene roots follow carrying: a child of a carried model is carried too.
  const ModelId scene_root = parent ? world.scene.model(model.spec.parent).root : id;
  world.scene.add({.id = id,
                   .root = scene_root,
                   .pose = start,
                   .body = model.spec.body,
                   .color = model.spec.color,
                   .returns = model.spec.returns,
                   .present = parent ? world.scene.model(model.spec.parent).present : true});

  world.names.emplace(model.spec.name, id);
  if (parent) {
    world.models[static_cast<std::size_t>(model.spec.parent)].children.push_back(id);
  } else {
    world.top_level.push_back(id);
  }
  const ModelParams& params = model.spec.params;
  if (std::holds_alternative<PositionSpec>(params)) world.positions.push_back(id);
  if (std::holds_alternative<GripperSpec>(params)) world.grippers.push_back(id);
  if (std::holds_alternative<PowerSpec>(params)) world.powers.push_back(id);
  if (std::holds_alternative<LaserSpec>(params) || std::holds_alternative<SonarSpec>(params) ||
      std::holds_alternative<FiducialSpec>(params) || std::holds_alternative<BlobfinderSpec>(params) ||
      std::holds_alternative<PtzSpec>(params) || std::holds_alternative<PowerSpec>(params)) {
    world.sensors.push_back(id);
  }
  world.models.push_back(std::move(model));
  if (auto* position = std::get_if<PositionState>(&world.models.back().device)) {
    world.refresh_position_reading(id, *position);
  }
  return id;
}

void World::step() {
  State& world = *state_;
  ++world.steps;
  world.time = static_cast<double>(world.steps) * world.settings.step;  // no drift from repeated sums
  world.move_positions();
  world.drain_power();
  world.update_grippers();
  world.update_sensors();
}

double World::time() const { return state_->time; }
std::uint64_t World::steps() const { return state_->steps; }
const WorldSettings& World::settings() const { return state_->settings; }

std::size_t World::size() const { return state_->models.size(); }
const ModelSpec& World::spec(ModelId id) const { return state_->record(id).spec; }

std::optional<ModelId> World::find(std::string_view name) const {
  const auto found = state_->names.find(name);
  if (found == state_->names.end()) return std::nullopt;
  return found->second;
}

std::vector<ModelId> World::children(ModelId id) const { return state_->record(id).children; }
ModelId World::root_of(ModelId id) const { return state_->record(id).root; }
const Scene& World::scene() const { return state_->scene; }

void World::set_active(ModelId id, bool active) {
  State& world = *state_;
  ModelRecord& model = world.record(id);
  const bool was_active = model.active;
  model.active = active;
  if (was_active == active) return;
  std::visit(
      [&](auto& device) {
        using Device = std::decay_t<decltype(device)>;
        if constexpr (std::is_same_v<Device, PositionState>) {
          // The last unsubscription stops the robot (stage-worlds.md §2.5).
          if (!active) {
            device.command.setZero();
            device.velocity.setZero();
            device.goal.reset();
          }
        } else if constexpr (std::is_same_v<Device, LaserState>) {
          if (!active) device.spec = std::get<LaserSpec>(model.spec.params);  // Stage 1.3 resets the scan
          if (active) device.clock.last_step.reset();
        } else if constexpr (requires { device.clock; }) {
          if (active) device.clock.last_step.reset();  // a reading at the next step
        }
      },
      model.device);
}

bool World::active(ModelId id) const { return state_->record(id).active; }

geometry::Pose2 World::true_pose(ModelId id) const {
  state_->record(id);
  return state_->global(id);
}

void World::set_true_pose(ModelId id, const geometry::Pose2& pose) {
  State& world = *state_;
  ModelRecord& model = world.record(id);
  if (model.spec.parent != kNoModel) {
    throw ModelError(world.describe(id) + " rides on model " + std::to_string(model.spec.parent) +
                     "; only a top-level model can be moved");
  }
  if (!(std::isfinite(pose.x) && std::isfinite(pose.y) && std::isfinite(pose.yaw))) {
    throw std::invalid_argument("set_true_pose: " + world.describe(id) + ": the pose is not finite");
  }
  if (model.carried_by != kNoModel) {
    // Taken out of the gripper's hands.
    const ModelId gripper = model.carried_by;
    world.release(std::get<GripperState>(world.record(gripper).device), id);
  }
  model.local = {pose.x, pose.y, geometry::normalize_angle(pose.yaw)};
  world.place(id, model.local);
}

}  // namespace playerkit::sim
