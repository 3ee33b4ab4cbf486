#include "sweep_collect.hpp"

#include <gtest/gtest.h>

#include <fstream>
#include <sstream>

#include "support/scratch_directory.hpp"

namespace playerkit::amcl_offline {
namespace sweep_collect_test {

// A sweep directory made by hand: two logs x two sigma-hit values, one seed.
// Run 0 converged at once, run 1 never converged, run 2 failed, run 3 has
// not run yet.
struct HandMadeSweep {
  testing::ScratchDirectory scratch{"sweep_collect_test"};

  HandMadeSweep() {
    std::filesystem::create_directories(scratch.path() / "runs");
    scratch.write("plan.json", R"({"parameters": ["sigma-hit"], "runs": [
      {"id": "a_sigma-hit=0.1_seed=1", "log": "a", "parameters": {"sigma-hit": "0.1"}, "seed": 1},
      {"id": "a_sigma-hit=0.2_seed=1", "log": "a", "parameters": {"sigma-hit": "0.2"}, "seed": 1},
      {"id": "b_sigma-hit=0.1_seed=1", "log": "b", "parameters": {"sigma-hit": "0.1"}, "seed": 1},
      {"id": "b_sigma-hit=0.2_seed=1", "log": "b", "parameters": {"sigma-hit": "0.2"}, "seed": 1}]})");
    scratch.write("runs/a_sigma-hit=0.1_seed=1.eval.json", evaluation(true, 0.08, 0.3, 0.0349066, 2));
    scratch.write("runs/a_sigma-hit=0.1_seed=1.err",
                  "amcl-offline: 292 scans (200 updates) in 0.25 s wall, 301.2 s of log: 1205x real time\n");
    scratch.write("runs/a_sigma-hit=0.2_seed=1.eval.json", evaluation(false, 1.5, 4.0, 0.5, 0));
    scratch.write("runs/a_sigma-hit=0.2_seed=1.err",
                  "amcl-offline: 237 scans (236 updates) in 0.21 s wall; no real-time factor: the log has no usable times\n");
    scratch.write("runs/b_sigma-hit=0.1_seed=1.failed", "");
  }

  // What eval --json writes, cut to the fields collect reads (plus one it
  // does not), the "all" figures doubled so that a mix-up shows.
  static std::string evaluation(bool converged, double rmse, double max, double heading, int lost) {
    std::ostringstream text;
    const auto stats = [&](double scale) {
      std::ostringstream s;
      s << R"({"count": 10, "position_rmse_m": )" << rmse * scale << R"(, "position_max_m": )" << max * scale
        << R"(, "heading_rmse_rad": )" << heading * scale << R"(, "heading_max_rad": 1})";
      return s.str();
    };
    text << R"({"estimates": 10, "converged": )" << (converged ? "true" : "false")
         << R"(, "convergence_time_s": )" << (converged ? "0.0" : "null") << R"(, "all": )" << stats(converged ? 2 : 1)
         << R"(, "after_convergence": )" << stats(1) << R"(, "lost_episodes": )" << lost << R"(, "longest_lost_s": 0})";
    return text.str();
  }
};

std::string table_text(const SweepTable& table, SweepTableFormat format) {
  std::ostringstream out;
  write_sweep_table(table, format, out);
  return out.str();
}

