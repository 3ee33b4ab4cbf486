#include "eval_command.hpp"

#include <gtest/gtest.h>

#include <nlohmann/json.hpp>

#include <sstream>
#include <string>

#include "support/scratch_directory.hpp"

namespace playerkit::amcl_offline {
namespace eval_command_test {

// A straight drive along x at 1 m/s for 10 s, one pose a second, shifted
// `offset_y` sideways.
std::string drive_csv(double offset_y) {
  std::ostringstream text;
  text << "time,x,y,yaw\n";
  for (int t = 0; t <= 10; ++t) text << t << "," << t << "," << offset_y << ",0\n";
  return text.str();
}

// The same drive as localize writes it, claiming `std_xy` metres and 0.05 rad.
std::string drive_with_spread_csv(double offset_y, double std_xy) {
  std::ostringstream text;
  text << "time,x,y,yaw,std_x,std_y,std_yaw,particles,cov_xy\n";
  for (int t = 0; t <= 10; ++t) text << t << "," << t << "," << offset_y << ",0," << std_xy << "," << std_xy << ",0.05,500,0\n";
  return text.str();
}

struct EvalCommandTest : ::testing::Test {
  playerkit::testing::ScratchDirectory scratch{"eval_command_test"};
  std::string truth = scratch.write("truth.csv", drive_csv(0.0)).string();
  std::string exact = scratch.write("exact.csv", drive_csv(0.0)).string();
  std::string shifted = scratch.write("shifted.csv", drive_csv(0.1)).string();

  std::string output_of(const EvalOptions& options) {
    std::ostringstream out, err;
    EXPECT_EQ(run_eval(options, out, err), tools::kExitOk);
    return out.str();
  }
};

TEST_F(EvalCommandTest, SeveralRunsMakeOneMarkdownTableWithARowOverAll) {
  const EvalOptions options{{{exact, truth}, {shifted, truth}}, EvalFormat::markdown};
  EXPECT_EQ(output_of(options),
            "| estimate | truth | matched | rmse_m | max_m | rmse_deg | max_deg | converged_s | lost | in_2sigma |\n"
            "|---|---|---:|---:|---:|---:|---:|---:|---:|---:|\n"
            "| " + exact + " | " + truth + " | 11/11 | 0.000 | 0.000 | 0.00 | 0.00 | 0.0 | 0 | - |\n"
            "| " + shifted + " | " + truth + " | 11/11 | 0.100 | 0.100 | 0.00 | 0.00 | 0.0 | 0 | - |\n"
            "| all 2 runs |  |  | 0.050 | 0.100 | 0.00 | 0.00 | 2/2 converged | 0 | - |\n");
}

TEST_F(EvalCommandTest, TheTextTableAlignsItsColumns) {
  const std::string text = output_of({{{exact, truth}, {shifted, truth}}, EvalFormat::text});
  std::istringstream lines(text);
  std::string header, first, second, all;
  std::getline(lines, header);
  std::getline(lines, first);
  std::getline(lines, second);
  std::getline(lines, all);
  EXPECT_EQ(header.rfind("estimate", 0), 0u);
  // Right-aligned figures end where their header does.
  EXPECT_EQ(first.size(), header.size());
  EXPECT_EQ(second.size(), header.size());
  EXPECT_EQ(header.find("rmse_m") + 6, second.find("0.100") + 5);
  EXPECT_EQ(all.rfind("all 2 runs", 0), 0u);
}

TEST_F(EvalCommandTest, JsonHoldsEveryRunsEvaluationAndTheSummary) {
  const auto json = nlohmann::json::parse(output_of({{{exact, truth}, {shifted, truth}}, EvalFormat::json}));
  ASSERT_EQ(json["runs"].size(), 2u);
  EXPECT_EQ(json["runs"][1]["estimate"], shifted);
  EXPECT_NEAR(json["runs"][1]["evaluation"]["all"]["position_rmse_m"].get<double>(), 0.1, 1e-9);
  EXPECT_EQ(json["all"]["runs"], 2);
  EXPECT_EQ(json["all"]["converged"], 2);
  EXPECT_NEAR(json["all"]["position_rmse_m_mean"].get<double>(), 0.05, 1e-9);
  EXPECT_NEAR(json["all"]["position_max_m"].get<double>(), 0.1, 1e-9);
}

TEST_F(EvalCommandTest, OneRunKeepsItsFullReport) {
  const std::string text = output_of({{{shifted, truth}}, EvalFormat::text});
  EXPECT_EQ(text.rfind("matched 11 of 11 estimates\n", 0), 0u) << text;
  EXPECT_NE(text.find("converged after 0.0 s"), std::string::npos) << text;
  const auto json = nlohmann::json::parse(output_of({{{shifted, truth}}, EvalFormat::json}));
  EXPECT_EQ(json["matched"], 11);  // the evaluation itself, as before
}

TEST_F(EvalCommandTest, TheClaimedSpreadsCoverageIsReported) {
  const std::string honest = scratch.write("honest.csv", drive_with_spread_csv(0.1, 0.1)).string();
  const std::string overconfident = scratch.write("overconfident.csv", drive_with_spread_csv(0.1, 0.02)).string();
  EXPECT_NE(output_of({{{honest, truth}}, EvalFormat::text})
                .find("the claimed 2-sigma held the truth in 100.0% of 11 rows; 0 confidently wrong (off by more "
                      "than 0.50 m or 20 deg outside it)\n"),
            std::string::npos);
  const std::string table = output_of({{{honest, truth}, {overconfident, truth}}, EvalFormat::markdown});
  EXPECT_NE(table.find("| 0 | 100.0% |\n"), std::string::npos) << table;
  EXPECT_NE(table.find("| 0 | 0.0% |\n"), std::string::npos) << table;
  EXPECT_NE(table.find("2/2 converged | 0 | 50.0% |\n"), std::string::npos) << table;
  const auto json = nlohmann::json::parse(output_of({{{overconfident, truth}}, EvalFormat::json}));
  EXPECT_EQ(json["coverage"]["inside_2sigma"], 0);
  EXPECT_NEAR(json["coverage"]["worst_position_sigmas"].get<double>(), 5.0, 1e-9);
}

}  // namespace eval_command_test
}  // namespace playerkit::amcl_offline
