#include "families/cmucam2/driver/cmucam2_options.hpp"

#include <cmath>

#include "core/option_reader.hpp"
#include "links/port_option.hpp"

namespace playerkit::drivers::cmucam2 {

namespace cam = hardware::cmucam2;

namespace {

std::string color_name(int index) { return "color" + std::to_string(index); }

}  // namespace

const core::OptionSchema& cmucam2_option_schema() {
  static const core::OptionSchema schema = [] {
    core::OptionSchema made{
        links::port_option("/dev/ttyS1")
            .aliases({"devicepath"})
            .doc("the camera's serial port (1.5's devicepath), or tcp:HOST:PORT"),
        core::OptionSpec::integer("num_blobs", 1, 1, kMaxColors).doc("how many colours to track: color0 ... color<n-1>"),
        core::OptionSpec::number("servo_resolution", 0.75, 0.01, 10)
            .unit("deg")
            .doc("degrees per servo position, both servos, around position 128 (ptz)"),
    };
    for (int i = 0; i < kMaxColors; ++i) {
      made.add(core::OptionSpec::tuple(color_name(i), std::vector<core::OptionType>(6, core::OptionType::number),
                                       std::vector<double>(6, 16))
                   .doc(i == 0 ? "[red_min red_max green_min green_max blue_min blue_max], 0 to 255 (the manual's "
                                 "B/G order is wrong)"
                               : "as color0"));
    }
    return made;
  }();
  return schema;
}

Cmucam2Settings read_cmucam2_settings(const config::Section& section, const std::string& driver) {
  const core::OptionReader options(section, driver, cmucam2_option_schema());
  Cmucam2Settings settings;
  settings.port = options.text("port");
  settings.degrees_per_position = options.number("servo_resolution");
  settings.colors.clear();
  const int count = options.integer("num_blobs");
  for (int i = 0; i < count; ++i) {
    const std::string name = color_name(i);
    std::array<int, 6> bounds{};
    for (std::size_t e = 0; e < bounds.size(); ++e) {
      const double value = options.element(name, e);
      if (value < 0 || value > 255 || value != std::floor(value)) {
        options.fail({name}, "bounds must be whole numbers from 0 to 255", e);
      }
      bounds[e] = static_cast<int>(value);
    }
    const cam::ColorBounds color{bounds[0], bounds[1], bounds[2], bounds[3], bounds[4], bounds[5]};
    if (!color.valid()) options.fail({name}, "each minimum must not exceed its maximum");
    settings.colors.push_back(color);
  }
  return settings;
}

}  // namespace playerkit::drivers::cmucam2
