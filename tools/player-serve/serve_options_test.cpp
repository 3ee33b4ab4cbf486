#include "serve_options.hpp"

#include <gtest/gtest.h>

#include <limits>
#include <string>

#include "support/scratch_directory.hpp"

namespace serve_options_test {

using playerkit::core::LogLevel;
using playerkit::serve::make_serve_options;
using playerkit::serve::ServeCommandLine;
using playerkit::serve::UsageError;

ServeCommandLine config_only() {
  ServeCommandLine command_line;
  command_line.config_path = "robot.cfg";
  return command_line;
}

// The UsageError's text, or "" when none was thrown.
std::string usage_error(const ServeCommandLine& command_line) {
  try {
    (void)make_serve_options(command_line);
  } catch (const UsageError& e) {
    return e.what();
  }
  return "";
}

TEST(ServeOptions, DefaultsAreTheDaemons) {
  const auto request = make_serve_options(config_only());
  const playerkit::daemon::ServeOptions defaults;
  EXPECT_FALSE(request.check_only);
  EXPECT_EQ(request.options.config_path, "robot.cfg");
  EXPECT_EQ(request.options.port, defaults.port);
  EXPECT_EQ(request.options.bind_address, defaults.bind_address);
  EXPECT_FALSE(request.options.auth_key.has_value());
  EXPECT_FALSE(request.options.readlog.has_value());
  EXPECT_EQ(request.options.log_level, LogLevel::kInfo);
}

TEST(ServeOptions, FlagsReachTheDaemon) {
  auto command_line = config_only();
  command_line.port = 7000;
  command_line.bind_address = "127.0.0.1";
  command_line.key = "secret";
  command_line.plugins = {"./a.so", "./b.so"};
  command_line.readlog = "run.log";
  command_line.readlog_speed = 2.5;
  command_line.check = true;
  const auto request = make_serve_options(command_line);
  EXPECT_TRUE(request.check_only);
  EXPECT_EQ(request.options.port, 7000);
  EXPECT_EQ(request.options.bind_address, "127.0.0.1");
  ASSERT_TRUE(request.options.auth_key.has_value());
  EXPECT_EQ(*request.options.auth_key, "secret");
  EXPECT_EQ(request.options.plugins, command_line.plugins);
  ASSERT_TRUE(request.options.readlog.has_value());
  EXPECT_EQ(*request.options.readlog, "run.log");
  EXPECT_DOUBLE_EQ(request.options.readlog_speed, 2.5);
}

// -f alone is checked but changes nothing: there is no log to replay.
TEST(ServeOptions, ReplaySpeedWithoutLogIsIgnored) {
  auto command_line = config_only();
  command_line.readlog_speed = 3;
  const auto request = make_serve_options(command_line);
  EXPECT_FALSE(request.options.readlog.has_value());
  EXPECT_DOUBLE_EQ(request.options.readlog_speed, 1.0);
}

TEST(ServeOptions, QuietAndVerboseSetTheLogLevelVerboseWinning) {
  auto command_line = config_only();
  command_line.quiet = true;
  EXPECT_EQ(make_serve_options(command_line).options.log_level, LogLevel::kError);
  command_line.verbose = true;
  EXPECT_EQ(make_serve_options(command_line).options.log_level, LogLevel::kDebug);
  command_line.quiet = false;
  EXPECT_EQ(make_serve_options(command_line).options.log_level, LogLevel::kDebug);
}

TEST(ServeOptions, GazeboIsRefusedPointingAtTheSimulator) {
  auto command_line = config_only();
  command_line.gazebo_id = "default";
  EXPECT_EQ(usage_error(command_line),
            "Gazebo (-g) is not available: the gz_* drivers serve a simulated world instead "
            "(player-serve -s WORLD gazebo.cfg)");
}

ServeCommandLine world_only() {
  ServeCommandLine command_line;
  command_line.world = "cave.world";
  return command_line;
}

TEST(ServeOptions, AWorldAloneIsEnoughToServe) {
  const auto request = make_serve_options(world_only());
  EXPECT_TRUE(request.options.config_path.empty());
  EXPECT_FALSE(request.options.has_configuration());
  ASSERT_TRUE(request.options.simulation.has_value());
  const playerkit::daemon::SimulationOptions defaults;
  EXPECT_EQ(request.options.simulation->world, "cave.world");
  EXPECT_EQ(request.options.simulation->speedup, defaults.speedup);
  EXPECT_EQ(request.options.simulation->seed, defaults.seed);
  EXPECT_FALSE(request.options.simulation->sim_time.has_value());
  EXPECT_FALSE(request.options.simulation->paused);
  EXPECT_EQ(request.options.served_name(), "cave.world");
}

TEST(ServeOptions, SimulationFlagsReachTheDaemon) {
  auto command_line = world_only();
  command_line.config_path = "gz.cfg";
  command_line.speedup = 0.0;
  command_line.seed = 42;
  command_line.sim_time = 60.0;
  command_line.paused = true;
  const auto request = make_serve_options(command_line);
  ASSERT_TRUE(request.options.simulation.has_value());
  EXPECT_EQ(request.options.simulation->speedup, 0.0);
  EXPECT_EQ(request.options.simulation->seed, 42u);
  EXPECT_EQ(request.options.simulation->sim_time, 60.0);
  EXPECT_TRUE(request.options.simulation->paused);
  EXPECT_EQ(request.options.served_name(), "gz.cfg");
}

TEST(ServeOptions, NothingToServeIsAUsageError) {
  EXPECT_EQ(usage_error(ServeCommandLine{}), "nothing to serve: give a configuration file, -s WORLD, or both");
}

TEST(ServeOptions, SimulationFlagsNeedAWorld) {
  auto command_line = config_only();
  command_line.speedup = 2.0;
  EXPECT_EQ(usage_error(command_line), "--speedup runs a simulation; it needs -s WORLD");
  command_line = config_only();
  command_line.paused = true;
  EXPECT_EQ(usage_error(command_line), "--paused runs a simulation; it needs -s WORLD");
  command_line = config_only();
  command_line.sim_time = 1.0;
  EXPECT_EQ(usage_error(command_line), "--sim-time runs a simulation; it needs -s WORLD");
  command_line = config_only();
  command_line.seed = 1;
  EXPECT_EQ(usage_error(command_line), "--seed runs a simulation; it needs -s WORLD");
}

TEST(ServeOptions, APictureNeedsAWorldAnExistingDirectoryAndNoInputsName) {
  const playerkit::testing::ScratchDirectory scratch("serve_options_test");
  auto command_line = world_only();
  command_line.world = scratch.write("cave.world", "resolution 0.03\n").string();
  command_line.config_path = scratch.write("gz.cfg", "\n").string();
  command_line.picture = scratch.file("run.png").string();
  const auto request = make_serve_options(command_line);
  ASSERT_TRUE(request.options.simulation.has_value());
  EXPECT_EQ(request.options.simulation->picture, command_line.picture);
  EXPECT_EQ(request.options.simulation->picture_inputs,
            (std::vector<std::string>{command_line.world, command_line.config_path}));

  command_line.picture = command_line.world;
  EXPECT_NE(usage_error(command_line).find("cave.world"), std::string::npos) << usage_error(command_line);
  command_line.picture = (scratch.path() / "." / "gz.cfg").string();
  EXPECT_NE(usage_error(command_line), "");
  command_line.picture = scratch.file("missing/run.png").string();
  EXPECT_EQ(usage_error(command_line), "--picture " + command_line.picture + ": the directory " +
                                           scratch.file("missing").string() + " does not exist");
  command_line = config_only();
  command_line.picture = "run.png";
  EXPECT_EQ(usage_error(command_line), "--picture runs a simulation; it needs -s WORLD");
}

TEST(ServeOptions, SimulationNumbersAreChecked) {
  auto command_line = world_only();
  command_line.speedup = -1.0;
  EXPECT_EQ(usage_error(command_line),
            "--speedup -1: the speedup must be 0 (as fast as possible) or above, below 1000000");
  command_line.speedup = std::numeric_limits<double>::quiet_NaN();
  EXPECT_NE(usage_error(command_line), "");
  command_line = world_only();
  command_line.sim_time = 0.0;
  EXPECT_EQ(usage_error(command_line), "--sim-time 0: the simulated seconds must be above 0 and below 1e9");
}

TEST(ServeOptions, ReplayAndSimulationBothKeepTimeSoOnlyOneIsTaken) {
  auto command_line = world_only();
  command_line.readlog = "run.log";
  EXPECT_EQ(usage_error(command_line),
            "-r and -s both set the server's clock (log time, simulation time); give one of them");
}

TEST(ServeOptions, OnlyTcpTransport) {
  auto command_line = config_only();
  command_line.transport = "udp";
  EXPECT_EQ(usage_error(command_line), "transport 'udp' is not available: playerkit serves clients over TCP only");
}

TEST(ServeOptions, ReplaySpeedMustBeAboveZeroAndBelowAMillion) {
  auto command_line = config_only();
  command_line.readlog = "run.log";
  command_line.readlog_speed = 0;
  EXPECT_EQ(usage_error(command_line), "-f 0: the replay speed must be above 0 and below 1000000");
  command_line.readlog_speed = -1.5;
  EXPECT_EQ(usage_error(command_line), "-f -1.5: the replay speed must be above 0 and below 1000000");
  command_line.readlog_speed = 1e6;
  EXPECT_EQ(usage_error(command_line), "-f 1e+06: the replay speed must be above 0 and below 1000000");
  command_line.readlog_speed = std::numeric_limits<double>::quiet_NaN();
  EXPECT_NE(usage_error(command_line), "");
  command_line.readlog_speed = 999999;
  EXPECT_EQ(usage_error(command_line), "");
}

}  // namespace serve_options_test
