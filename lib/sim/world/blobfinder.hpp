#pragma once
// A colour blob finder in the scene: image_width rays across `fov`; each
// run of adjacent rays hitting models of one colour that is a channel
// becomes a blob (the image's left is the fov's left, +bearing).

#include "algorithms/geometry/pose2.hpp"
#include "sim/world/model_spec.hpp"
#include "sim/world/readings.hpp"
#include "sim/world/scene.hpp"

namespace playerkit::sim {

// `camera_pose`: global pose of the camera, including a ptz's pan. `fov`:
// the ptz's zoom when it sits on one, else spec.fov. Leaves `time` 0.
[[nodiscard]] BlobScan find_blobs(const Scene& scene, const BlobfinderSpec& spec, const geometry::Pose2& camera_pose,
                                  double fov, ModelId own_root);

}  // namespace playerkit::sim
