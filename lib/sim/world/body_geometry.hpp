#pragma once
// Internal: a model's body placed in the world, and the exact tests the
// scene (rays) and the world (collisions) run on it. Shared by scene.cpp,
// body_index.cpp and collisions.cpp.

#include <Eigen/Core>

#include <limits>

#include "algorithms/geometry/pose2.hpp"
#include "sim/world/model_spec.hpp"

namespace playerkit::sim {

// A rectangle (half extents half_x, half_y along its own axes) or a circle
// (radius half_x), with its heading's cosine and sine kept so that a ray
// test needs no trigonometry.
struct PlacedBody {
  Eigen::Vector2d centre = Eigen::Vector2d::Zero();
  double cos_yaw = 1.0;
  double sin_yaw = 0.0;
  double half_x = 0.0;
  double half_y = 0.0;
  bool circle = false;
  double bounding_radius = 0.0;  // of the circle around the whole body

  // A world point in the body's own frame (centre at the origin, x along its heading).
  [[nodiscard]] Eigen::Vector2d to_local(const Eigen::Vector2d& point) const {
    const Eigen::Vector2d d = point - centre;
    return {cos_yaw * d.x() + sin_yaw * d.y(), -sin_yaw * d.x() + cos_yaw * d.y()};
  }
};

// `body_pose`: the body's centre and heading (model pose composed with body.offset).
[[nodiscard]] PlacedBody place_body(const Body& body, const geometry::Pose2& body_pose);

// An axis-aligned square cell [low, high] as a body.
[[nodiscard]] PlacedBody cell_body(const Eigen::Vector2d& low, const Eigen::Vector2d& high);

inline constexpr double kNoRayHit = std::numeric_limits<double>::infinity();

// Distance along the ray (unit `direction`) to where it enters the body:
// 0 when the origin is inside, kNoRayHit when it never does.
[[nodiscard]] double ray_entry(const PlacedBody& body, const Eigen::Vector2d& origin, const Eigen::Vector2d& direction);

// Whether the two bodies share some area (touching edges do not).
[[nodiscard]] bool bodies_overlap(const PlacedBody& a, const PlacedBody& b);

// Whether a world point lies inside the body (its border included).
[[nodiscard]] bool body_contains(const PlacedBody& body, const Eigen::Vector2d& point);

}  // namespace playerkit::sim
