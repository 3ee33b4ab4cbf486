#include "families/sick/driver/sick_driver_docs.hpp"

#include "families/sick/driver/sick_driver_settings.hpp"

namespace playerkit::drivers::sick_laser {

core::DriverDoc sick_driver_doc(hardware::sick::Model model) {
  const bool lms = model == hardware::sick::Model::lms200;
  core::DriverDoc doc;
  doc.manual_section = lms ? "7.39" : "7.40";
  doc.needs_hardware = true;
  doc.schema = sick_option_schema(model);
  doc.requests = {
      "GET_GEOM: pose and size from the options",
      "GET_CONFIG: min/max angle, resolution, range_res, intensity in force",
      lms ? "SET_CONFIG: reconfigures the laser (variant, unit, reflector levels, subrange); NACK when the "
            "combination is impossible or the laser refuses, the previous scan kept"
          : "SET_CONFIG: angles (subrange), resolution 50/100, range_res; NACK when impossible or refused",
      "anything else: NACK",
  };
  doc.example = lms ? "laser:0 ( driver \"sicklms200\" port \"/dev/ttyUSB0\" rate 38400 resolution 50 range_res 1 )"
                    : "laser:0 ( driver \"sickpls\" port \"/dev/ttyUSB0\" rate 38400 )";
  return doc;
}

}  // namespace playerkit::drivers::sick_laser
