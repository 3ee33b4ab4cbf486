#pragma once
// An emulated Garmin NMEA receiver, written from garminnmea.md §6 ("what a
// faithful emulator must do"), so that Player 1.5's garminnmea driver works
// against it unmodified:
//
//  * it streams from the start, whatever the host does, at any baud rate;
//    bytes from the host (RTCM corrections) are read and ignored;
//  * every cycle (1 s): RMC, GGA, GSA, GSV, PGRME, GLL, PGRMZ, PGRMM, each a
//    telegram of its own, spread over most of the cycle as a receiver at
//    4800 baud keeps the line busy (a listener never waits long for a
//    sentence), CR LF, checksummed, at most 82 characters; GGA has
//    all 14 fields, 2 degree digits of latitude and 3 of longitude, always
//    populated while it has a fix;
//  * the position is where the antenna is in a geo-referenced world: the
//    map's origin at a latitude and longitude, x east and y north, projected
//    back from UTM in the origin's zone, so a robot's path in metres is the
//    same path in UTM metres;
//
//  * at its own line speed (4800): a host that writes at another speed (a
//    probe for another device) reads garbage, as through a real UART; one
//    that has written nothing since it opened the line is taken to listen
//    at the right one;
//
// or it plays a recorded log (lines starting with `$`) at the log's own
// pace: sentences a new time of day apart go out that far apart (divided by
// `rate`), the rest one after another at the line's speed.

#include <cstdint>
#include <deque>
#include <functional>
#include <string>
#include <vector>

#include "algorithms/geometry/pose2.hpp"
#include "emulators/device_emulator.hpp"
#include "families/garminnmea/protocol/nmea_sentences.hpp"

namespace playerkit::emulators {

struct GarminNmeaGenerated {
  double origin_latitude = 34.020575;  // the map's (0, 0): garminnmea.md's worked example
  double origin_longitude = -118.28539;
  double altitude = 545.4;  // metres above mean sea level
  // Where the antenna is in the map (x east, y north), asked every cycle.
  std::function<geometry::Pose2()> pose_source;
  hardware::garminnmea::Date date{2004, 6, 15};
  double start_time_of_day = 12 * 3600 + 35 * 60 + 19;  // seconds, UTC
  Duration period = std::chrono::seconds(1);
  int decimals = 6;  // of the minutes: 6 is 2 mm, 4 (a Geko's) is 18 cm
  bool fix = true;   // false: the receiver searches (GGA quality 0, RMC and GLL status V)
  // The line speed; a host heard writing at another reads garbage (0: any speed).
  int baud = 4800;
  int quality = 1;
  int satellites = 8;
  double hdop = 0.9;
  double horizontal_error = 15.0;  // PGRME, metres
  double vertical_error = 22.5;
};

struct GarminNmeaPlayback {
  std::vector<std::string> sentences;  // as recorded, without line ends
  bool loop = false;
  double rate = 1.0;  // 2: twice as fast as recorded
  int baud = 4800;    // the recorded line's speed (pacing; a host at another reads garbage; 0: any)
  // Silence before the first sentence: time for the host to open the line,
  // so that a test hears the log from its first sentence.
  Duration start{0};
};

class GarminNmeaEmulator final : public DeviceEmulator {
 public:
  explicit GarminNmeaEmulator(GarminNmeaGenerated generated);
  // Throws std::invalid_argument for a log without a sentence.
  explicit GarminNmeaEmulator(GarminNmeaPlayback playback);

  void receive(std::span<const std::uint8_t> bytes, Duration now, int host_baud) override;
  void host_disconnected(Duration now) override;
  [[nodiscard]] int baud() const override { return playing_ ? playback_.baud : generated_.baud; }
  void advance(Duration now) override;
  [[nodiscard]] Duration next_deadline() const override;
  std::vector<Telegram> take_output() override;
  [[nodiscard]] std::string describe() const override;

  // For tests.
  [[nodiscard]] std::uint64_t sentences_sent() const { return sentences_sent_; }
  [[nodiscard]] std::uint64_t cycles() const { return cycles_; }
  [[nodiscard]] std::uint64_t bytes_received() const { return bytes_received_; }
  [[nodiscard]] bool finished() const { return next_due_ == Duration::max(); }
  // Where a generating receiver put its last fix (degrees).
  [[nodiscard]] double last_latitude() const { return last_latitude_; }
  [[nodiscard]] double last_longitude() const { return last_longitude_; }

  // One generated cycle's sentences (bodies) at `time_of_day` for a position.
  static std::vector<std::string> cycle_bodies(const GarminNmeaGenerated& settings, double time_of_day,
                                               const hardware::garminnmea::Date& date, double latitude,
                                               double longitude);

 private:
  void generate_cycle(Duration at);
  void play_due();
  void schedule_after_playing(std::size_t length);
  void send(const std::string& line);
  void garble(std::vector<std::uint8_t>& bytes);

  bool playing_ = false;
  GarminNmeaGenerated generated_;
  GarminNmeaPlayback playback_;
  std::size_t next_line_ = 0;
  Duration loop_start_{0};
  double loop_first_time_ = -1;  // the first time of day of this pass
  double day_offset_ = 0;        // added to times of day that wrapped past midnight
  double last_time_ = -1;

  Duration next_due_{0};  // playback: the next line's; generation: the next cycle's
  std::deque<std::pair<Duration, std::string>> pending_;  // a generated cycle's lines, spread over it
  std::vector<Telegram> output_;
  std::uint64_t sentences_sent_ = 0;
  std::uint64_t cycles_ = 0;
  std::uint64_t bytes_received_ = 0;
  int host_baud_ = 0;  // the speed the host last wrote at; 0 unknown (it only listens)
  std::uint32_t noise_state_ = 0x2545F491u;
  double last_latitude_ = 0;
  double last_longitude_ = 0;
};

}  // namespace playerkit::emulators
