// The garminnmea driver against the emulated receiver on a real
// pseudo-terminal: the sheet's worked fix, both real Garmin logs as gpsd
// decodes them (and corrupted copies of them), a receiver without a fix,
// the options in 1.5's form and their errors, DGPS corrections relayed,
// and each fault of the kit.

#include "families/garminnmea/driver/garminnmea_driver.hpp"

#include <gtest/gtest.h>

#include <arpa/inet.h>
#include <netinet/in.h>
#include <sys/socket.h>
#include <unistd.h>

#include <mutex>

#include "config/config_file.hpp"
#include "config/errors.hpp"
#include "drivers/driver_harness_test_support.hpp"
#include "families/garminnmea/driver/garminnmea_options.hpp"
#include "families/garminnmea/emulator/garminnmea_emulator.hpp"
#include "families/garminnmea/protocol/gps_fix_tracker.hpp"
#include "families/garminnmea/protocol/gpsd_check_test_support.hpp"
#include "families/garminnmea/protocol/utm.hpp"
#include "framing/nmea_format.hpp"
#include "protocol/interfaces.hpp"
#include "protocol/messages/gps.hpp"

namespace playerkit::drivers::testing {
namespace garminnmea_driver_test {

using emulators::GarminNmeaEmulator;
namespace gps = hardware::garminnmea;
using namespace gps::gpsd_check_test_support;

// Every publication, not only the latest: a cycle makes several fixes.
class Published final : public core::DeviceListener {
 public:
  explicit Published(core::Device& device) : device_(device) { device_.add_listener(this); }
  ~Published() override { device_.remove_listener(this); }
  void data_published(const core::Device& device) override {
    const auto sample = device.latest_data();
    std::lock_guard lock(mutex_);
    all_.push_back(protocol::decode<protocol::GpsData>(sample->payload));
  }
  void replies_ready(const core::Device&) override {}
  std::vector<protocol::GpsData> all() const {
    std::lock_guard lock(mutex_);
    return all_;
  }

 private:
  core::Device& device_;
  mutable std::mutex mutex_;
  std::vector<protocol::GpsData> all_;
};

std::function<std::unique_ptr<GarminNmeaEmulator>()> generated(emulators::GarminNmeaGenerated settings = {}) {
  return [settings] { return std::make_unique<GarminNmeaEmulator>(settings); };
}

struct GarminNmeaDriverTest : ::testing::Test {
  explicit GarminNmeaDriverTest(std::function<std::unique_ptr<GarminNmeaEmulator>()> make = generated(),
                                LineOptions options = {})
      : receiver(std::move(make), std::move(options)) {}

  core::Device& gps_device() { return devices.device(protocol::kGpsCode); }
  void start(const std::string& extra = "dgps_enable 0") {
    devices.load("gps:0 ( driver \"garminnmea\" port \"$PORT\" " + extra + " )\n", receiver.port());
    published = std::make_unique<Published>(gps_device());
    ASSERT_TRUE(gps_device().subscribe()) << devices.log.all();
  }

