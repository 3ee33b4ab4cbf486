// Sensors: which take a reading at a step, from where, and their getters.

#include <algorithm>
#include <cmath>
#include <numbers>
#include <stdexcept>
#include <string>

#include "sim/world/blobfinder.hpp"
#include "sim/world/fiducial_finder.hpp"
#include "sim/world/laser.hpp"
#include "sim/world/noise.hpp"
#include "sim/world/sonar.hpp"
#include "sim/world/world_state.hpp"

namespace playerkit::sim {

void World::State::update_sensors() {
  for (const ModelId id : sensors) {
    if (models[static_cast<std::size_t>(id)].active) update_sensor(id);
  }
}

void World::State::update_sensor(ModelId id) {
  ModelRecord& model = models[static_cast<std::size_t>(id)];
  const ModelId own_root = model.root;
  const double dt = settings.step;
  // Noise keyed by the step, so a reading at step k does not depend on
  // whether the sensor was read before.
  const auto noise = [&] { return NoiseDraws(settings.seed, id, steps); };

  if (auto* laser = std::get_if<LaserState>(&model.device)) {
    if (!laser->clock.due(steps, dt, laser->spec.interval)) return;
    NoiseDraws draws = noise();
    laser->scan = scan_laser(scene, laser->spec, global(id).compose(laser->spec.pose), own_root, draws);
    laser->scan.time = time;
    laser->clock.last_step = steps;
  } else if (auto* sonar = std::get_if<SonarState>(&model.device)) {
    const auto& spec = std::get<SonarSpec>(model.spec.params);
    if (!sonar->clock.due(steps, dt, spec.interval)) return;
    NoiseDraws draws = noise();
    sonar->scan = scan_sonar(scene, spec, sonar->headings, global(id), own_root, draws);
    sonar->scan.time = time;
    sonar->clock.last_step = steps;
  } else if (auto* finder = std::get_if<FiducialState>(&model.device)) {
    const auto& spec = std::get<FiducialSpec>(model.spec.params);
    if (!finder->clock.due(steps, dt, spec.interval)) return;
    // Stage 1.3 mounts the finder on a laser and looks from the scan's origin.
    geometry::Pose2 pose = global(id);
    if (model.spec.parent != kNoModel) {
      const ModelRecord& parent = models[static_cast<std::size_t>(model.spec.parent)];
      if (const auto* carrier = std::get_if<LaserState>(&parent.device)) {
        pose = global(model.spec.parent).compose(carrier->spec.pose).compose(model.local);
      }
    }
    finder->scan = find_fiducials(scene, spec, pose, own_root);
    finder->scan.time = time;
    finder->clock.last_step = steps;
  } else if (auto* blobs = std::get_if<BlobfinderState>(&model.device)) {
    const auto& spec = std::get<BlobfinderSpec>(model.spec.params);
    if (!blobs->clock.due(steps, dt, spec.interval)) return;
    // On a ptz the camera turns with its pan and sees through its zoom.
    geometry::Pose2 camera = global(id);
    double fov = spec.fov;
    if (model.spec.parent != kNoModel) {
      const ModelRecord& parent = models[static_cast<std::size_t>(model.spec.parent)];
      if (const auto* ptz = std::get_if<PtzState>(&parent.device)) {
        camera = global(model.spec.parent).compose({0.0, 0.0, ptz->pan}).compose(model.local);
        fov = ptz->fov;
      }
    }
    blobs->scan = find_blobs(scene, spec, camera, fov, own_root);
    blobs->scan.time = time;
    blobs->clock.last_step = steps;
  } else if (auto* ptz = std::get_if<PtzState>(&model.device)) {
    if (!ptz->clock.due(steps, dt, std::get<PtzSpec>(model.spec.params).interval)) return;
    ptz->reading = {.pan = ptz->pan, .tilt = 0.0, .fov = ptz->fov, .time = time};
    ptz->clock.last_step = steps;
  } else if (auto* power = std::get_if<PowerState>(&model.device)) {
    const auto& spec = std::get<PowerSpec>(model.spec.params);
    if (!power->clock.due(steps, dt, spec.interval)) return;
    const double charge = spec.capacity_joules > 0.0 ? power->joules / spec.capacity_joules : 0.0;
    power->reading = {.joules = power->joules,
                      .volts = spec.empty_volts + (spec.full_volts - spec.empty_volts) * charge,
                      .time = time};
    power->clock.last_step = steps;
  }
}

const LaserScan& World::laser(ModelId id) const { return state_->device<LaserState>(id, "laser").scan; }
const SonarScan& World::sonar(ModelId id) const { return state_->device<SonarState>(id, "sonar").scan; }
const FiducialScan& World::fiducials(ModelId id) const {
  return state_->device<FiducialState>(id, "fiducial finder").scan;
}
const BlobScan& World::blobs(ModelId id) const { return state_->device<BlobfinderState>(id, "blobfinder").scan; }
const PtzReading& World::ptz(ModelId id) const { return state_->device<PtzState>(id, "ptz").reading; }

void World::configure_laser(ModelId id, double fov, int samples) {
  auto& laser = state_->device<LaserState>(id, "laser");
  if (!(fov > 0.0 && fov <= 2.0 * std::numbers::pi) || samples < 1) {
    throw std::invalid_argument("configure_laser: " + state_->describe(id) + ": a scan needs a fov in (0, 2π] and " +
                                "at least one sample, not fov " + std::to_string(fov) + " rad and " +
                                std::to_string(samples) + " samples");
  }
  laser.spec.fov = fov;
  laser.spec.samples = samples;
}

void World::command_ptz(ModelId id, double pan, double /*tilt: Stage 1.3's is fixed at 0*/, double fov) {
  auto& ptz = state_->device<PtzState>(id, "ptz");
  const auto& spec = std::get<PtzSpec>(state_->record(id).spec.params);
  if (!std::isfinite(pan) || !std::isfinite(fov)) {
    throw std::invalid_argument("command_ptz: " + state_->describe(id) + ": pan and fov must be finite");
  }
  const double pan_limit = std::abs(spec.pan_limit);
  ptz.pan = std::clamp(pan, -pan_limit, pan_limit);
  ptz.fov = std::clamp(fov, std::min(spec.min_fov, spec.max_fov), spec.max_fov);
}

}  // namespace playerkit::sim
