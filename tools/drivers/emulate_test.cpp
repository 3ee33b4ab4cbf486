#include <gtest/gtest.h>
#include <unistd.h>

#include <atomic>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <thread>

#include "emulate_options.hpp"
#include "emulate_session.hpp"
#include "families/builtin_families.hpp"
#include "links/open_link.hpp"

namespace playerkit::player_drivers {
namespace emulate_test {

template <class Make>
std::string usage_error_of(Make make) {
  try {
    make();
  } catch (const UsageError& e) {
    return e.what();
  }
  return "";
}

// The built-in families' emulators; these tests use the p2os and sick ones.
const emulators::EmulatorCatalog& catalog() {
  static const auto built = families::builtin_families().emulator_catalog();
  return built;
}

bool pioneer_and_sick_built() { return catalog().find("p2os") && catalog().find("sicklms200"); }

std::filesystem::path scratch(const std::string& name) {
  return std::filesystem::temp_directory_path() / ("player_drivers_emulate_test_" + std::to_string(::getpid()) + "_" + name);
}

TEST(EmulateOptions, NamesTakeTheOptionsAfterThemAndTheLinesInOrder) {
  if (!pioneer_and_sick_built()) GTEST_SKIP() << "the p2os and sick families are left out of this build";
  EmulateCommandLine line;
  line.words = {"p2os", "model=p3at", "baud=38400", "sicklms200", "mount=0.1,0,0"};
  line.endpoints = {{EndpointArgument::Kind::tcp, "0"}, {EndpointArgument::Kind::link, "/tmp/laser"}};
  line.faults = {"bad-checksum=0.5", "seed=3"};
  const EmulateOptions options = make_emulate_options(line, catalog());
  ASSERT_EQ(options.requests.size(), 2u);
  EXPECT_EQ(options.requests[0].name, "p2os");
  EXPECT_EQ(options.requests[0].options,
            (emulators::EmulatorOptionValues{{"model", "p3at"}, {"baud", "38400"}}));
  EXPECT_TRUE(std::holds_alternative<emulators::TcpEndpoint>(options.requests[0].endpoint));
  EXPECT_EQ(std::get<emulators::PtyEndpoint>(options.requests[1].endpoint).symlink, std::filesystem::path("/tmp/laser"));
  EXPECT_DOUBLE_EQ(options.faults.bad_checksum, 0.5);
  EXPECT_EQ(options.faults.seed, 3u);
}

TEST(EmulateOptions, Refusals) {
  if (!pioneer_and_sick_built()) GTEST_SKIP() << "the p2os and sick families are left out of this build";
  EmulateCommandLine line;
  line.words = {"model=p3at", "p2os"};
  EXPECT_EQ(usage_error_of([&] { make_emulate_options(line, catalog()); }),
            "'model=p3at': name the emulator first, then its KEY=VALUE options (NAME KEY=VALUE ...)");
  line.words = {"lms200"};
  EXPECT_EQ(usage_error_of([&] { make_emulate_options(line, catalog()); }),
            "no emulator 'lms200'; there are " + catalog().names());
  line.words = {"p2os"};
  line.endpoints = {{EndpointArgument::Kind::link, "/tmp/a"}, {EndpointArgument::Kind::link, "/tmp/b"}};
  EXPECT_EQ(usage_error_of([&] { make_emulate_options(line, catalog()); }),
            "emulate: 2 --link/--tcp for 1 emulator(s): give one per emulator, in order");
  line.endpoints = {{EndpointArgument::Kind::tcp, "http"}};
  EXPECT_EQ(usage_error_of([&] { make_emulate_options(line, catalog()); }), "--tcp 'http': a port number is 0 (any free port) to 65535");
  line.endpoints.clear();
  line.faults = {"explode=1"};
  EXPECT_EQ(usage_error_of([&] { make_emulate_options(line, catalog()); }).substr(0, 18), "--fault explode=1:");
  line.faults.clear();
  line.map_scale = 0.05;
  EXPECT_EQ(usage_error_of([&] { make_emulate_options(line, catalog()); }), "--map-scale is the scale of --map's image: it needs --map");
  line.map = "world.png";
  line.map_scale = -1;
  EXPECT_EQ(usage_error_of([&] { make_emulate_options(line, catalog()); }), "--map-scale must be a positive number of metres per pixel");
}

TEST(EmulateMap, AnImageIsReadThroughTheYamlBesideItOrAtItsScale) {
  const std::string data = PLAYERKIT_TEST_DATA_DIR;
  EmulateOptions options;
  options.map = data + "/maps/stage-cave.png";
  std::string how;
  EXPECT_EQ(usage_error_of([&] { load_emulator_map(options, how); }),
            "--map " + data + "/maps/stage-cave.png is an image: give its scale with --map-scale METRES_PER_PIXEL (or put "
            "stage-cave.yaml beside it)");
  options.map_scale = 0.032;
  const auto map = load_emulator_map(options, how);
  EXPECT_EQ(map->width(), 500);
  EXPECT_DOUBLE_EQ(map->resolution(), 0.032);
  // The bundled copy has its YAML beside it.
  EmulateOptions bundled;
  bundled.map = std::filesystem::path(data).parent_path().parent_path() / "data/maps/stage-cave.png";
  const auto through_yaml = load_emulator_map(bundled, how);
  EXPECT_NE(how.find("stage-cave.yaml"), std::string::npos) << how;
  EXPECT_DOUBLE_EQ(through_yaml->resolution(), 0.032);
  EXPECT_DOUBLE_EQ(through_yaml->origin().x(), -8.0);
}

TEST(EmulateSession, PrintsWhereEachEmulatorIsThenRunsUntilStopped) {
  if (!pioneer_and_sick_built()) GTEST_SKIP() << "the p2os and sick families are left out of this build";
  EmulateCommandLine line;
  line.words = {"p2os", "sickpls"};
  const auto link = scratch("robot");
  line.endpoints = {{EndpointArgument::Kind::link, link.string()}};
  const EmulateOptions options = make_emulate_options(line, catalog());
  std::ostringstream out, err;
  std::atomic<bool> stop{false};
  std::atomic<bool> link_seen{false};
  std::thread watcher([&] {
    // The emulator is up once its symlink is there; a driver could open it now.
    for (int i = 0; i < 200 && !std::filesystem::is_symlink(link); ++i) std::this_thread::sleep_for(std::chrono::milliseconds(10));
    link_seen = std::filesystem::is_symlink(link);
    if (link_seen) links::open_link(link.string(), {.baud = 9600});
    stop = true;
  });
  const int status = run_emulators(options, catalog(), out, err, [&] { return stop.load(); });
  watcher.join();
  EXPECT_EQ(status, kExitOk);
  EXPECT_TRUE(link_seen);
  const std::string text = out.str();
  EXPECT_EQ(text.rfind("p2os on " + link.string() + ": position:0 ( driver \"p2os_position\" port \"" + link.string() +
                           "\" )\nsickpls on /dev/pts/",
                       0),
            0u)
      << text;
  EXPECT_NE(err.str().find("sickpls rides on the emulated robot"), std::string::npos) << err.str();
  EXPECT_FALSE(std::filesystem::exists(std::filesystem::symlink_status(link)));
}

TEST(EmulateSession, StatsEverySecondAndDuration) {
  if (!pioneer_and_sick_built()) GTEST_SKIP() << "the p2os and sick families are left out of this build";
  EmulateCommandLine line;
  line.words = {"sicklms200"};
  line.stats = true;
  line.duration = 1.2;
  std::ostringstream out, err;
  EXPECT_EQ(run_emulators(make_emulate_options(line, catalog()), catalog(), out, err, [] { return false; }), kExitOk);
  EXPECT_NE(err.str().find("stats sicklms200 /dev/pts/"), std::string::npos) << err.str();
  EXPECT_NE(err.str().find(": in 0 B, out 0 B, 0 telegrams"), std::string::npos) << err.str();
}

TEST(EmulateSession, RefusesABadOptionOrAnOccupiedPath) {
  if (!pioneer_and_sick_built()) GTEST_SKIP() << "the p2os and sick families are left out of this build";
  std::ostringstream out, err;
  EmulateCommandLine line;
  line.words = {"sicklms200", "noise=loud"};
  EXPECT_EQ(run_emulators(make_emulate_options(line, catalog()), catalog(), out, err, [] { return true; }), kExitUsage);
  EXPECT_NE(err.str().find("sicklms200: noise=loud: expected a number"), std::string::npos) << err.str();
  const auto occupied = scratch("occupied");
  std::ofstream(occupied).put('x');
  line.words = {"sicklms200"};
  line.endpoints = {{EndpointArgument::Kind::link, occupied.string()}};
  EXPECT_EQ(run_emulators(make_emulate_options(line, catalog()), catalog(), out, err, [] { return true; }), kExitFailure);
  std::filesystem::remove(occupied);
  EXPECT_TRUE(out.str().empty()) << out.str();
}

}  // namespace emulate_test
}  // namespace playerkit::player_drivers
