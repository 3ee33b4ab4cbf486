// The emulated receiver on a simulated clock: what the sheet's §6 asks of
// every cycle, positions that follow the pose in UTM metres, a searching
// receiver, and a real log played at its own pace, looped, faster.

#include "families/garminnmea/emulator/garminnmea_emulator.hpp"

#include <gtest/gtest.h>

#include <cctype>
#include <utility>

#include "families/garminnmea/protocol/gps_fix_tracker.hpp"
#include "families/garminnmea/protocol/gpsd_check_test_support.hpp"
#include "families/garminnmea/protocol/utm.hpp"
#include "framing/nmea_format.hpp"

namespace playerkit::emulators {
namespace garminnmea_emulator_test {

namespace gps = hardware::garminnmea;
using namespace std::chrono_literals;

// The lines the receiver sent by `now`, each with its CR LF (a sentence and its line end are two telegrams).
std::vector<std::string> lines_until(GarminNmeaEmulator& emulator, Duration now) {
  emulator.advance(now);
  std::vector<std::string> lines;
  std::string line;
  for (const Telegram& t : emulator.take_output()) {
    for (const std::uint8_t byte : t.bytes) {
      line.push_back(static_cast<char>(byte));
      if (byte == '\n') lines.push_back(std::exchange(line, {}));
    }
  }
  if (!line.empty()) lines.push_back(line);
  return lines;
}

std::string body_of(const std::string& line) {
  const std::vector<std::uint8_t> bytes(line.begin(), line.end());
  return std::string(framing::nmea_body(bytes));
}

TEST(GarminNmeaEmulator, EveryCycleHasTheSentencesThe15DriverNeeds) {
  GarminNmeaEmulator receiver(GarminNmeaGenerated{});
  auto first = lines_until(receiver, 0ms);  // at once: the driver gives up after silence
  ASSERT_EQ(first.size(), 1u);
  EXPECT_EQ(first[0].substr(0, 7), "$GPRMC,");
  // The rest of the cycle spread over 800 ms: a listener never waits long.
  const auto rest = lines_until(receiver, 999ms);
  EXPECT_GE(rest.size(), 7u);
  first.insert(first.end(), rest.begin(), rest.end());
  lines_until(receiver, 1000ms);
  const auto second = lines_until(receiver, 1999ms);
  EXPECT_EQ(second.size() + 1, first.size());
  const framing::NmeaFormat format;
  bool gga = false, pgrme = false;
  for (const std::string& line : second) {
    EXPECT_LE(line.size(), 82u) << line;
    EXPECT_EQ(line.substr(line.size() - 2), "\r\n");
    const std::vector<std::uint8_t> bytes(line.begin(), line.end());
    EXPECT_EQ(format.scan(bytes).kind, framing::FrameScan::Kind::frame) << line;
    const std::string body = body_of(line);
    const auto fields = gps::split_fields(body);
    if (fields[0] == "GPGGA") {
      gga = true;
      EXPECT_EQ(fields.size(), 15u);  // all 14 fields
      EXPECT_EQ(fields[1], "123520.00");
      EXPECT_EQ(fields[2].substr(0, 4), "3401");
      EXPECT_EQ(fields[4].substr(0, 5), "11817");
    }
    pgrme |= fields[0] == "PGRME";
  }
  EXPECT_TRUE(gga && pgrme);
  EXPECT_EQ(receiver.cycles(), 2u);
}

TEST(GarminNmeaEmulator, ThePositionFollowsThePoseInUtmMetres) {
  geometry::Pose2 pose{};
  GarminNmeaGenerated settings;
  settings.origin_latitude = -45.4576;  // south, and far east: zone 59
  settings.origin_longitude = 167.1527;
  settings.pose_source = [&pose] { return pose; };
  GarminNmeaEmulator receiver(settings);
  const gps::Utm origin = gps::to_utm(settings.origin_latitude, settings.origin_longitude);
  gps::GpsFixTracker tracker;
  for (int step = 0; step < 5; ++step) {
    pose = {3.25 * step, -1.5 * step, 0.3};
    std::optional<gps::GpsFix> fix;
    for (const auto& line : lines_until(receiver, std::chrono::seconds(step))) {
      if (auto f = tracker.take(body_of(line))) fix = f;
    }
    ASSERT_TRUE(fix);
    const gps::Utm here = gps::to_utm(fix->latitude, fix->longitude);
    EXPECT_NEAR(here.easting - origin.easting, pose.x, 0.003);
    EXPECT_NEAR(here.northing - origin.northing, pose.y, 0.003);
  }
}

TEST(GarminNmeaEmulator, ASearchingReceiverSaysSo) {
  GarminNmeaGenerated settings;
  settings.fix = false;
  GarminNmeaEmulator receiver(settings);
  gps::GpsFixTracker tracker;
  int reports = 0;
  for (const auto& line : lines_until(receiver, 3500ms)) {
    if (auto fix = tracker.take(body_of(line))) {
      ++reports;
      EXPECT_FALSE(fix->has_position);
    }
  }
  EXPECT_EQ(reports, 4);  // one GGA of quality 0 a cycle
}

// Found by running Player 2.1.3's garminnmea with `--fault bad-checksum` (docs/reference-checks/
// 2026-12-08-serial-sensors.md): the fault corrupts a telegram's last byte, which was the sentence's LF, so the
// driver saw merged sentences ("couldn't find an end character") instead of a bad checksum. The checksum digits
// now end their own telegram, the CR LF follows in another that carries no checksum.
TEST(GarminNmeaEmulator, ASentenceEndsItsTelegramWithItsChecksumTheLineEndFollows) {
  GarminNmeaEmulator receiver(GarminNmeaGenerated{});
  receiver.advance(999ms);
  const std::vector<Telegram> out = receiver.take_output();
  ASSERT_GE(out.size(), 16u);
  ASSERT_EQ(out.size() % 2, 0u);
  for (std::size_t i = 0; i < out.size(); i += 2) {
    const std::string sentence(out[i].bytes.begin(), out[i].bytes.end());
    ASSERT_GE(sentence.size(), 4u);
    EXPECT_EQ(sentence.front(), '$');
    EXPECT_EQ(sentence[sentence.size() - 3], '*') << sentence;
    EXPECT_TRUE(std::isxdigit(static_cast<unsigned char>(sentence.back()))) << sentence;
    EXPECT_TRUE(out[i].has_checksum);
    EXPECT_EQ(out[i + 1].bytes, (std::vector<std::uint8_t>{'\r', '\n'}));
    EXPECT_FALSE(out[i + 1].has_checksum);
  }
}

TEST(GarminNmeaEmulator, AHostWritingAtAnotherSpeedReadsGarbage) {
  GarminNmeaEmulator receiver(GarminNmeaGenerated{});
  const std::vector<std::uint8_t> probe{'P', 'R', ' '};
  receiver.receive(probe, 0ms, 9600);
  const framing::NmeaFormat format;
  for (const Telegram& t : receiver.take_output()) {
    EXPECT_FALSE(t.has_checksum);
    EXPECT_TRUE(std::all_of(t.bytes.begin(), t.bytes.end(), [](std::uint8_t b) { return b >= 0x80; }));
  }
  // A new session listens at the right speed until it writes.
  receiver.host_disconnected(500ms);
  EXPECT_EQ(lines_until(receiver, 999ms).back().substr(0, 1), "$");
  receiver.receive(std::vector<std::uint8_t>{'\r', '\n'}, 1000ms, 4800);
  EXPECT_EQ(lines_until(receiver, 1000ms).back().substr(0, 7), "$GPRMC,");
}

TEST(GarminNmeaEmulator, DatesRollOverAtMidnight) {
  GarminNmeaGenerated settings;
  settings.date = {2004, 12, 31};
  settings.start_time_of_day = 86399;
  GarminNmeaEmulator receiver(settings);
  const auto lines = lines_until(receiver, 1s);
  std::vector<std::string> rmc;
  for (const auto& line : lines) {
    const std::string body = body_of(line);
    if (line.starts_with("$GPRMC")) rmc.emplace_back(gps::split_fields(body)[9]);
  }
  EXPECT_EQ(rmc, (std::vector<std::string>{"311204", "010105"}));
}

TEST(GarminNmeaEmulator, PlaysALogAtItsOwnPaceIgnoringTheHost) {
  GarminNmeaPlayback playback;
  playback.sentences = gps::gpsd_check_test_support::log_sentences("garmin48.log");
  playback.rate = 2;
  const std::size_t total = playback.sentences.size();
  GarminNmeaEmulator receiver(playback);
  const std::vector<std::uint8_t> rtcm{0x66, 0x7f, 0x00};
  receiver.receive(rtcm, 0ms, 4800);
  EXPECT_EQ(receiver.bytes_received(), 3u);
  // The first cycle (22:53:08) at once, at the line's speed: its first 8
  // lines are about 500 characters, half a second of 4800 baud at twice the speed.
  auto lines = lines_until(receiver, 0ms);
  ASSERT_EQ(lines.size(), 1u);
  EXPECT_EQ(lines[0].substr(0, 13), "$GPRMC,225308");
  EXPECT_EQ(lines[0].substr(lines[0].size() - 5), "*6D\r\n");  // as recorded
  lines = lines_until(receiver, 499ms);
  EXPECT_GE(lines.size(), 5u);
  // The GLL of 22:53:09 waits for half a second, the RMC of 22:53:10 for one.
  EXPECT_TRUE(std::none_of(lines.begin(), lines.end(), [](const auto& l) { return l.starts_with("$GPGLL"); }));
  lines = lines_until(receiver, 999ms);
  EXPECT_TRUE(std::any_of(lines.begin(), lines.end(),
                          [](const auto& l) { return l.starts_with("$GPGLL,4527.458,S,16709.165,E,225309"); }));
  EXPECT_TRUE(std::none_of(lines.begin(), lines.end(), [](const auto& l) { return l.starts_with("$GPRMC"); }));
  lines = lines_until(receiver, 1001ms);
  ASSERT_FALSE(lines.empty());
  EXPECT_EQ(lines[0].substr(0, 13), "$GPRMC,225310");
  // 22:53:08 to 22:53:35 is 27 s of log: 13.5 s at twice the speed, then it stops.
  lines_until(receiver, 13000ms);
  EXPECT_FALSE(receiver.finished());
  lines_until(receiver, 15000ms);
  EXPECT_TRUE(receiver.finished());
  EXPECT_EQ(receiver.sentences_sent(), total);
}

TEST(GarminNmeaEmulator, ALoopedLogStartsAgain) {
  GarminNmeaPlayback playback;
  playback.sentences = gps::gpsd_check_test_support::log_sentences("garmin38.log");
  playback.rate = 10;
  playback.loop = true;
  const std::size_t total = playback.sentences.size();
  GarminNmeaEmulator receiver(playback);
  lines_until(receiver, 10s);
  EXPECT_GE(receiver.cycles(), 2u);
  EXPECT_GT(receiver.sentences_sent(), 2 * total);
  EXPECT_FALSE(receiver.finished());
  EXPECT_THROW(GarminNmeaEmulator(GarminNmeaPlayback{.sentences = {"# only a comment"}}), std::invalid_argument);
}

}  // namespace garminnmea_emulator_test
}  // namespace playerkit::emulators
