// sicklms200 when the line misbehaves: corrupt and noisy telegrams, a laser
// silent at start, a laser that vanishes and comes back, a port unplugged
// and plugged in again, a port missing or held by someone else; and the
// byte trace.
#include <gtest/gtest.h>

#include <mutex>
#include <string>
#include <vector>

#include "families/sick/driver/sick_driver_test_support.hpp"
#include "links/link_error.hpp"
#include "links/open_link.hpp"

namespace playerkit::drivers {
namespace sicklms200_faults_test {

using namespace sick_driver_test_support;

emulators::FaultPlan plan(std::initializer_list<std::string_view> faults) {
  emulators::FaultPlan result;
  for (std::string_view fault : faults) emulators::add_fault(result, fault);
  return result;
}

// Scans published in a row, each a whole 361-value one.
int whole_scans(LaserRig& rig, int wanted) {
  int count = 0;
  for (int i = 0; i < wanted; ++i) {
    const auto scan = rig.next_scan();
    if (!scan || scan->range_count != 361) break;
    ++count;
  }
  return count;
}

TEST(Sicklms200Faults, CorruptTelegramsAreCountedAndSkippedAndDataKeepsFlowing) {
  LaserRig rig({.faults = plan({"bad-checksum=0.1"})});
  rig.load("rate 500000");
  ASSERT_TRUE(rig.laser().subscribe()) << rig.all_log();
  EXPECT_EQ(whole_scans(rig, 40), 40);
  EXPECT_GT(rig.runner().stats().faults.bad_checksums, 0u);
  EXPECT_GT(counter(rig.driver(), "checksum_errors"), 0u);
  EXPECT_TRUE(rig.laser().available());
}

TEST(Sicklms200Faults, GarbageBetweenTelegramsIsCountedAndSkippedAndDataKeepsFlowing) {
  LaserRig rig({.faults = plan({"garbage=0.3"})});
  rig.load("rate 500000");
  ASSERT_TRUE(rig.laser().subscribe()) << rig.all_log();
  EXPECT_EQ(whole_scans(rig, 40), 40);
  // More runs of noise skipped than the ACK before each reply.
  EXPECT_GT(rig.runner().stats().faults.garbage_runs, 0u);
  EXPECT_GT(counter(rig.driver(), "resyncs"),
            rig.with_laser([](RefusingLaser& l) { return l.inner().requests_answered(); }));
  EXPECT_TRUE(rig.laser().available());
}

TEST(Sicklms200Faults, ALaserSilentLongerThanTheSetupRefusesTheSubscriptionNamingThePort) {
  LaserRig rig({.faults = plan({"silent-start=60"})});
  rig.load("rate 500000", "reply_timeout 0.1");
  EXPECT_FALSE(rig.laser().subscribe());
  EXPECT_EQ(rig.laser().subscriptions(), 0);
  const std::string line = rig.logged({"setup failed"});
  EXPECT_NE(line.find(rig.port() + ": no answer from the SICK LMS 200 at 38400, 9600, 500000 baud"),
            std::string::npos)
      << line;
  EXPECT_NE(line.find("is it powered and connected to this port?"), std::string::npos) << line;
  // Each speed was tried twice, and the port let go for the next attempt.
  EXPECT_EQ(counter(rig.driver(), "timeouts"), 6u);
  links::SerialSettings settings;
  EXPECT_NO_THROW(links::open_link(rig.port(), settings));
}

TEST(Sicklms200Faults, ALaserThatVanishesIsLostThenFoundAgainWithoutARestart) {
  // The line dies 1.5 s after the laser starts, for 2.5 s.
  LaserRig rig({.faults = plan({"vanish=1.5:2.5"})});
  rig.load("rate 500000");
  ASSERT_TRUE(rig.laser().subscribe()) << rig.all_log();
  ASSERT_TRUE(rig.next_scan());

  ASSERT_TRUE(drivers::testing::eventually([&] { return !rig.laser().available(); }, 10s)) << rig.all_log();
  const std::string lost = rig.logged({"lost the SICK LMS 200 on " + rig.port() + ": no scan for"});
  EXPECT_NE(lost.find("data stops, new subscriptions get 'e'"), std::string::npos) << rig.all_log();
  // Meanwhile newcomers are refused, and requests still answered.
  EXPECT_FALSE(rig.laser().subscribe());
  const auto geom = rig.request({protocol::kLaserGetGeom});
  ASSERT_TRUE(geom);
  EXPECT_EQ(geom->type, protocol::MessageType::kAck);

  ASSERT_TRUE(drivers::testing::eventually([&] { return rig.laser().available(); }, 15s)) << rig.all_log();
  EXPECT_NE(rig.logged({"answers again at 500000 baud; data resumes"}), "") << rig.all_log();
  EXPECT_EQ(whole_scans(rig, 5), 5);
  EXPECT_EQ(counter(rig.driver(), "reconnects"), 1u);
  EXPECT_EQ(rig.laser().subscriptions(), 1);  // the first subscriber never noticed more than the gap
}

TEST(Sicklms200Faults, APortUnpluggedAndPluggedBackIsReopenedAndTheNewLaserSetUp) {
  ScratchDirectory scratch;
  LaserRig rig({.symlink = scratch.file("ttyLASER")});
  EXPECT_EQ(rig.port(), scratch.file("ttyLASER").string());
  rig.load("rate 500000");
  ASSERT_TRUE(rig.laser().subscribe()) << rig.all_log();
  ASSERT_TRUE(rig.next_scan());

  rig.replug(false);
  ASSERT_TRUE(drivers::testing::eventually([&] { return !rig.laser().available(); }, 10s)) << rig.all_log();
  EXPECT_NE(rig.logged({"lost the SICK LMS 200 on " + rig.port()}), "") << rig.all_log();
  rig.replug(true);  // a new laser, powered up at 38400 and idle
  ASSERT_TRUE(drivers::testing::eventually([&] { return rig.laser().available(); }, 15s)) << rig.all_log();
  EXPECT_EQ(whole_scans(rig, 5), 5);
  EXPECT_EQ(rig.with_laser([](RefusingLaser& l) { return l.inner().line_baud(); }), 500000);
}

TEST(Sicklms200Faults, AMissingPortGivesTheLinksMessage) {
  ScratchDirectory scratch;
  const std::string missing = scratch.file("ttyNOTHERE").string();
  std::string expected;
  try {
    links::open_link(missing, links::SerialSettings{});
  } catch (const links::LinkError& e) {
    expected = e.what();
  }
  ASSERT_FALSE(expected.empty());
  LaserRig rig;
  rig.load_on(missing, "");
  EXPECT_FALSE(rig.laser().subscribe());
  EXPECT_NE(rig.logged({"setup failed: " + expected}), "") << rig.all_log();
}

TEST(Sicklms200Faults, ABusyPortGivesTheLinksMessage) {
  LaserRig rig;
  const auto holder = links::open_link(rig.port(), links::SerialSettings{});
  std::string expected;
  try {
    links::open_link(rig.port(), links::SerialSettings{});
  } catch (const links::LinkError& e) {
    EXPECT_EQ(e.kind(), links::LinkErrorKind::busy);
    expected = e.what();
  }
  ASSERT_FALSE(expected.empty());
  rig.load();
  EXPECT_FALSE(rig.laser().subscribe());
  EXPECT_NE(rig.logged({"setup failed: " + expected}), "") << rig.all_log();
}

TEST(Sicklms200Faults, TheByteTraceSeesBothDirectionsAcrossSubscriptions) {
  std::mutex mutex;  // before the rig: its shutdown still traces
  std::vector<std::uint8_t> out;
  std::size_t in = 0;
  LaserRig rig;
  // Subscribed twice, each time with the laser's whole start-up: a generous
  // reply_timeout (it costs nothing while the laser answers) so that a slow,
  // sanitized run does not take a late reply for a missing laser.
  rig.load("rate 38400", "reply_timeout 2 retry_interval 0.2");
  ASSERT_TRUE(rig.driver().set_byte_trace(
      [&](bool outgoing, std::span<const std::uint8_t> bytes, std::chrono::steady_clock::time_point) {
        std::lock_guard lock(mutex);
        if (outgoing) {
          out.insert(out.end(), bytes.begin(), bytes.end());
        } else {
          in += bytes.size();
        }
      }));
  for (int round = 0; round < 2; ++round) {
    {
      std::lock_guard lock(mutex);
      out.clear();
    }
    ASSERT_TRUE(rig.laser().subscribe()) << rig.all_log();
    ASSERT_TRUE(rig.next_scan());
    {
      std::lock_guard lock(mutex);
      // The sheet's "enter installation mode" telegram comes first (§1.4).
      const std::vector<std::uint8_t> t1 = {0x02, 0x00, 0x0A, 0x00, 0x20, 0x00, 0x53, 0x49,
                                            0x43, 0x4B, 0x5F, 0x4C, 0x4D, 0x53, 0xBE, 0xC5};
      ASSERT_GE(out.size(), t1.size());
      EXPECT_TRUE(std::equal(t1.begin(), t1.end(), out.begin()));
      EXPECT_GT(in, 732u);
    }
    rig.laser().unsubscribe();  // its last telegrams pass through the trace too
  }
}

}  // namespace sicklms200_faults_test
}  // namespace playerkit::drivers
