#include "families/flockofbirds/flockofbirds_emulator_kind.hpp"

#include <fstream>
#include <sstream>
#include <stdexcept>

#include "emulators/emulator_option_reader.hpp"
#include "families/flockofbirds/emulator/flock_emulator.hpp"

namespace playerkit::families {

namespace {

std::string file_text(const emulators::EmulatorOptionReader& reader, const std::string& path) {
  std::ifstream file(path, std::ios::binary);
  if (!file) reader.fail("trajectory", "cannot read the file");
  std::ostringstream text;
  text << file.rdbuf();
  return text.str();
}

}  // namespace

emulators::EmulatorKind flockofbirds_emulator_kind() {
  return {
      .name = "flockofbirds",
      .summary = "an Ascension Flock of Birds 6-DOF tracker (one bird, binary records, 115200 baud)",
      .interface_name = "position3d",
      .driver = "flockofbirds",
      .mount = emulators::EmulatorMount::standalone,
      .options =
          {
              {"trajectory", "built-in", "a file of poses, one a line: seconds x y z (mm) azimuth elevation roll (deg)"},
              {"loop", "1", "1: the trajectory starts again after its last pose; 0: the last pose holds"},
              {"scaling", "36", "position full scale in inches: 36 or 72"},
              {"rate", "100", "records a second while streaming"},
              {"baud", "115200", "the bird's line speed: bytes at another speed are noise to it"},
          },
      .make =
          [](const emulators::EmulatorOptionReader& reader, const emulators::EmulatorWorld&) {
            emulators::FlockEmulatorOptions options;
            const std::string trajectory = reader.text("trajectory", "built-in");
            if (trajectory != "built-in") {
              const std::string text = file_text(reader, trajectory);
              try {
                options.trajectory = emulators::BirdTrajectory::parse(text, reader.flag("loop", true));
              } catch (const std::invalid_argument& e) {
                reader.fail("trajectory", e.what());
              }
            }
            const int inches = reader.integer("scaling", 36, 36, 72);
            if (inches != 36 && inches != 72) reader.fail("scaling", "expected 36 or 72");
            options.scaling = inches == 36 ? hardware::flockofbirds::PositionScaling::inches_36
                                           : hardware::flockofbirds::PositionScaling::inches_72;
            options.rate_hz = reader.number("rate", 100, 1, 1000);
            options.baud = reader.integer("baud", 115200, 2400, 115200);
            return std::unique_ptr<emulators::DeviceEmulator>(
                std::make_unique<emulators::FlockEmulator>(std::move(options)));
          },
  };
}

}  // namespace playerkit::families