  EmulatedLine<GarminNmeaEmulator> receiver;
  ConfiguredDevices devices;
  std::unique_ptr<Published> published;
};

TEST_F(GarminNmeaDriverTest, TheSheetsWorkedFixFromTheFirstCycleOn) {
  start();
  // The first cycle may go out before the driver opens the line; the
  // cycle's GLL, after its RMC (the date), GGA and PGRME, has everything.
  const auto data =
      data_when<protocol::GpsData>(gps_device(), [](const auto& d) { return d.time_sec > 86400 && d.err_horz > 0; });
  ASSERT_TRUE(data) << devices.log.all();
  // The first cycle is published: no outlier filter drops it (1.5 dropped 2 to 4).
  // 2004-06-15 12:35:19 UTC whatever the host's time zone, or a second later.
  EXPECT_GE(data->time_sec, 1087302919u);
  EXPECT_LE(data->time_sec, 1087302921u);
  EXPECT_EQ(data->latitude, 7348444);
  EXPECT_EQ(data->longitude, -25549644);
  EXPECT_EQ(data->altitude, 545400);
  EXPECT_EQ(data->quality, 1);
  EXPECT_EQ(data->hdop, 9);
  EXPECT_EQ(data->err_horz, 15000u);
  EXPECT_EQ(data->err_vert, 22500u);
  const gps::Utm utm = gps::to_utm(34.020575, -118.28539);
  EXPECT_EQ(data->utm_e, std::lround(utm.easting * 100));
  EXPECT_EQ(data->utm_n, std::lround(utm.northing * 100));
  EXPECT_NEAR(data->utm_e, 38132189, 2);  // the sheet's, from 1.5's Snyder series
  EXPECT_NEAR(data->utm_n, 376518218, 2);
  EXPECT_EQ(counter(gps_device().driver(), "checksum_errors"), 0u);
}

TEST_F(GarminNmeaDriverTest, AReceiverWithoutAFixReportsNoPosition) {
  emulators::GarminNmeaGenerated searching;
  searching.fix = false;
  receiver.replug(false);
  EmulatedLine<GarminNmeaEmulator> lost(generated(searching));
  devices.load("gps:0 ( driver \"garminnmea\" port \"$PORT\" dgps_enable 0 )\n", lost.port());
  ASSERT_TRUE(gps_device().subscribe()) << devices.log.all();
  const auto data = next_data<protocol::GpsData>(gps_device());
  ASSERT_TRUE(data);
  EXPECT_EQ(data->quality, 0);
  EXPECT_EQ(data->latitude, 0);
  EXPECT_EQ(data->utm_e, 0);
  EXPECT_TRUE(more_data(gps_device(), 1));
  EXPECT_EQ(counter(gps_device().driver(), "fixes"), 0u);
  EXPECT_GE(counter(gps_device().driver(), "no_fix_reports"), 2u);
}

// --- the real logs

// A log as the receiver sent it; `corrupt_every` > 0 corrupts every such
// sentence's body (its recorded checksum no longer fits).
struct Log {
  std::vector<std::string> sentences;
  std::vector<std::string> kept;  // those left intact
  std::size_t corrupted = 0;
  std::size_t bad_as_recorded = 0;  // the Garmin 48's log has a GSV cut short ("*7")
};

bool checksum_fits(const std::string& line) {
  const std::string wire = line + "\r\n";
  const std::vector<std::uint8_t> bytes(wire.begin(), wire.end());
  return framing::NmeaFormat().scan(bytes).kind == framing::FrameScan::Kind::frame;
}
Log load(const std::string& name, std::size_t corrupt_every = 0) {
  Log log;
  for (std::string line : log_sentences(name)) {
    const std::size_t index = log.sentences.size();
    if (corrupt_every > 0 && index % corrupt_every == corrupt_every / 2) {
      line[line.find('*') / 2] ^= 0x01;
      ++log.corrupted;
    } else if (checksum_fits(line)) {
      log.kept.push_back(line);
    } else {
      ++log.bad_as_recorded;
    }
    log.sentences.push_back(line);
  }
  return log;
}

// What the tracker makes of the sentences: the driver must publish exactly these.
std::vector<gps::GpsFix> decoded(const std::vector<std::string>& sentences) {
  gps::GpsFixTracker tracker;
  std::vector<gps::GpsFix> fixes;
  for (const auto& line : sentences) {
    const std::vector<std::uint8_t> bytes(line.begin(), line.end());
    if (auto fix = tracker.take(framing::nmea_body(bytes))) fixes.push_back(*fix);
  }
  return fixes;
}

struct GarminNmeaLogTest : GarminNmeaDriverTest {
  static std::function<std::unique_ptr<GarminNmeaEmulator>()> playing(const std::vector<std::string>& sentences) {
    return [sentences] {
      emulators::GarminNmeaPlayback playback;
      playback.sentences = sentences;
      playback.rate = 20;
      // The driver opens the line within a few milliseconds; two seconds
      // leave room for a loaded machine (a sanitizer build on two cores).
      playback.start = std::chrono::seconds(2);
      return std::make_unique<GarminNmeaEmulator>(playback);
    };
  }
  GarminNmeaLogTest() : GarminNmeaDriverTest(generated()) {}

