#pragma once
// How wrong an emulated robot's encoders are: systematic and random error,
// applied to each motion step as the wheels would see it. Seeded, so the
// same options and the same calls give the same odometry.

#include <cstdint>

namespace playerkit::emulators::mobile_base {

struct OdometryError {
  double translation_scale = 0.0;        // measured distance = true × (1 + this)
  double rotation_scale = 0.0;           // measured rotation = true × (1 + this)
  double heading_drift_per_metre = 0.0;  // rad of heading error per metre driven
  double translation_noise = 0.0;        // standard deviation, m per √m driven
  double rotation_noise = 0.0;           // standard deviation, rad per √m driven
  std::uint64_t seed = 1;
};

}  // namespace playerkit::emulators::mobile_base
