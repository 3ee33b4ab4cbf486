// --check catches what serving would refuse, without opening anything; parse
// errors name unknown flags.

#include "check_config.hpp"

#include <gtest/gtest.h>

#include <sstream>
#include <string>

#include <CLI/CLI.hpp>

#include "parse_errors.hpp"
#include "support/scratch_directory.hpp"

namespace check_config_test {

using playerkit::testing::ScratchDirectory;

struct Checked {
  int status;
  std::string out;
  std::string err;
};

Checked check(const std::string& config_path, std::optional<std::string> readlog = std::nullopt) {
  playerkit::daemon::ServeOptions options;
  options.config_path = config_path;
  options.readlog = std::move(readlog);
  std::ostringstream out;
  std::ostringstream err;
  const int status = playerkit::serve::check_config(options, out, err);
  return {status, out.str(), err.str()};
}

const std::string kPlayerLog =
    "## Player version 1.5 \n## File version 0.0.0 \n"
    "0000001000.000 h 6665 position 00 0000001000.000 +01.000 +02.000 +0.000 +0.000 +0.000 +0.000 0 \n";

TEST(CheckConfig, AValidConfigurationIsListed) {
  ScratchDirectory scratch("check_config_test");
  const auto cfg = scratch.write("ok.cfg", "mcom:0 ( driver \"lifomcom\" )\nnull:0 ( driver \"null\" prot 1 )\n");
  const Checked result = check(cfg.string());
  EXPECT_EQ(result.status, 0) << result.err;
  EXPECT_NE(result.out.find(cfg.string() + ": 2 devices, served on port 6665"), std::string::npos) << result.out;
  // Options no driver read are warned about, as serving does.
  EXPECT_EQ(result.err, cfg.string() + ":2:24: warning: property 'prot' is defined but not used\n");
}

TEST(CheckConfig, AnEmptyConfigurationServesNothing) {
  ScratchDirectory scratch("check_config_test");
  const auto cfg = scratch.write("empty.cfg", "# nothing\n");
  const Checked result = check(cfg.string());
  EXPECT_EQ(result.status, 2);
  EXPECT_EQ(result.err, cfg.string() + ": no devices declared, nothing to serve\n");
}

TEST(CheckConfig, WritelogIntoADirectoryOrNowhere) {
  ScratchDirectory scratch("check_config_test");
  const std::string sources = "position:0 ( driver \"readlog\" filename \"run.log\" )\n";
  scratch.write("run.log", kPlayerLog);
  const auto into_directory =
      scratch.write("dir.cfg", sources + "null:0 ( driver \"writelog\" filename \"" + scratch.path().string() +
                                   "\" devices [\"position:0\"] )\n");
  Checked result = check(into_directory.string());
  EXPECT_EQ(result.status, 2);
  EXPECT_EQ(result.err, into_directory.string() + ":2:37: writelog: filename \"" + scratch.path().string() +
                            "\" is a directory\n");
  const auto nowhere = scratch.write("nowhere.cfg", sources + "null:0 ( driver \"writelog\" filename \"" +
                                                        scratch.path().string() + "/none/run.log\" devices [\"position:0\"] )\n");
  result = check(nowhere.string());
  EXPECT_EQ(result.status, 2);
  EXPECT_NE(result.err.find("/none does not exist"), std::string::npos) << result.err;
}

TEST(CheckConfig, WritelogOfADeviceThatIsNotDeclared) {
  ScratchDirectory scratch("check_config_test");
  const auto cfg = scratch.write("missing.cfg", "null:0 ( driver \"writelog\" filename \"" +
                                                    scratch.file("out.log").string() + "\" devices [\"laser:0\"] )\n");
  const Checked result = check(cfg.string());
  EXPECT_EQ(result.status, 2);
  EXPECT_EQ(result.err, cfg.string() + ":1:1: writelog: no device laser:0@6665 to record\n");
  EXPECT_FALSE(std::filesystem::exists(scratch.file("out.log")));
}

TEST(CheckConfig, AmclWithADirectoryForAMapOrWithoutItsLaser) {
  ScratchDirectory scratch("check_config_test");
  scratch.write("run.log", kPlayerLog);
  const std::string position = "position:0 ( driver \"readlog\" filename \"run.log\" )\n";
  const auto cfg = scratch.write("amcl.cfg", position + "localize:0 ( driver \"amcl\" map_file \"" +
                                                 scratch.path().string() + "\" map_scale 0.05 )\n");
  Checked result = check(cfg.string());
  EXPECT_EQ(result.status, 2);
  EXPECT_EQ(result.err.rfind(cfg.string() + ":2:37: amcl: cannot load the map: ", 0), 0u) << result.err;
  const std::string map = std::string(PLAYERKIT_TEST_DATA_DIR) + "/maps/cave.pnm";
  const auto no_laser = scratch.write("nolaser.cfg", position + "localize:0 ( driver \"amcl\" map_file \"" + map +
                                                         "\" map_scale 0.03 map_negate 1 )\n");
  result = check(no_laser.string());
  EXPECT_EQ(result.status, 2);
  EXPECT_EQ(result.err, no_laser.string() + ":2:1: amcl: no laser:0 device on port 6665 to localize with\n");
}

TEST(CheckConfig, ReadlogOfAMissingFileOrWithoutALog) {
  ScratchDirectory scratch("check_config_test");
  const auto cfg = scratch.write("readlog.cfg", "laser:0 ( driver \"readlog\" filename \"gone.log\" )\n");
  Checked result = check(cfg.string());
  EXPECT_EQ(result.status, 2);
  EXPECT_NE(result.err.find("cannot open " + scratch.file("gone.log").string() + ": No such file or directory"),
            std::string::npos)
      << result.err;
  const auto needs_r = scratch.write("replay.cfg", "laser:0 ( driver \"readlog\" )\n");
  result = check(needs_r.string());
  EXPECT_EQ(result.status, 2);
  EXPECT_NE(result.err.find("readlog: no log file: start player-serve with -r LOG"), std::string::npos) << result.err;
  scratch.write("run.log", kPlayerLog);
  result = check(needs_r.string(), scratch.file("run.log").string());
  EXPECT_EQ(result.status, 0) << result.err;
}

TEST(CheckConfig, TheReplayedLogIsCheckedFirst) {
  ScratchDirectory scratch("check_config_test");
  const auto cfg = scratch.write("replay.cfg", "laser:0 ( driver \"readlog\" )\n");
  Checked result = check(cfg.string(), "/nonexistent/run.log");
  EXPECT_EQ(result.status, 2);
  EXPECT_EQ(result.err, "player-serve: cannot open /nonexistent/run.log: No such file or directory\n");
  const auto carmen = scratch.write("intel.log", "ODOM 1.0 2.0 0.5 0 0 0 100.0 host 0.0\n");
  result = check(cfg.string(), carmen.string());
  EXPECT_EQ(result.status, 2);
  EXPECT_NE(result.err.find(" is a CARMEN log; readlog replays Player text logs: serve it with `player-log replay "),
            std::string::npos)
      << result.err;
}

std::string parse_error_of(std::vector<std::string> arguments) {
  CLI::App app{"test"};
  std::string config;
  app.add_option("CONFIG", config)->required();
  app.add_flag("--check");
  std::vector<const char*> argv{"tool"};
  for (const auto& argument : arguments) argv.push_back(argument.c_str());
  try {
    app.parse(static_cast<int>(argv.size()), const_cast<char**>(argv.data()));
  } catch (const CLI::ParseError& error) {
    return playerkit::tools::parse_error_message(app, error);
  }
  return "parsed";
}

TEST(ParseErrors, AnUnknownFlagIsNamedEvenWhenTheConfigIsMissing) {
  EXPECT_EQ(parse_error_of({"--bogus"}),
            "The following argument was not expected: --bogus\nCONFIG is required\n"
            "Run with --help for more information.\n");
  EXPECT_EQ(parse_error_of({"--bogus", "x.cfg"}),
            "The following argument was not expected: --bogus\nRun with --help for more information.\n");
  EXPECT_EQ(parse_error_of({}), "CONFIG is required\nRun with --help for more information.\n");
}

TEST(ParseErrors, ArgumentsAreEscaped) {
  EXPECT_EQ(parse_error_of({"--bo\x1b[2Jgus", "x.cfg"}),
            "The following argument was not expected: --bo\\x1b[2Jgus\nRun with --help for more information.\n");
}

}  // namespace check_config_test
