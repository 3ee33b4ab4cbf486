#pragma once
// Test support: a gpsd regression log (tests/data/gpsd-garmin, PROVENANCE.md
// there) and the fixes gpsd reports from it (its `.chk`, JSON lines), for
// the tracker's and the driver's tests.

#include <cmath>
#include <filesystem>
#include <fstream>
#include <optional>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

namespace playerkit::hardware::garminnmea::gpsd_check_test_support {

inline std::filesystem::path data_dir() { return std::filesystem::path(PLAYERKIT_TEST_DATA_DIR) / "gpsd-garmin"; }

// What gpsd reports after a log line: a TPV with a position.
struct GpsdFix {
  std::optional<int> time_of_day;  // seconds since midnight; gpsd's dates are rewritten, its times are not
  double latitude = 0;
  double longitude = 0;
  std::optional<double> altitude;  // altMSL
};

// The sentences of a log, comments and blank lines left out.
inline std::vector<std::string> log_sentences(const std::string& name) {
  std::ifstream in(data_dir() / name);
  std::vector<std::string> lines;
  for (std::string line; std::getline(in, line);) {
    if (!line.empty() && line.back() == '\r') line.pop_back();
    if (!line.empty() && line[0] == '$') lines.push_back(line);
  }
  return lines;
}

inline std::vector<GpsdFix> gpsd_fixes(const std::string& name) {
  std::ifstream in(data_dir() / (name + ".chk"));
  std::vector<GpsdFix> fixes;
  for (std::string line; std::getline(in, line);) {
    if (line.empty() || line[0] != '{') continue;
    const auto object = nlohmann::json::parse(line);
    if (object.value("class", "") != "TPV" || !object.contains("lat") || object.value("mode", 0) < 2) continue;
    GpsdFix fix{.time_of_day = std::nullopt,
                .latitude = object["lat"].get<double>(),
                .longitude = object["lon"].get<double>(),
                .altitude = std::nullopt};
    if (object.contains("time")) {
      const std::string time = object["time"].get<std::string>();  // 2021-01-20T22:53:08.000Z
      fix.time_of_day = std::stoi(time.substr(11, 2)) * 3600 + std::stoi(time.substr(14, 2)) * 60 +
                        static_cast<int>(std::lround(std::stod(time.substr(17, 6))));
    }
    if (object.contains("altMSL")) fix.altitude = object["altMSL"].get<double>();
    fixes.push_back(fix);
  }
  return fixes;
}

// Degrees in the wire's unit, 1/60 arc-second.
inline long wire_angle(double degrees) { return std::lround(degrees * 216000.0); }

}  // namespace playerkit::hardware::garminnmea::gpsd_check_test_support
