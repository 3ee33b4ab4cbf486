#include "families/sick/sick_emulator_kinds.hpp"

#include "emulators/emulator_option_reader.hpp"
#include "families/sick/emulator/sick_emulator_options.hpp"
#include "families/sick/emulator/sick_lms200_emulator.hpp"
#include "families/sick/emulator/sick_pls_emulator.hpp"

namespace playerkit::families {

namespace {

std::vector<emulators::EmulatorOptionDoc> laser_options(const char* max_range) {
  return {
      {"pose", "0,0,0", "where the laser stands in the map: x,y,yaw in m, m, deg (alone)"},
      {"mount", "0,0,0", "where the laser sits on the emulated robot: x,y,yaw in m, m, deg"},
      {"noise", "0", "standard deviation of the range noise, m"},
      {"seed", "1", "seed of the noise"},
      {"max_range", max_range, "longest range measured, m (what a beam that meets nothing reads)"},
      {"baud", "9600", "the line speed at power-up: 9600, 19200, 38400 or 500000"},
      {"model_baud", "1", "1: bytes sent at another speed than the laser's are line noise; 0: any speed works"},
  };
}

// What both models share: where the laser is, its noise, its line.
emulators::SickEmulatorOptions laser_settings(const emulators::EmulatorOptionReader& options,
                                              const emulators::EmulatorWorld& world) {
  emulators::SickEmulatorOptions settings;
  settings.map = world.map;
  if (world.carrier_pose) {
    if (options.has("pose")) {
      options.fail("pose", "this laser rides on the emulated robot; say where with mount=x,y,yaw");
    }
    const geometry::Pose2 mount = options.pose("mount", {});
    settings.pose_source = [carrier = world.carrier_pose, mount] { return carrier().compose(mount); };
  } else {
    if (options.has("mount")) options.fail("mount", "no robot is emulated to carry the laser; use pose=x,y,yaw");
    settings.pose = options.pose("pose", {});
  }
  settings.range_noise_sigma_m = options.number("noise", 0.0, 0.0, 1.0);
  settings.noise_seed = static_cast<std::uint64_t>(options.integer("seed", 1, 0, 2147483647));
  if (options.has("max_range")) settings.max_range_m = options.number("max_range", 8.0, 0.01, 81.91);
  settings.power_up_baud = options.integer("baud", 9600, 1, 4000000);
  if (settings.power_up_baud != 9600 && settings.power_up_baud != 19200 && settings.power_up_baud != 38400 &&
      settings.power_up_baud != 500000) {
    options.fail("baud", "a SICK laser runs at 9600, 19200, 38400 or 500000");
  }
  settings.model_baud_rates = options.flag("model_baud", true);
  return settings;
}

}  // namespace

emulators::EmulatorKind sicklms200_emulator_kind() {
  auto options = laser_options("8.191");
  options.push_back({"type", "LMS200;30106", "the type text the laser reports (at most 20 characters)"});
  return {
      .name = "sicklms200",
      .summary = "a SICK LMS 200 laser range-finder (9600 baud at power-up, 180 deg, mm)",
      .interface_name = "laser",
      .driver = "sicklms200",
      .mount = emulators::EmulatorMount::rider,
      .options = std::move(options),
      .make =
          [](const emulators::EmulatorOptionReader& reader, const emulators::EmulatorWorld& world) {
            auto settings = laser_settings(reader, world);
            if (reader.has("type")) settings.type = reader.text("type", "");
            return std::unique_ptr<emulators::DeviceEmulator>(
                std::make_unique<emulators::SickLms200Emulator>(settings));
          },
  };
}

emulators::EmulatorKind sickpls_emulator_kind() {
  return {
      .name = "sickpls",
      .summary = "a SICK PLS laser scanner (9600 baud at power-up, 180 deg at 0.5 deg, cm)",
      .interface_name = "laser",
      .driver = "sickpls",
      .mount = emulators::EmulatorMount::rider,
      .options = laser_options("81.91"),
      .make =
          [](const emulators::EmulatorOptionReader& reader, const emulators::EmulatorWorld& world) {
            return std::unique_ptr<emulators::DeviceEmulator>(
                std::make_unique<emulators::SickPlsEmulator>(laser_settings(reader, world)));
          },
  };
}

}  // namespace playerkit::families
