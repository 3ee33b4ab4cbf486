#pragma once
// The simulator's drivers (lib/drivers/sim): devices of a simulated world,
// under the names Player 1.5 showed for them.
//
//  * The world file's type words, as `player -s` (Stage 1.3) named every
//    device of a world: position (omniposition), laser, sonar,
//    fiducialfinder (lbd), blobfinder (vision), ptz, gripper, power, truth;
//    and Stage 3/4's ranger and fiducial. Option `model`: the model's name.
//  * 1.5's Gazebo drivers, for Gazebo-era configurations: gz_position,
//    gz_laser, gz_sonar (and gz_sonars, its name in 1.5's code), gz_fiducial,
//    gz_truth, gz_gripper, gz_ptz, gz_power. Option `gz_id`: the model's name.
//  * simulation: run control (pause, step) for scripts.
//
// Every one serves the world `player-serve -s WORLD` loaded
// (simulation_driver_specs); the built-in specs, registered without a world,
// refuse to be created, saying so. Every simulated device claims the server
// clock with the simulation clock.

#include <memory>
#include <vector>

#include "core/driver_registry.hpp"
#include "drivers/sim/simulation_source.hpp"

namespace playerkit::drivers {

// Every simulated driver, serving `source`'s world (null: none, an error at
// creation).
std::vector<core::DriverSpec> simulation_driver_specs(std::shared_ptr<sim::SimulationSource> source);

// The same one by one, without a world, for the built-in list.
core::DriverSpec sim_position_driver_spec();
core::DriverSpec sim_omniposition_driver_spec();
core::DriverSpec sim_laser_driver_spec();
core::DriverSpec sim_ranger_driver_spec();
core::DriverSpec sim_sonar_driver_spec();
core::DriverSpec sim_fiducialfinder_driver_spec();
core::DriverSpec sim_lbd_driver_spec();
core::DriverSpec sim_fiducial_driver_spec();
core::DriverSpec sim_blobfinder_driver_spec();
core::DriverSpec sim_vision_driver_spec();
core::DriverSpec sim_ptz_driver_spec();
core::DriverSpec sim_gripper_driver_spec();
core::DriverSpec sim_power_driver_spec();
core::DriverSpec sim_truth_driver_spec();
core::DriverSpec sim_simulation_driver_spec();
core::DriverSpec gz_position_driver_spec();
core::DriverSpec gz_laser_driver_spec();
core::DriverSpec gz_sonar_driver_spec();
core::DriverSpec gz_sonars_driver_spec();
core::DriverSpec gz_fiducial_driver_spec();
core::DriverSpec gz_truth_driver_spec();
core::DriverSpec gz_gripper_driver_spec();
core::DriverSpec gz_ptz_driver_spec();
core::DriverSpec gz_power_driver_spec();

}  // namespace playerkit::drivers
