#include "sim/world/body_geometry.hpp"

#include <algorithm>
#include <cmath>
#include <utility>

namespace playerkit::sim {

namespace {

double box_ray_entry(const PlacedBody& box, const Eigen::Vector2d& origin, const Eigen::Vector2d& direction) {
  const Eigen::Vector2d start = box.to_local(origin);
  const Eigen::Vector2d heading{box.cos_yaw * direction.x() + box.sin_yaw * direction.y(),
                                -box.sin_yaw * direction.x() + box.cos_yaw * direction.y()};
  const double half[2] = {box.half_x, box.half_y};
  double enter = -kNoRayHit;
  double leave = kNoRayHit;
  // Slabs (Kay and Kajiya): the ray is inside the box where it is inside both.
  for (int axis = 0; axis < 2; ++axis) {
    const double from = start[axis];
    const double along = heading[axis];
    if (along == 0.0) {
      if (std::abs(from) > half[axis]) return kNoRayHit;
      continue;
    }
    double near = (-half[axis] - from) / along;
    double far = (half[axis] - from) / along;
    if (near > far) std::swap(near, far);
    enter = std::max(enter, near);
    leave = std::min(leave, far);
  }
  if (enter > leave || leave < 0.0) return kNoRayHit;
  return std::max(enter, 0.0);
}

double circle_ray_entry(const PlacedBody& circle, const Eigen::Vector2d& origin, const Eigen::Vector2d& direction) {
  const Eigen::Vector2d from_centre = origin - circle.centre;
  const double along = from_centre.dot(direction);
  const double outside = from_centre.squaredNorm() - circle.half_x * circle.half_x;
  if (outside <= 0.0) return 0.0;
  if (along > 0.0) return kNoRayHit;  // outside and heading away
  const double discriminant = along * along - outside;
  if (discriminant < 0.0) return kNoRayHit;
  // The smaller root -along - sqrt(disc), written so that a far origin
  // does not subtract two nearly equal numbers.
  return outside / (-along + std::sqrt(discriminant));
}

// Half the extent of a box's projection on a unit axis.
double box_projection_radius(const PlacedBody& box, const Eigen::Vector2d& axis) {
  return box.half_x * std::abs(axis.x() * box.cos_yaw + axis.y() * box.sin_yaw) +
         box.half_y * std::abs(-axis.x() * box.sin_yaw + axis.y() * box.cos_yaw);
}

bool boxes_overlap(const PlacedBody& a, const PlacedBody& b) {
  const Eigen::Vector2d between = b.centre - a.centre;
  // Separating axis theorem: the four edge normals are the only candidates.
  const Eigen::Vector2d axes[4] = {
      {a.cos_yaw, a.sin_yaw}, {-a.sin_yaw, a.cos_yaw}, {b.cos_yaw, b.sin_yaw}, {-b.sin_yaw, b.cos_yaw}};
  for (const Eigen::Vector2d& axis : axes) {
    if (std::abs(between.dot(axis)) >= box_projection_radius(a, axis) + box_projection_radius(b, axis)) return false;
  }
  return true;
}

bool box_overlaps_circle(const PlacedBody& box, const PlacedBody& circle) {
  const Eigen::Vector2d local = box.to_local(circle.centre);
  const Eigen::Vector2d nearest{std::clamp(local.x(), -box.half_x, box.half_x),
                                std::clamp(local.y(), -box.half_y, box.half_y)};
  return (local - nearest).squaredNorm() < circle.half_x * circle.half_x;
}

}  // namespace

PlacedBody place_body(const Body& body, const geometry::Pose2& body_pose) {
  PlacedBody placed;
  placed.centre = body_pose.translation();
  placed.cos_yaw = std::cos(body_pose.yaw);
  placed.sin_yaw = std::sin(body_pose.yaw);
  placed.circle = body.shape == Shape::circle;
  if (placed.circle) {
    placed.half_x = placed.half_y = std::abs(body.size.x()) / 2.0;
    placed.bounding_radius = placed.half_x;
  } else {
    placed.half_x = std::abs(body.size.x()) / 2.0;
    placed.half_y = std::abs(body.size.y()) / 2.0;
    placed.bounding_radius = std::hypot(placed.half_x, placed.half_y);
  }
  return placed;
}

PlacedBody cell_body(const Eigen::Vector2d& low, const Eigen::Vector2d& high) {
  PlacedBody cell;
  cell.centre = (low + high) / 2.0;
  cell.half_x = (high.x() - low.x()) / 2.0;
  cell.half_y = (high.y() - low.y()) / 2.0;
  cell.bounding_radius = std::hypot(cell.half_x, cell.half_y);
  return cell;
}

double ray_entry(const PlacedBody& body, const Eigen::Vector2d& origin, const Eigen::Vector2d& direction) {
  return body.circle ? circle_ray_entry(body, origin, direction) : box_ray_entry(body, origin, direction);
}

bool bodies_overlap(const PlacedBody& a, const PlacedBody& b) {
  const double reach = a.bounding_radius + b.bounding_radius;
  if ((a.centre - b.centre).squaredNorm() >= reach * reach) return false;
  if (a.circle && b.circle) return true;  // the bounding circles are the bodies
  if (a.circle) return box_overlaps_circle(b, a);
  if (b.circle) return box_overlaps_circle(a, b);
  return boxes_overlap(a, b);
}

bool body_contains(const PlacedBody& body, const Eigen::Vector2d& point) {
  if (body.circle) return (point - body.centre).squaredNorm() <= body.half_x * body.half_x;
  const Eigen::Vector2d local = body.to_local(point);
  return std::abs(local.x()) <= body.half_x && std::abs(local.y()) <= body.half_y;
}

}  // namespace playerkit::sim
