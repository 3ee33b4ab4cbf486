#include "families/sick/driver/sick_driver_docs.hpp"

namespace playerkit::drivers::sick_laser {

core::DriverDoc sick_driver_doc(hardware::sick::Model model) {
  const bool lms = model == hardware::sick::Model::lms200;
  core::DriverDoc doc;
  doc.manual_section = lms ? "7.39" : "7.40";
  doc.needs_hardware = true;
  doc.options = {
      {"port", "string", "\"/dev/ttyS1\"", "", "the serial port, or tcp:HOST:PORT for a serial-over-network bridge"},
      {"rate", "int", lms ? "38400" : "9600", "baud",
       "the speed the laser is run at: 9600, 38400 or 500000 (500000 needs an adapter that can)"},
      {"delay", "int", "0", "s", "wait before the first telegram (35 for a laser powered when the port opens)"},
      {"resolution", "int", "50", "0.01 deg",
       lms ? "angular step: 25, 50 or 100" : "angular step: 50, or 100 (every second value)"},
  };
  if (lms) {
    doc.options.push_back({"fov", "int", "180 (100 with resolution 25)", "deg",
                           "field of view: 180, or 100 (needed for resolution 25)"});
    doc.options.push_back({"intensity", "int", "1", "",
                           "1: reflector level 0-7 per beam in `intensity`; 0: all zero"});
  }
  doc.options.push_back({"range_res", "int", "1", "",
                         "ranges in mm (1), cm (10) or dm (100)"});
  doc.options.push_back({"min_angle", "angle", "-90 (-50 at fov 100)", "deg", "first beam of the scan"});
  doc.options.push_back({"max_angle", "angle", "90 (50 at fov 100)", "deg", "last beam of the scan"});
  doc.options.push_back({"invert", "int", "0", "", "1 for a laser mounted upside down: beams and angles mirrored"});
  doc.options.push_back({"pose", "tuple", "[0 0 0]", "m m deg", "mounting pose on the robot (GET_GEOM)"});
  doc.options.push_back({"size", "tuple", "[0.15 0.15]", "m m", "the laser's footprint (GET_GEOM)"});
  doc.options.push_back({"reply_timeout", "float", "1.0", "s", "wait for each reply of the laser"});
  doc.options.push_back({"retry_interval", "float", "1.0", "s",
                         "between attempts to reach a laser that went silent or away"});
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
