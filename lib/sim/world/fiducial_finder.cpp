#include "sim/world/fiducial_finder.hpp"

#include <algorithm>
#include <cmath>

namespace playerkit::sim {

namespace {

// Any unrelated model with a body blocks the line of sight, whatever its
// ranger return (Stage's quirk, stage-worlds.md §2.8).
bool blocks_line_of_sight(const SceneModel& model) { return model.present && model.body.present; }

}  // namespace

FiducialScan find_fiducials(const Scene& scene, const FiducialSpec& spec, const geometry::Pose2& finder_pose,
                            ModelId own_root) {
  FiducialScan scan;
  const Eigen::Vector2d origin = finder_pose.translation();
  const std::vector<ModelId> candidates = scene.models_near(origin, spec.range_max);
  const ModelFilter any_body = blocks_line_of_sight;

  for (const ModelId id : candidates) {
    const SceneModel& target = scene.model(id);
    if (!target.present || target.returns.fiducial_id == 0 || target.returns.fiducial_key != spec.key) continue;
    if (target.root == own_root) continue;

    // Centre to centre: the finder's origin to the middle of the target's body.
    const Eigen::Vector2d offset = target.body_pose.translation() - origin;
    const double range = offset.norm();
    if (!(range < spec.range_max) || range < spec.range_min) continue;
    const double direction = std::atan2(offset.y(), offset.x());
    const double bearing = geometry::angle_difference(direction, finder_pose.yaw);
    if (std::abs(bearing) > spec.fov / 2.0) continue;

    // Seen when the ray meets the target first, or (a target with no body
    // of its own) reaches its centre meeting nothing.
    const RayHit hit = scene.cast(origin, direction, range, own_root, any_body);
    const bool seen = hit.model == id || (hit.model == kNoModel && !hit.wall);
    if (!seen) continue;

    scan.sightings.push_back({.id = range > spec.range_max_id ? 0 : target.returns.fiducial_id,
                              .range = range,
                              .bearing = bearing,
                              .orientation = geometry::angle_difference(target.pose.yaw, finder_pose.yaw),
                              .model = id});
  }
  std::sort(scan.sightings.begin(), scan.sightings.end(), [](const FiducialSighting& a, const FiducialSighting& b) {
    return a.range != b.range ? a.range < b.range : a.model < b.model;
  });
  return scan;
}

}  // namespace playerkit::sim
