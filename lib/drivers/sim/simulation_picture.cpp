#include "drivers/sim/simulation_picture.hpp"

#include <utility>

#include "sim/render/world_png.hpp"

namespace playerkit::drivers::sim {

namespace render = playerkit::sim::render;

SimulationPicture::SimulationPicture(PictureSettings settings)
    : settings_(std::move(settings)), trails_(settings_.trails) {}

void SimulationPicture::record(const playerkit::sim::World& world) { trails_.record(world); }

render::WorldSnapshot SimulationPicture::snapshot(const playerkit::sim::World& world) const {
  return render::take_snapshot(world, &trails_);
}

void SimulationPicture::write(const render::WorldSnapshot& snapshot) {
  const render::Picture picture = render::draw_world(snapshot, settings_.options);
  std::lock_guard lock(write_mutex_);
  render::write_png(settings_.file, picture, settings_.inputs);
}

}  // namespace playerkit::drivers::sim