  // Plays `log` to the driver; every publication.
  std::vector<protocol::GpsData> play(const Log& log) {
    receiver.replug(false);
    line = std::make_unique<EmulatedLine<GarminNmeaEmulator>>(playing(log.sentences));
    devices.load("gps:0 ( driver \"garminnmea\" port \"$PORT\" dgps_enable 0 )\n", line->port());
    published = std::make_unique<Published>(gps_device());
    EXPECT_TRUE(gps_device().subscribe()) << devices.log.all();
    EXPECT_TRUE(line->wait_until([](GarminNmeaEmulator& e) { return e.finished(); }, 20s));
    const core::Driver& driver = gps_device().driver();
    // Every sentence read: used, ignored (RMB, BOD, RTE) or a checksum error.
    EXPECT_TRUE(eventually(
        [&] {
          return counter(driver, "sentences") + counter(driver, "sentences_ignored") +
                     counter(driver, "checksum_errors") == log.sentences.size();
        },
        5s))
        << counter(driver, "sentences") << " " << counter(driver, "sentences_ignored") << " "
        << counter(driver, "checksum_errors");
    EXPECT_EQ(counter(driver, "checksum_errors"), log.corrupted + log.bad_as_recorded);
    return published->all();
  }

  // gpsd's fixes: each at its time of day with gpsd's position (1/60
  // arc-second) and altitude (1 cm), the GGA's quality.
  void expect_gpsd_fixes(const std::vector<protocol::GpsData>& ours, const std::string& name) {
    for (const GpsdFix& theirs : gpsd_fixes(name)) {
      const protocol::GpsData* match = nullptr;
      for (const auto& data : ours) {
        if (data.quality == 0) continue;
        const bool same_place = data.latitude == wire_angle(theirs.latitude) && data.longitude == wire_angle(theirs.longitude);
        if (theirs.time_of_day ? static_cast<int>(data.time_sec % 86400) == *theirs.time_of_day : same_place) match = &data;
      }
      ASSERT_TRUE(match) << name << ": no fix at " << theirs.time_of_day.value_or(-1);
      EXPECT_LE(std::abs(match->latitude - wire_angle(theirs.latitude)), 1);
      EXPECT_LE(std::abs(match->longitude - wire_angle(theirs.longitude)), 1);
      if (theirs.altitude && theirs.time_of_day) {
        EXPECT_NEAR(match->altitude, *theirs.altitude * 1000, 10);
      }
      EXPECT_EQ(match->quality, 1);
      EXPECT_EQ(match->time_usec, 0u);
    }
  }

  // Exactly the tracker's fixes of `sentences`, in order.
  static void expect_fixes_of(const std::vector<protocol::GpsData>& ours, const std::vector<std::string>& sentences) {
    const auto expected = decoded(sentences);
    ASSERT_EQ(ours.size(), expected.size());
    for (std::size_t i = 0; i < ours.size(); ++i) {
      EXPECT_EQ(ours[i].time_sec, static_cast<std::uint32_t>(expected[i].time_sec)) << i;
      EXPECT_EQ(ours[i].latitude, wire_angle(expected[i].latitude)) << i;
      EXPECT_EQ(ours[i].longitude, wire_angle(expected[i].longitude)) << i;
      EXPECT_EQ(ours[i].altitude, std::lround(expected[i].altitude * 1000)) << i;
      EXPECT_EQ(ours[i].quality, expected[i].quality) << i;
    }
  }

