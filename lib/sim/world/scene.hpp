#pragma once
// What sensors may ask of the world at one instant: the static map and the
// models' bodies where they stand now. The world (world.hpp) keeps one
// Scene up to date as models move; sensors (laser.hpp, sonar.hpp, ...) are
// functions of a const Scene&.
//
// 2-D throughout: Stage 3/4 test rays against heights (a laser on a Pioneer
// sees over other Pioneers' bodies); here every body is as tall as the
// walls, so rays see every body they cross (docs/compatibility.md).

#include <Eigen/Core>

#include <functional>
#include <span>
#include <vector>

#include "algorithms/geometry/pose2.hpp"
#include "algorithms/grid/occupancy_grid.hpp"
#include "algorithms/grid/square_caster.hpp"
#include "sim/world/body_index.hpp"
#include "sim/world/model_spec.hpp"

namespace playerkit::sim {

// One model as sensors see it.
struct SceneModel {
  ModelId id = kNoModel;
  ModelId root = kNoModel;       // its top-level ancestor (itself at top level)
  geometry::Pose2 pose{};        // the model's global pose
  geometry::Pose2 body_pose{};   // the body's centre: pose composed with body.offset
  Body body{};
  Rgb color{};
  Returns returns{};
  bool present = true;           // false once consumed by a gripper
};

struct RayHit {
  double range = 0.0;        // max_range when nothing was met
  ModelId model = kNoModel;  // the model hit; kNoModel for a wall or nothing
  bool wall = false;         // stopped by an occupied map cell
};

// Which models a ray may stop on, besides walls (which always stop it).
using ModelFilter = std::function<bool(const SceneModel&)>;

// One ray of a sensor's many: `direction` is a unit vector.
struct SceneRay {
  Eigen::Vector2d origin = Eigen::Vector2d::Zero();
  Eigen::Vector2d direction = Eigen::Vector2d::UnitX();
};

class Scene {
 public:
  Scene() = default;
  // Occupied cells are walls; free and unknown cells are open. The map
  // also sets the ray and collision resolution.
  explicit Scene(grid::OccupancyGrid map);

  [[nodiscard]] const grid::OccupancyGrid& map() const { return map_; }
  // How far around `point` (in x and in y) the map has no wall: a body
  // within that square needs no cell-by-cell test. 0 when not known.
  [[nodiscard]] double walls_clear_around(const Eigen::Vector2d& point) const { return walls_.clear_around(point); }

  // The first wall cell or model body a ray meets. Models of the tree of
  // `ignore_root` (the sensor's own robot) are never hit; others only where
  // `stops` says so (nullptr: those with a body and ranger return >= 0).
  [[nodiscard]] RayHit cast(const Eigen::Vector2d& origin, double angle, double max_range,
                            ModelId ignore_root, const ModelFilter& stops = nullptr) const;
  // The same along `direction`, the unit vector (cos angle, sin angle): a
  // sensor that turns one vector from ray to ray needs no trigonometry.
  [[nodiscard]] RayHit cast(const Eigen::Vector2d& origin, const Eigen::Vector2d& direction, double max_range,
                            ModelId ignore_root, const ModelFilter& stops = nullptr) const;
  // cast(ray.origin, ray.direction, max_range, ignore_root) for every ray
  // (bodies stop them by the default rule), into `hits` (as many as rays;
  // std::invalid_argument otherwise). The same answers, in less time than
  // one by one: the walls of all rays are walked together.
  void cast_all(std::span<const SceneRay> rays, double max_range, ModelId ignore_root,
                std::span<RayHit> hits) const;
  // cast_all() for a fan: rays from one origin (a laser's scan), given by
  // their unit directions. The same answers, in less time: the walls of a
  // fan are walked with its origin's part done once.
  void cast_fan(const Eigen::Vector2d& origin, std::span<const Eigen::Vector2d> directions, double max_range,
                ModelId ignore_root, std::span<RayHit> hits) const;

  // Every model, indexed by id.
  [[nodiscard]] std::span<const SceneModel> models() const { return models_; }
  [[nodiscard]] const SceneModel& model(ModelId id) const { return models_.at(static_cast<std::size_t>(id)); }

  // Models whose body comes within `radius` of `centre` (a broad phase for
  // fiducial finders and collisions; may return a few more).
  [[nodiscard]] std::vector<ModelId> models_near(const Eigen::Vector2d& centre, double radius) const;
  // The same, in id order, into `near` (cleared first): no allocation once
  // it has grown, for queries every step.
  void models_near(const Eigen::Vector2d& centre, double radius, std::vector<ModelId>& near) const;

  // Kept by the world as models are added, move or vanish.
  void add(SceneModel model);
  void update(ModelId id, const geometry::Pose2& pose);
  void set_present(ModelId id, bool present);
  // A model carried by a gripper joins the carrier's tree (and leaves it).
  void set_root(ModelId id, ModelId root);

 private:
  // The walk through the walls of a ray that may start off the map, as
  // the caster's ray (empty when it never meets the map) and the distance
  // to add to its answer.
  struct WallWalk {
    bool on_map = false;
    grid::SquareCaster::Ray ray;
    double offset = 0.0;
  };
  // Whether `point` lies on the map (its cells' half-open extent).
  [[nodiscard]] bool on_map(const Eigen::Vector2d& point) const;
  [[nodiscard]] WallWalk wall_walk(const Eigen::Vector2d& origin, const Eigen::Vector2d& direction,
                                   double max_range) const;
  // cast_all's bodies (by the default rule): lowers each hit to the nearest
  // body its ray enters before it.
  void add_bodies(std::span<const SceneRay> rays, double max_range, ModelId ignore_root,
                  std::span<RayHit> hits) const;
  // add_bodies for many rays: the bodies filed by direction.
  void nearest_bodies(std::span<const SceneRay> rays, ModelId ignore_root, std::span<RayHit> hits) const;
  // Lowers `hit` to the nearest body the ray enters before it.
  void nearest_body(const Eigen::Vector2d& origin, const Eigen::Vector2d& direction, ModelId ignore_root,
                    const ModelFilter& stops, RayHit& hit) const;

  // Whether a ray of `ignore_root`'s tree, stopped by the default rule, may
  // meet any body at all: a lone robot's laser then skips the broad phase.
  [[nodiscard]] bool visible_bodies_beyond(ModelId ignore_root) const;
  // Keeps the counts below as a model appears (+1) or goes (-1).
  void count_visible(const SceneModel& model, int change);

  grid::OccupancyGrid map_;
  Eigen::Vector2d map_low_ = Eigen::Vector2d::Zero(), map_high_ = Eigen::Vector2d::Zero();  // the map's extent
  grid::SquareCaster walls_;
  // Bodies a default ray meets (present, solid, ranger return >= 0): in
  // all, and per top-level tree (indexed by root id).
  int visible_bodies_ = 0;
  std::vector<int> visible_bodies_by_root_;
  std::vector<SceneModel> models_;
  BodyIndex index_;  // the broad phase of cast() and models_near()
};

}  // namespace playerkit::sim
