#include "nav_bench_options.hpp"

#include <gtest/gtest.h>

#include <fstream>
#include <unistd.h>

namespace playerkit::nav_bench {
namespace nav_bench_options_test {

class NavBenchOptionsTest : public ::testing::Test {
 protected:
  void SetUp() override {
    folder_ = std::filesystem::temp_directory_path() / ("nav_bench_options_test_" + std::to_string(::getpid()));
    std::filesystem::create_directories(folder_);
    std::ofstream(folder_ / "room.world") << "size [4 4]\n";
    std::ofstream(folder_ / "nav.cfg") << "position:1 ( driver \"vfh\" )\n";
    line_.world = (folder_ / "room.world").string();
    line_.config = (folder_ / "nav.cfg").string();
  }
  void TearDown() override { std::filesystem::remove_all(folder_); }

  std::string usage_error() const {
    try {
      (void)make_nav_bench_options(line_);
    } catch (const UsageError& e) {
      return e.what();
    }
    return "accepted";
  }

  std::filesystem::path folder_;
  NavBenchCommandLine line_;
};

TEST_F(NavBenchOptionsTest, TheDefaultsAreFiftyGoalsSeedOneAsText) {
  const NavBenchOptions options = make_nav_bench_options(line_);
  EXPECT_EQ(options.world, folder_ / "room.world");
  EXPECT_EQ(options.goals, 50);
  EXPECT_EQ(options.seed, 1u);
  EXPECT_EQ(options.format, ReportFormat::text);
  line_.format = "json";
  line_.goals = 3;
  EXPECT_EQ(make_nav_bench_options(line_).format, ReportFormat::json);
  EXPECT_EQ(make_nav_bench_options(line_).goals, 3);
}

TEST_F(NavBenchOptionsTest, EachBadFlagIsNamed) {
  line_.format = "yaml";
  EXPECT_EQ(usage_error(), "--format 'yaml': text or json");
  line_.format = "text";
  line_.goals = 0;
  EXPECT_EQ(usage_error(), "--goals 0: from 1 to 10000");
  line_.goals = 5;
  line_.world = (folder_ / "none.world").string();
  EXPECT_EQ(usage_error(), "a world file '" + line_.world + "': no such file");
  line_.world = (folder_ / "room.world").string();
  line_.config.clear();
  EXPECT_EQ(usage_error(), "name a configuration file (--config) with amcl, vfh and wavefront");
}

}  // namespace nav_bench_options_test
}  // namespace playerkit::nav_bench
