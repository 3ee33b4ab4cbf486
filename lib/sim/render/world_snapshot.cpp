#include "sim/render/world_snapshot.hpp"

#include <cmath>
#include <cstddef>
#include <variant>

namespace playerkit::sim::render {
namespace {

Eigen::Vector2d ray_end(const geometry::Pose2& origin, double bearing, double range) {
  const double angle = origin.yaw + bearing;
  return origin.translation() + range * Eigen::Vector2d(std::cos(angle), std::sin(angle));
}

void add_laser_rays(const World& world, ModelId id, const LaserSpec& spec, std::vector<SnapshotRay>& rays) {
  const LaserScan& scan = world.laser(id);
  const std::size_t samples = scan.ranges.size();
  if (samples == 0) return;
  const geometry::Pose2 origin = world.true_pose(id).compose(spec.pose);
  const double spacing =
      samples > 1 ? (scan.max_angle - scan.min_angle) / static_cast<double>(samples - 1) : 0.0;
  for (std::size_t i = 0; i < samples; ++i) {
    const double range = scan.ranges[i];
    if (!std::isfinite(range)) continue;
    const double bearing = scan.min_angle + spacing * static_cast<double>(i);
    rays.push_back({.kind = RayKind::laser,
                    .from = origin.translation(),
                    .to = ray_end(origin, bearing, range),
                    .hit = range < scan.range_max});
  }
}

void add_sonar_rays(const World& world, ModelId id, const SonarSpec& spec, std::vector<SnapshotRay>& rays) {
  const SonarScan& scan = world.sonar(id);
  const geometry::Pose2 pose = world.true_pose(id);
  for (std::size_t i = 0; i < scan.ranges.size() && i < spec.transducers.size(); ++i) {
    const double range = scan.ranges[i];
    if (!std::isfinite(range)) continue;
    const geometry::Pose2 transducer = pose.compose(spec.transducers[i]);
    rays.push_back({.kind = RayKind::sonar,
                    .from = transducer.translation(),
                    .to = ray_end(transducer, 0.0, range),
                    .hit = range < spec.range_max});
  }
}

// Stage 1.3 mounts a finder on a laser and looks from the scan's origin
// (as the world does when it takes the reading).
geometry::Pose2 finder_pose(const World& world, ModelId id) {
  const ModelSpec& spec = world.spec(id);
  if (spec.parent != kNoModel) {
    if (const auto* laser = std::get_if<LaserSpec>(&world.spec(spec.parent).params)) {
      return world.true_pose(spec.parent).compose(laser->pose).compose(spec.pose);
    }
  }
  return world.true_pose(id);
}

void add_sightings(const World& world, ModelId id, std::vector<SnapshotSighting>& sightings) {
  const FiducialScan& scan = world.fiducials(id);
  if (scan.sightings.empty()) return;
  const geometry::Pose2 origin = finder_pose(world, id);
  for (const FiducialSighting& sighting : scan.sightings) {
    sightings.push_back({.from = origin.translation(),
                         .to = ray_end(origin, sighting.bearing, sighting.range),
                         .id = sighting.id});
  }
}

}  // namespace

WorldSnapshot take_snapshot(const World& world, const Trails* trails) {
  WorldSnapshot snapshot;
  snapshot.time = world.time();
  snapshot.map = &world.scene().map();
  for (const SceneModel& model : world.scene().models()) {
    if (!model.present || !model.body.present) continue;
    snapshot.bodies.push_back({.model = model.id,
                               .shape = model.body.shape,
                               .size = model.body.size,
                               .pose = model.body_pose,
                               .color = model.color,
                               .robot = std::holds_alternative<PositionSpec>(world.spec(model.id).params)});
  }
  for (std::size_t index = 0; index < world.size(); ++index) {
    const auto id = static_cast<ModelId>(index);
    const ModelParams& params = world.spec(id).params;
    if (const auto* laser = std::get_if<LaserSpec>(&params)) {
      add_laser_rays(world, id, *laser, snapshot.rays);
    } else if (const auto* sonar = std::get_if<SonarSpec>(&params)) {
      add_sonar_rays(world, id, *sonar, snapshot.rays);
    } else if (std::holds_alternative<FiducialSpec>(params)) {
      add_sightings(world, id, snapshot.sightings);
    }
  }
  if (trails != nullptr) {
    for (const ModelId id : trails->models()) {
      if (id < 0 || static_cast<std::size_t>(id) >= world.size()) continue;
      snapshot.trails.push_back({.model = id, .color = world.spec(id).color, .points = trails->points(id)});
    }
  }
  return snapshot;
}

}  // namespace playerkit::sim::render