TEST(SweepCollect, EveryPlannedRunIsARowOkFailedOrMissing) {
  const HandMadeSweep sweep;
  const SweepTable table = collect_sweep(sweep.scratch.path());
  EXPECT_EQ(table.parameters, (std::vector<std::string>{"sigma-hit"}));
  ASSERT_EQ(table.runs.size(), 4U);
  EXPECT_EQ(table.runs[0].status, SweepStatus::ok);
  EXPECT_EQ(table.runs[0].wall_s, 0.25);
  EXPECT_EQ(table.runs[0].real_time_factor, 1205.0);
  EXPECT_EQ(table.runs[1].status, SweepStatus::ok);
  EXPECT_EQ(table.runs[1].wall_s, 0.21);
  EXPECT_FALSE(table.runs[1].real_time_factor);
  EXPECT_FALSE(table.runs[1].converged_after_s);
  EXPECT_EQ(table.runs[2].status, SweepStatus::failed);
  EXPECT_EQ(table.runs[3].status, SweepStatus::missing);
  EXPECT_EQ(sweep_tally(table), "4 runs: 2 ok, 1 failed, 1 missing");

  EXPECT_EQ(table_text(table, SweepTableFormat::csv),
            "log,sigma-hit,seed,status,rmse_m,max_m,rmse_deg,converged_s,lost,wall_s,realtime\n"
            "a,0.1,1,ok,0.080,0.300,2.00,0.0,2,0.25,1205\n"
            "a,0.2,1,ok,1.500,4.000,28.65,never,0,0.21,\n"
            "b,0.1,1,failed,,,,,,,\n"
            "b,0.2,1,missing,,,,,,,\n");
  EXPECT_EQ(table_text(table, SweepTableFormat::markdown),
            "| log | sigma-hit | seed | status | rmse_m | max_m | rmse_deg | converged_s | lost | wall_s | realtime |\n"
            "|---|---|---:|---:|---:|---:|---:|---:|---:|---:|---:|\n"
            "| a | 0.1 | 1 | ok | 0.080 | 0.300 | 2.00 | 0.0 | 2 | 0.25 | 1205 |\n"
            "| a | 0.2 | 1 | ok | 1.500 | 4.000 | 28.65 | never | 0 | 0.21 |  |\n"
            "| b | 0.1 | 1 | failed |  |  |  |  |  |  |  |\n"
            "| b | 0.2 | 1 | missing |  |  |  |  |  |  |  |\n");
  const std::string json = table_text(table, SweepTableFormat::json);
  EXPECT_NE(json.find(R"("id": "a_sigma-hit=0.2_seed=1")"), std::string::npos);
  EXPECT_NE(json.find(R"("converged_after_s": null)"), std::string::npos);
  EXPECT_NE(json.find(R"("status": "missing")"), std::string::npos);
}

TEST(SweepCollect, ParameterValuesWithCommasAreQuotedInCsv) {
  SweepTable table;
  table.parameters = {"particles"};
  SweepResult run;
  run.log = "a";
  run.parameters = {"100,5000"};
  run.seed = 1;
  table.runs.push_back(run);
  EXPECT_EQ(table_text(table, SweepTableFormat::csv),
            "log,particles,seed,status,rmse_m,max_m,rmse_deg,converged_s,lost,wall_s,realtime\n"
            "a,\"100,5000\",1,missing,,,,,,,\n");
}

TEST(SweepCollect, ADirectoryWithoutAPlanOrWithABadResultIsAnError) {
  const HandMadeSweep sweep;
  EXPECT_THROW(collect_sweep(sweep.scratch.path() / "runs"), std::runtime_error);
  sweep.scratch.write("runs/b_sigma-hit=0.2_seed=1.eval.json", "{\"estimates\": 3");
  EXPECT_THROW(collect_sweep(sweep.scratch.path()), std::runtime_error);
  sweep.scratch.write("runs/b_sigma-hit=0.2_seed=1.eval.json", "{\"estimates\": 3}");
  try {
    collect_sweep(sweep.scratch.path());
    ADD_FAILURE() << "accepted";
  } catch (const std::runtime_error& e) {
    EXPECT_NE(std::string(e.what()).find("b_sigma-hit=0.2_seed=1.eval.json: not an eval --json result"), std::string::npos) << e.what();
  }
}

TEST(SweepCollect, ThePlotIsAPng) {
  const HandMadeSweep sweep;
  const auto png = sweep.scratch.file("rmse.png");
  write_sweep_plot(collect_sweep(sweep.scratch.path()), png);
  std::ifstream in(png, std::ios::binary);
  std::string magic(8, '\0');
  in.read(magic.data(), 8);
  EXPECT_EQ(magic, "\x89PNG\r\n\x1a\n");
}

}  // namespace sweep_collect_test
}  // namespace playerkit::amcl_offline
