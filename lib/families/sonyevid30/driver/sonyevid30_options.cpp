#include "families/sonyevid30/driver/sonyevid30_options.hpp"

#include <climits>

#include "core/option_reader.hpp"
#include "links/port_option.hpp"

namespace playerkit::drivers::sonyevid30 {

const core::OptionSchema& sonyevid30_option_schema() {
  static const core::OptionSchema schema{
      links::port_option("/dev/ttyS2").doc("the camera's serial port (9600 baud), or tcp:HOST:PORT"),
      // Plain numbers, not angles: 1.5 converted them with the file's angle
      // unit and then cast to int, so `fov [3 30]` in degrees became [0 0]
      // (a crash), and only a radians file gave 3 and 30. Both forms mean
      // degrees here, as the manual says.
      core::OptionSpec::tuple("fov", {core::OptionType::number, core::OptionType::number}, {3.0, 30.0})
          .unit("deg")
          .doc("the fields of view at full tele and full wide, in degrees whatever unit_angle says"),
      core::OptionSpec::integer("movement", 0, 0, INT_MAX)
          .doc("non-zero: pan and tilt driven toward the demand (drive commands) instead of absolute targets"),
  };
  return schema;
}

Sonyevid30Settings read_sonyevid30_settings(const config::Section& section) {
  const core::OptionReader options(section, "sonyevid30", sonyevid30_option_schema());
  Sonyevid30Settings settings;
  settings.port = options.text("port");
  settings.fov = {.tele = options.element("fov", 0), .wide = options.element("fov", 1)};
  if (!(settings.fov.tele > 0) || !(settings.fov.wide > settings.fov.tele) || settings.fov.wide > 180) {
    options.fail({"fov"}, "must be [tele wide] with 0 < tele < wide <= 180 degrees");
  }
  settings.movement = options.integer("movement") != 0;
  return settings;
}

}  // namespace playerkit::drivers::sonyevid30
