#include "families/garminnmea/garminnmea_emulator_kind.hpp"

#include <cstdio>
#include <fstream>

#include "emulators/emulator_option_reader.hpp"
#include "families/garminnmea/emulator/garminnmea_emulator.hpp"

namespace playerkit::families {

namespace {

using emulators::EmulatorOptionReader;

int line_speed(const EmulatorOptionReader& options) {
  const int baud = options.integer("baud", 4800, 0, 115200);
  if (baud != 0 && baud != 4800 && baud != 9600 && baud != 19200 && baud != 38400 && baud != 57600 && baud != 115200) {
    options.fail("baud", "a receiver runs at 4800, 9600, 19200, 38400, 57600 or 115200 (0: any speed)");
  }
  return baud;
}

std::unique_ptr<emulators::DeviceEmulator> playing(const EmulatorOptionReader& options) {
  const std::string path = options.text("log", "");
  std::ifstream in(path);
  if (!in) options.fail("log", "cannot read it");
  emulators::GarminNmeaPlayback playback;
  for (std::string line; std::getline(in, line);) {
    if (!line.empty() && line.back() == '\r') line.pop_back();
    playback.sentences.push_back(line);
  }
  playback.loop = options.flag("loop", false);
  playback.baud = line_speed(options);
  playback.rate = options.number("rate", 1.0, 0.01, 1000.0);
  playback.start = std::chrono::duration_cast<emulators::Duration>(
      std::chrono::duration<double>(options.number("start", 0.0, 0.0, 60.0)));
  for (const char* generating : {"origin", "altitude", "pose", "mount", "utc", "period", "decimals", "fix"}) {
    if (options.has(generating)) options.fail(generating, "a log played back says that itself");
  }
  return std::make_unique<emulators::GarminNmeaEmulator>(std::move(playback));
}

std::unique_ptr<emulators::DeviceEmulator> generating(const EmulatorOptionReader& options,
                                                      const emulators::EmulatorWorld& world) {
  emulators::GarminNmeaGenerated settings;
  for (const char* playing_only : {"loop", "rate", "start"}) {
    if (options.has(playing_only)) options.fail(playing_only, "only with log=FILE");
  }
  const std::string origin = options.text("origin", "34.020575,-118.28539");
  double latitude = 0, longitude = 0;
  char end = 0;
  if (std::sscanf(origin.c_str(), "%lf,%lf%c", &latitude, &longitude, &end) != 2 || latitude < -80 || latitude > 84 ||
      longitude < -180 || longitude > 180) {
    options.fail("origin", "expected LAT,LON in degrees, latitude from -80 to 84 (UTM's reach), longitude -180 to 180");
  }
  settings.origin_latitude = latitude;
  settings.origin_longitude = longitude;
  settings.altitude = options.number("altitude", settings.altitude, -1000, 20000);
  if (world.carrier_pose) {
    if (options.has("pose")) options.fail("pose", "this receiver rides on the emulated robot; say where with mount=x,y,yaw");
    const geometry::Pose2 mount = options.pose("mount", {});
    settings.pose_source = [carrier = world.carrier_pose, mount] { return carrier().compose(mount); };
  } else {
    if (options.has("mount")) options.fail("mount", "no robot is emulated to carry the receiver; use pose=x,y,yaw");
    const geometry::Pose2 pose = options.pose("pose", {});
    settings.pose_source = [pose] { return pose; };
  }
  const std::string utc = options.text("utc", "2004-06-15T12:35:19");
  int hour = 0, minute = 0, second = 0;
  if (std::sscanf(utc.c_str(), "%d-%d-%dT%d:%d:%d%c", &settings.date.year, &settings.date.month, &settings.date.day,
                  &hour, &minute, &second, &end) != 6 ||
      settings.date.year < 1980 || settings.date.year > 2079 || settings.date.month < 1 || settings.date.month > 12 ||
      settings.date.day < 1 || settings.date.day > 31 || hour > 23 || minute > 59 || second > 59 || hour < 0 ||
      minute < 0 || second < 0) {
    options.fail("utc", "expected YYYY-MM-DDTHH:MM:SS, a year from 1980 to 2079 (NMEA's two digits)");
  }
  settings.start_time_of_day = hour * 3600 + minute * 60 + second;
  settings.period = std::chrono::duration_cast<emulators::Duration>(
      std::chrono::duration<double>(options.number("period", 1.0, 0.05, 60.0)));
  settings.decimals = options.integer("decimals", 6, 1, 7);
  settings.fix = options.flag("fix", true);
  settings.baud = line_speed(options);
  settings.quality = options.integer("quality", 1, 1, 8);
  settings.satellites = options.integer("satellites", 8, 0, 12);
  settings.hdop = options.number("hdop", 0.9, 0.1, 99.9);
  return std::make_unique<emulators::GarminNmeaEmulator>(std::move(settings));
}

}  // namespace

emulators::EmulatorKind garminnmea_emulator_kind() {
  return {
      .name = "garminnmea",
      .summary = "a Garmin NMEA GPS receiver: a recorded log played back, or fixes where the emulated robot is",
      .interface_name = "gps",
      .driver = "garminnmea",
      .mount = emulators::EmulatorMount::rider,
      .options =
          {
              {"log", "", "an NMEA log to play back (lines starting with $), at the pace of its times of day"},
              {"loop", "0", "1: play the log again from the top when it ends"},
              {"rate", "1", "playback speed: 10 plays the log ten times as fast"},
              {"start", "0", "seconds of silence before the log's first sentence"},
              {"origin", "34.020575,-118.28539", "LAT,LON in degrees of the map's (0,0); x is east, y north"},
              {"altitude", "545.4", "the antenna's altitude above mean sea level, m"},
              {"pose", "0,0,0", "where the receiver stands in the map: x,y,yaw in m, m, deg (alone)"},
              {"mount", "0,0,0", "where the antenna sits on the emulated robot: x,y,yaw in m, m, deg"},
              {"utc", "2004-06-15T12:35:19", "the date and UTC time of the first fix"},
              {"period", "1", "seconds between fixes"},
              {"decimals", "6", "decimals of the minutes of latitude and longitude (4: a Geko's 18 cm; 6: 2 mm)"},
              {"fix", "1", "0: the receiver has no fix (GGA quality 0, RMC and GLL status V)"},
              {"quality", "1", "the GGA fix quality: 1 GPS, 2 DGPS"},
              {"satellites", "8", "satellites used, 0 to 12"},
              {"hdop", "0.9", "horizontal dilution of precision"},
              {"baud", "4800", "the line speed: a host that writes at another reads garbage (0: any speed)"},
          },
      .make =
          [](const EmulatorOptionReader& reader, const emulators::EmulatorWorld& world) {
            return reader.has("log") ? playing(reader) : generating(reader, world);
          },
  };
}

}  // namespace playerkit::families
