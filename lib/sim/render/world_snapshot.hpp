#pragma once
// What a picture of a world shows, copied out of a sim::World at one
// instant as plain geometry in world metres: bodies, the latest sensor rays,
// fiducial sightings and trails. Taking it is cheap (no pixels), so a
// serving thread can take it with the world locked and draw it after
// unlocking (world_picture.hpp).

#include <Eigen/Core>

#include <vector>

#include "algorithms/geometry/pose2.hpp"
#include "algorithms/grid/occupancy_grid.hpp"
#include "sim/render/trails.hpp"
#include "sim/world/model_spec.hpp"
#include "sim/world/world.hpp"

namespace playerkit::sim::render {

struct SnapshotBody {
  ModelId model = kNoModel;
  Shape shape = Shape::rectangle;
  Eigen::Vector2d size{0.0, 0.0};  // rectangle x by y; a circle's diameter in x
  geometry::Pose2 pose{};          // the body's centre and heading, global
  Rgb color{};
  bool robot = false;  // a position model: its heading is drawn
};

enum class RayKind { laser, sonar };

// One reading of a laser sample or a sonar transducer: from the sensor to
// where the ray ended (its range_max when it met nothing).
struct SnapshotRay {
  RayKind kind = RayKind::laser;
  Eigen::Vector2d from{0.0, 0.0};
  Eigen::Vector2d to{0.0, 0.0};
  bool hit = false;  // ended on something, before range_max
};

// A fiducial a finder saw: from the finder to the sighted centre.
struct SnapshotSighting {
  Eigen::Vector2d from{0.0, 0.0};
  Eigen::Vector2d to{0.0, 0.0};
  int id = 0;
};

struct SnapshotTrail {
  ModelId model = kNoModel;
  Rgb color{};  // the model's own
  std::vector<Eigen::Vector2d> points;
};

struct WorldSnapshot {
  double time = 0.0;  // simulation seconds
  // The world's own map: a World never changes it, and it lives (at the
  // same address, also when the World is moved) as long as the World does.
  const grid::OccupancyGrid* map = nullptr;
  std::vector<SnapshotBody> bodies;  // present models with a body, in id order
  std::vector<SnapshotRay> rays;     // the latest reading of every laser and sonar that has one
  std::vector<SnapshotSighting> sightings;
  std::vector<SnapshotTrail> trails;
};

// Every sensor's latest reading, from where the sensor is now: a reading is
// at most one interval old while the sensor is read; one taken before its
// last client left stays as it was (the robot stopped then too, unless
// teleported). `trails` may be null.
[[nodiscard]] WorldSnapshot take_snapshot(const World& world, const Trails* trails = nullptr);

}  // namespace playerkit::sim::render
