// The trajectory CSV reader takes lines of at most text::kMaxLineBytes.

#include "localization/trajectory.hpp"

#include <gtest/gtest.h>

#include <sstream>
#include <stdexcept>
#include <string>

#include "text/line_reader.hpp"

namespace playerkit::localization {
namespace csv_line_limit_test {

TEST(TrajectoryCsvLimits, ALineOverTheCapIsAnErrorNamingIt) {
  std::istringstream in("time,x,y,yaw\n1,0,0,0\n" + std::string(text::kMaxLineBytes + 1, '7') + "\n2,0,0,0\n");
  try {
    (void)read_trajectory_csv(in, "estimate.csv");
    FAIL() << "no error";
  } catch (const std::runtime_error& error) {
    EXPECT_STREQ(error.what(), "estimate.csv:3: line longer than 1048576 bytes");
  }
}

TEST(TrajectoryCsvLimits, ALineAtTheCapIsRead) {
  // A comment line just at the cap is skipped like any comment.
  std::istringstream in("time,x,y,yaw\n#" + std::string(text::kMaxLineBytes - 1, 'c') + "\n1,2,3,0\n");
  const Trajectory trajectory = read_trajectory_csv(in, "estimate.csv");
  ASSERT_EQ(trajectory.size(), 1u);
}

}  // namespace csv_line_limit_test
}  // namespace playerkit::localization