  std::unique_ptr<EmulatedLine<GarminNmeaEmulator>> line;
};

TEST_F(GarminNmeaLogTest, Garmin48EveryFixGpsdDecodes) {
  const Log log = load("garmin48.log");
  const auto ours = play(log);
  expect_gpsd_fixes(ours, "garmin48.log");
  EXPECT_EQ(log.bad_as_recorded, 1u);
  expect_fixes_of(ours, log.kept);
  // The GLL fixes of their own second (22:53:11, ...) are there: 1.5 ignored GLL.
  EXPECT_TRUE(std::any_of(ours.begin(), ours.end(), [](const auto& d) { return d.time_sec % 86400 == 82391; }));
  // Dated by the RMC: 2001-06-06 22:53:08 UTC.
  EXPECT_EQ(ours.front().time_sec, 991867988u);
}

TEST_F(GarminNmeaLogTest, Garmin38EveryFixGpsdDecodes) {
  const Log log = load("garmin38.log");
  const auto ours = play(log);
  expect_gpsd_fixes(ours, "garmin38.log");
  EXPECT_EQ(log.bad_as_recorded, 0u);
  expect_fixes_of(ours, log.kept);
}

TEST_F(GarminNmeaLogTest, ACorruptedGarmin48LosesOnlyTheCorruptedSentences) {
  const Log log = load("garmin48.log", 7);
  ASSERT_GE(log.corrupted, 10u);
  expect_fixes_of(play(log), log.kept);
}

TEST_F(GarminNmeaLogTest, ACorruptedGarmin38LosesOnlyTheCorruptedSentences) {
  const Log log = load("garmin38.log", 5);
  ASSERT_GE(log.corrupted, 10u);
  expect_fixes_of(play(log), log.kept);
}

// --- options

TEST(GarminNmeaOptions, PlayerFifteensFormAndItsDefaults) {
  const config::ConfigFile file = config::ConfigFile::parse(
      "gps:0 ( driver \"garminnmea\" port \"/tmp/gps\" baud 9600 dgps_enable 0 dgps_group \"225.0.0.44\" dgps_port 7779 )\n",
      "gps.cfg");
  const auto settings = garminnmea::read_garminnmea_settings(file.sections().at(0));
  EXPECT_EQ(settings.port, "/tmp/gps");
  EXPECT_EQ(settings.baud, 9600);
  EXPECT_FALSE(settings.dgps_enable);
  EXPECT_EQ(settings.dgps_group, "225.0.0.44");
  EXPECT_EQ(settings.dgps_port, 7779);
  const auto defaults = garminnmea::read_garminnmea_settings(
      config::ConfigFile::parse("gps:0 ( driver \"garminnmea\" )\n", "gps.cfg").sections().at(0));
  // The schema's default (1.5's, documented in the README table), not spelled here: tests name no real port.
  EXPECT_EQ(defaults.port, garminnmea::garminnmea_option_schema().find("port")->text_fallback());
  EXPECT_EQ(defaults.baud, 4800);
  EXPECT_TRUE(defaults.dgps_enable);
  EXPECT_EQ(defaults.dgps_group, "225.0.0.43");
  EXPECT_EQ(defaults.dgps_port, 7778);
}

TEST(GarminNmeaOptions, BadValuesAreReportedWhereTheyAre) {
  const auto error_of = [](const std::string& text) -> std::string {
    try {
      (void)garminnmea::read_garminnmea_settings(config::ConfigFile::parse(text, "gps.cfg").sections().at(0));
    } catch (const config::ConfigError& e) {
      return e.what();
    }
    return "no error";
  };
  // 1.5 ran a baud it did not know at 4800 without a word.
  const std::string baud = error_of("gps:0 ( driver \"garminnmea\" baud 2400 )\n");
  EXPECT_NE(baud.find("gps.cfg:1:34"), std::string::npos) << baud;
  EXPECT_NE(baud.find("4800"), std::string::npos) << baud;
  const std::string group = error_of("gps:0 (\n  driver \"garminnmea\"\n  dgps_group \"10.0.0.1\" )\n");
  EXPECT_NE(group.find("gps.cfg:3:14"), std::string::npos) << group;
  EXPECT_NE(group.find("multicast"), std::string::npos) << group;
}

TEST(GarminNmeaOptions, TheReadmeTableIsTheSchemas) {
  EXPECT_EQ(readme_options_table(std::string(PLAYERKIT_TEST_DATA_DIR) + "/../../lib/families/garminnmea/README.md",
                                 "garminnmea"),
            garminnmea::garminnmea_option_schema().markdown());
}

// --- DGPS corrections

int free_udp_port() {
  const int probe = ::socket(AF_INET, SOCK_DGRAM, 0);
  sockaddr_in address{};
  address.sin_family = AF_INET;
  address.sin_addr.s_addr = htonl(INADDR_LOOPBACK);
  ::bind(probe, reinterpret_cast<sockaddr*>(&address), sizeof address);
  socklen_t size = sizeof address;
  ::getsockname(probe, reinterpret_cast<sockaddr*>(&address), &size);
  ::close(probe);
  return ntohs(address.sin_port);
}

TEST_F(GarminNmeaDriverTest, RelaysCorrectionsHeardOnUdpToTheReceiver) {
  const int port = free_udp_port();
  // Bound and joined on loopback: the test's traffic stays on this host.
  start("dgps_enable 1 dgps_bind \"127.0.0.1\" dgps_port " + std::to_string(port));
  const std::vector<std::uint8_t> rtcm{0x66, 0x40, 0x7f, 0x01, 0x02};
  const int sender = ::socket(AF_INET, SOCK_DGRAM, 0);
  sockaddr_in to{};
  to.sin_family = AF_INET;
  to.sin_addr.s_addr = htonl(INADDR_LOOPBACK);
  to.sin_port = htons(static_cast<std::uint16_t>(port));
  ASSERT_EQ(::sendto(sender, rtcm.data(), rtcm.size(), 0, reinterpret_cast<sockaddr*>(&to), sizeof to), 5);
  ::close(sender);
  EXPECT_TRUE(receiver.wait_until([](GarminNmeaEmulator& e) { return e.bytes_received() == 5; }));
  EXPECT_EQ(counter(gps_device().driver(), "dgps_bytes"), 5u);
  EXPECT_TRUE(more_data(gps_device(), 2));  // fixes keep coming
}

// --- the kit's faults

emulators::FaultPlan plan(std::string_view faults) {
  emulators::FaultPlan p;
  std::size_t start = 0;
  while (start < faults.size()) {
    const std::size_t comma = faults.find(' ', start);
    emulators::add_fault(p, std::string(faults.substr(start, comma - start)));
    if (comma == std::string_view::npos) break;
    start = comma + 1;
  }
  return p;
}

std::function<std::unique_ptr<GarminNmeaEmulator>()> fast_receiver() {
  emulators::GarminNmeaGenerated settings;
  settings.period = std::chrono::milliseconds(100);
  return generated(settings);
}

struct GarminNmeaNoisyLineTest : GarminNmeaDriverTest {
  GarminNmeaNoisyLineTest()
      : GarminNmeaDriverTest(fast_receiver(), {.tcp = false, .symlink = {},
                                               .faults = plan("bad-checksum=0.2 garbage=0.2 truncate=0.1 drop=0.001")}) {}
};

TEST_F(GarminNmeaNoisyLineTest, BadSentencesAreCountedAndSkippedGoodOnesUsed) {
  start();
  ASSERT_TRUE(eventually([&] { return counter(gps_device().driver(), "fixes") >= 40; }, 10s)) << devices.log.all();
  EXPECT_GT(counter(gps_device().driver(), "checksum_errors"), 0u);
  EXPECT_GT(counter(gps_device().driver(), "resyncs"), 0u);
  // Whatever got through is the receiver's fix, never a corrupted one.
  for (const auto& data : published->all()) {
    EXPECT_EQ(data.latitude, 7348444);
    EXPECT_EQ(data.longitude, -25549644);
  }
  EXPECT_EQ(devices.log.count("lost"), 0u) << devices.log.all();
}

struct GarminNmeaSlowStartTest : GarminNmeaDriverTest {
  GarminNmeaSlowStartTest()
      : GarminNmeaDriverTest(fast_receiver(), {.tcp = false, .symlink = {}, .faults = plan("silent-start=2")}) {}
};

TEST_F(GarminNmeaSlowStartTest, WaitsForAReceiverThatStartsLate) {
  start();  // within 1.5's ten seconds
  EXPECT_TRUE(next_data<protocol::GpsData>(gps_device()));
}

struct GarminNmeaVanishTest : GarminNmeaDriverTest {
  GarminNmeaVanishTest()
      : GarminNmeaDriverTest(fast_receiver(), {.tcp = false, .symlink = {}, .faults = plan("vanish=1:6.5")}) {}
};

TEST_F(GarminNmeaVanishTest, ALostReceiverIsFoundAgain) {
  start();
  EXPECT_FALSE(devices.log.first_with({"no NMEA sentence for"}, 10s).empty()) << devices.log.all();
  EXPECT_FALSE(devices.log.first_with({"answers again"}, 10s).empty()) << devices.log.all();
  EXPECT_TRUE(more_data(gps_device(), 3));
}

}  // namespace garminnmea_driver_test
}  // namespace playerkit::drivers::testing
