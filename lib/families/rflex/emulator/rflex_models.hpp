#pragma once
// The robots an emulated RFLEX can be (`player-drivers emulate rflex
// model=...`): their arbitrary units, body and sensors. The B21r's units are
// those of 1.5's b21r_rflex_lms200.cfg and the ATRV-Jr's of
// umass_ATRVJr.cfg (rflex.md §4); the Magellan Pro's units were never
// published, so its row is this emulator's own choice (data/config says so).

#include <string>
#include <string_view>
#include <vector>

namespace playerkit::emulators::rflex {

struct RflexModel {
  std::string name;
  std::string description;
  double odo_distance_conversion = 0.0;    // arb per mm
  double odo_angle_conversion = 0.0;       // arb per rad
  double range_distance_conversion = 1.0;  // sonar arb per mm
  double radius = 0.25;                    // m, the round footprint
  double wheelbase = 0.4;                  // m
  double max_speed = 1.0;                  // m/s
  double max_turn_rate = 2.0;              // rad/s
  std::vector<int> sonars_in_bank;         // transducers on boards 0, 1, ... (16 ids per board)
  int bumper_panels = 0;                   // at DIO addresses 0x40...
  int ir_banks = 0;                        // of 8 sensors each
  unsigned battery_centivolts = 2640;
};

// b21r, atrvjr, magellan.
const std::vector<RflexModel>& rflex_models();
// nullptr for a name not in the table.
const RflexModel* find_rflex_model(std::string_view name);

}  // namespace playerkit::emulators::rflex
