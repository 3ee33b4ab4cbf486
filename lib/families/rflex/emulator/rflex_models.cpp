#include "families/rflex/emulator/rflex_models.hpp"

namespace playerkit::emulators::rflex {

const std::vector<RflexModel>& rflex_models() {
  static const std::vector<RflexModel> models{
      {.name = "b21r",
       .description = "RWI B21r: 24 sonars on three boards, 14 bump panels, three IR banks",
       .odo_distance_conversion = 103,
       .odo_angle_conversion = 35000,
       .range_distance_conversion = 1.476,
       .radius = 0.26,
       .wheelbase = 0.4,
       .max_speed = 1.0,
       .max_turn_rate = 2.0,
       .sonars_in_bank = {8, 8, 8},
       .bumper_panels = 14,
       .ir_banks = 3,
       .battery_centivolts = 2640},
      {.name = "atrvjr",
       .description = "iRobot ATRV-Jr: 16 sonars on two boards, no bumpers, no IR",
       .odo_distance_conversion = 90.81,
       .odo_angle_conversion = 37000,
       .range_distance_conversion = 1.476,
       .radius = 0.4,
       .wheelbase = 0.5,
       .max_speed = 1.0,
       .max_turn_rate = 1.5,
       .sonars_in_bank = {8, 8},
       .bumper_panels = 0,
       .ir_banks = 0,
       .battery_centivolts = 2450},
      {.name = "magellan",
       .description = "iRobot Magellan Pro: 16 sonars, 16 IR, 16 bump panels (units of this emulator's choosing)",
       .odo_distance_conversion = 60,
       .odo_angle_conversion = 20000,
       .range_distance_conversion = 1.476,
       .radius = 0.2,
       .wheelbase = 0.3,
       .max_speed = 1.0,
       .max_turn_rate = 2.5,
       .sonars_in_bank = {8, 8},
       .bumper_panels = 16,
       .ir_banks = 2,
       .battery_centivolts = 1260},
  };
  return models;
}

const RflexModel* find_rflex_model(std::string_view name) {
  for (const RflexModel& model : rflex_models()) {
    if (model.name == name) return &model;
  }
  return nullptr;
}

}  // namespace playerkit::emulators::rflex
