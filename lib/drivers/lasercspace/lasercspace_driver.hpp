#pragma once
// `lasercspace` (Player 1.5 manual §7.22): a laser device whose ranges are
// another laser's, shortened to the free configuration space of a round
// robot (lib/algorithms/cspace), e.g.
//
//   laser:1 ( driver "lasercspace" laser 0 radius 0.3 )
//
// The source laser is named by its index on the same port, as in 1.5.

#include "core/driver_registry.hpp"

namespace playerkit::drivers {

core::DriverSpec lasercspace_driver_spec();

}  // namespace playerkit::drivers
