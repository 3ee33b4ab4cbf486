#include "sim/world/blobfinder.hpp"

#include <algorithm>
#include <cmath>

namespace playerkit::sim {

namespace {

// Stage's blobfinder sizes every blob as an object this tall (§2.9).
constexpr double kBlobObjectHeight = 0.6;  // m

// The camera sees what is in front of it: anything with a body stops a ray.
bool blocks_camera(const SceneModel& model) { return model.present && model.body.present; }

// A run of adjacent columns that saw one colour, being extended.
struct ColourRun {
  int first_column = -1;  // -1: no run open
  Rgb color{};
  double range_sum = 0.0;
};

}  // namespace

BlobScan find_blobs(const Scene& scene, const BlobfinderSpec& spec, const geometry::Pose2& camera_pose, double fov,
                    ModelId own_root) {
  BlobScan scan;
  scan.image_width = std::max(spec.image_width, 0);
  scan.image_height = std::max(spec.image_height, 0);
  const int width = scan.image_width;
  const int height = scan.image_height;
  if (width == 0 || height == 0) return scan;

  // Channels: the spec's, or (none given) each colour seen, in the order
  // the columns first meet it. Per call, and small.
  std::vector<Rgb> seen_colours;
  const bool every_colour = spec.channels.empty();
  const auto channel_of = [&](const Rgb& color) -> int {
    const std::vector<Rgb>& channels = every_colour ? seen_colours : spec.channels;
    const auto found = std::find(channels.begin(), channels.end(), color);
    if (found != channels.end()) return static_cast<int>(found - channels.begin());
    if (!every_colour) return -1;
    seen_colours.push_back(color);
    return static_cast<int>(seen_colours.size()) - 1;
  };

  // Square pixels: the vertical fov is the horizontal one scaled by the
  // image's aspect, so one row spans what one column does.
  const double radians_per_row = fov / static_cast<double>(width);
  const auto close_run = [&](const ColourRun& run, int end_column) {
    const int channel = channel_of(run.color);
    if (channel < 0) return;
    Blob blob;
    blob.channel = channel;
    blob.color = run.color;
    blob.left = run.first_column;
    blob.right = end_column - 1;
    blob.range = run.range_sum / static_cast<double>(end_column - run.first_column);
    const double half_angle = std::atan2(kBlobObjectHeight / 2.0, blob.range);
    const int half_rows = static_cast<int>(std::min(half_angle / radians_per_row, static_cast<double>(height)));
    blob.top = std::max(height / 2 - half_rows, 0);
    blob.bottom = std::min(height / 2 + half_rows, height - 1);
    blob.x = (blob.left + blob.right) / 2;
    blob.y = (blob.top + blob.bottom) / 2;
    blob.area = (blob.right - blob.left + 1) * (blob.bottom - blob.top + 1);
    scan.blobs.push_back(blob);
  };

  const Eigen::Vector2d origin = camera_pose.translation();
  const double spacing = width > 1 ? fov / static_cast<double>(width - 1) : 0.0;
  const double left_bearing = width > 1 ? fov / 2.0 : 0.0;
  const ModelFilter stops = blocks_camera;
  ColourRun run;
  for (int column = 0; column < width; ++column) {
    // Column 0, the image's left, looks furthest to the left (+bearing).
    const double bearing = left_bearing - spacing * static_cast<double>(column);
    const RayHit hit = scene.cast(origin, camera_pose.yaw + bearing, spec.range, own_root, stops);
    const bool coloured = hit.model != kNoModel && scene.model(hit.model).returns.blob;
    const Rgb color = coloured ? scene.model(hit.model).color : Rgb{};
    if (run.first_column >= 0 && (!coloured || !(color == run.color))) {
      close_run(run, column);
      run.first_column = -1;
    }
    if (!coloured) continue;
    if (run.first_column < 0) run = {.first_column = column, .color = color, .range_sum = 0.0};
    run.range_sum += hit.range;
  }
  if (run.first_column >= 0) close_run(run, width);

  std::stable_sort(scan.blobs.begin(), scan.blobs.end(),
                   [](const Blob& a, const Blob& b) { return a.channel < b.channel; });
  return scan;
}

}  // namespace playerkit::sim
