#include "drivers/sim/simulation_source.hpp"

#include <stdexcept>
#include <utility>
#include <variant>
#include <vector>

#include "protocol/interfaces.hpp"
#include "text/printable.hpp"

namespace playerkit::drivers::sim {

using playerkit::sim::ModelId;
using playerkit::sim::World;

SimulationSource::SimulationSource(World world, std::string world_name, SimulationSettings settings)
    : world_name_(std::move(world_name)), settings_(settings), world_(std::move(world)) {}

std::shared_ptr<SimulationHost> SimulationSource::host(const core::DriverContext& context) {
  return context.connections.get<SimulationHost>("sim " + world_name_, [&]() {
    std::lock_guard lock(mutex_);
    if (!world_) {
      throw std::logic_error("the world " + world_name_ + " is served by another device table already");
    }
    auto host = std::make_shared<SimulationHost>(std::move(*world_), world_name_, settings_, context.logger);
    world_.reset();
    host_ = host;
    return host;
  });
}

std::shared_ptr<SimulationHost> SimulationSource::existing_host() const {
  std::lock_guard lock(mutex_);
  return host_.lock();
}

ModelKind model_kind_for(std::uint16_t interface_code) {
  switch (interface_code) {
    case protocol::kPositionCode: return ModelKind::position;
    case protocol::kLaserCode: return ModelKind::laser;
    case protocol::kSonarCode: return ModelKind::sonar;
    case protocol::kFiducialCode: return ModelKind::fiducial;
    case protocol::kBlobfinderCode: return ModelKind::blobfinder;
    case protocol::kPtzCode: return ModelKind::ptz;
    case protocol::kGripperCode: return ModelKind::gripper;
    case protocol::kPowerCode: return ModelKind::power;
    default: return ModelKind::any;
  }
}

std::string_view model_kind_name(ModelKind kind) {
  switch (kind) {
    case ModelKind::position: return "position";
    case ModelKind::laser: return "laser";
    case ModelKind::sonar: return "sonar";
    case ModelKind::fiducial: return "fiducial finder";
    case ModelKind::blobfinder: return "blobfinder";
    case ModelKind::ptz: return "ptz";
    case ModelKind::gripper: return "gripper";
    case ModelKind::power: return "power";
    case ModelKind::any: return "model";
  }
  return "model";
}

bool is_of_kind(const World& world, ModelId model, ModelKind kind) {
  const auto& params = world.spec(model).params;
  switch (kind) {
    case ModelKind::position: return std::holds_alternative<playerkit::sim::PositionSpec>(params);
    case ModelKind::laser: return std::holds_alternative<playerkit::sim::LaserSpec>(params);
    case ModelKind::sonar: return std::holds_alternative<playerkit::sim::SonarSpec>(params);
    case ModelKind::fiducial: return std::holds_alternative<playerkit::sim::FiducialSpec>(params);
    case ModelKind::blobfinder: return std::holds_alternative<playerkit::sim::BlobfinderSpec>(params);
    case ModelKind::ptz: return std::holds_alternative<playerkit::sim::PtzSpec>(params);
    case ModelKind::gripper: return std::holds_alternative<playerkit::sim::GripperSpec>(params);
    case ModelKind::power: return std::holds_alternative<playerkit::sim::PowerSpec>(params);
    case ModelKind::any: return true;
  }
  return false;
}

std::optional<ModelId> find_model(const World& world, std::string_view name, ModelKind kind, std::string& why) {
  const std::optional<ModelId> named = world.find(name);
  if (!named) {
    why = "the world has no model named \"" + text::excerpt(name) + "\"";
    return std::nullopt;
  }
  // Depth first, pre-order: the model, then each child's subtree in order.
  std::vector<ModelId> pending{*named};
  while (!pending.empty()) {
    const ModelId model = pending.back();
    pending.pop_back();
    if (is_of_kind(world, model, kind)) return model;
    const std::vector<ModelId> children = world.children(model);
    pending.insert(pending.end(), children.rbegin(), children.rend());
  }
  why = "model \"" + text::excerpt(name) + "\" is no " + std::string(model_kind_name(kind)) + " and carries none";
  return std::nullopt;
}

}  // namespace playerkit::drivers::sim
