#include "client/typed/bumper.hpp"

#include <algorithm>

#include "protocol/si_units.hpp"

namespace playerkit::client {

BumperState to_si(const protocol::BumperData& data) {
  const std::size_t n = std::min<std::size_t>(data.bumper_count, data.bumpers.size());
  BumperState state;
  for (std::size_t i = 0; i < n; ++i) state.pressed.push_back(data.bumpers[i] != 0);
  return state;
}

std::vector<BumperDefinition> to_si(const protocol::BumperGeom& geom) {
  using protocol::WireUnit;
  const std::size_t n = std::min<std::size_t>(geom.bumper_count, geom.bumper_def.size());
  std::vector<BumperDefinition> out;
  out.reserve(n);
  for (std::size_t i = 0; i < n; ++i) {
    const auto& d = geom.bumper_def[i];
    out.push_back({planar_pose({d.x_offset, d.y_offset, d.th_offset}),
                   protocol::to_si(WireUnit::kMillimetre, d.length), protocol::to_si(WireUnit::kMillimetre, d.radius)});
  }
  return out;
}

}  // namespace playerkit::client
