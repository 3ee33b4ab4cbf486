#include "sweep_command.hpp"

#include <gtest/gtest.h>

#include <fstream>
#include <functional>
#include <sstream>

#include "support/scratch_directory.hpp"

namespace playerkit::amcl_offline {
namespace sweep_command_test {

std::string usage_error(const std::function<void()>& make) {
  try {
    make();
  } catch (const tools::UsageError& e) {
    return e.what();
  }
  ADD_FAILURE() << "accepted";
  return "";
}

TEST(SweepCommand, PlanOptionsReadTheSpecAndTakeThisProgram) {
  const testing::ScratchDirectory scratch("sweep_command_test");
  const auto spec = scratch.write("sweep.json", R"({"logs": [{"log": "a.log", "map": "a.yaml"}], "seeds": [1, 2]})");
  SweepPlanCommand command{spec.string(), "out", std::nullopt};
  SweepPlanOptions options = make_sweep_plan_options(command, "/opt/amcl-offline");
  EXPECT_EQ(options.program, "/opt/amcl-offline");
  EXPECT_TRUE(options.dir.is_absolute());
  EXPECT_EQ(options.dir.filename(), "out");
  EXPECT_EQ(options.spec.logs.at(0).log, scratch.path() / "a.log");  // from the spec's directory
  EXPECT_EQ(options.spec.seeds.size(), 2U);
  command.program = "/cluster/bin/amcl-offline";
  EXPECT_EQ(make_sweep_plan_options(command, "/opt/amcl-offline").program, "/cluster/bin/amcl-offline");
}

TEST(SweepCommand, BadFlagsAndSpecsAreUsageErrorsNamingThem) {
  const testing::ScratchDirectory scratch("sweep_command_test");
  const auto good = scratch.write("good.json", R"({"logs": [{"log": "a.log", "map": "a.yaml"}]})");
  const auto bad = scratch.write("bad.json", R"({"logs": [{"log": 1, "map": "a.yaml"}]})");
  EXPECT_NE(usage_error([&] { make_sweep_plan_options({bad.string(), "out", std::nullopt}, "/p"); })
                .find("bad.json: logs[0].log: must be a non-empty string"),
            std::string::npos);
  EXPECT_NE(usage_error([&] { make_sweep_plan_options({scratch.file("none.json").string(), "out", std::nullopt}, "/p"); })
                .find("cannot read the sweep spec"),
            std::string::npos);
  EXPECT_EQ(usage_error([&] { make_sweep_plan_options({good.string(), "", std::nullopt}, "/p"); }),
            "-o: the sweep's directory may not be empty");
  EXPECT_EQ(usage_error([&] { make_sweep_collect_options({"dir", "tsv", "-", std::nullopt}); }),
            "--format: csv, markdown or json, not 'tsv'");
  SweepRunCommand run{good.string(), "out", 0, "csv", "-", std::nullopt};
  EXPECT_EQ(usage_error([&] { make_sweep_run_options(run, "/p"); }), "-j: at least 1 job at a time");
  run.jobs = 3;
  run.format = "markdown";
  const SweepRunOptions options = make_sweep_run_options(run, "/p");
  EXPECT_EQ(options.jobs, 3U);
  EXPECT_EQ(options.collect.format, SweepTableFormat::markdown);
  EXPECT_EQ(options.collect.dir, options.plan.dir);
}

TEST(SweepCommand, JobsRunBoundedAndAFailureStopsNoOther) {
  const testing::ScratchDirectory scratch("sweep_command_test");
  const std::string trace = scratch.file("trace").string();
  std::vector<SweepJob> jobs;
  for (int i = 0; i < 5; ++i) {
    // Each job notes its start and end; job 1 fails.
    jobs.push_back({"job" + std::to_string(i), "echo + >> " + trace + "; sleep 0.1; echo - >> " + trace +
                                                   (i == 1 ? "; exit 3" : "")});
  }
  std::ostringstream err;
  EXPECT_EQ(run_sweep_jobs(jobs, 2, err), 1U);
  std::ifstream in(trace);
  int now = 0, most = 0, ended = 0;
  for (std::string line; std::getline(in, line);) {
    now += line == "+" ? 1 : -1;
    ended += line == "-" ? 1 : 0;
    most = std::max(most, now);
  }
  EXPECT_EQ(ended, 5);
  // Never more than 2 at once (that two overlap at all depends on the machine's load).
  EXPECT_LE(most, 2);
  EXPECT_GE(most, 1);
  EXPECT_NE(err.str().find("job1 FAILED (exit status 3, after "), std::string::npos) << err.str();
  EXPECT_NE(err.str().find("[5/5] "), std::string::npos) << err.str();
}

}  // namespace sweep_command_test
}  // namespace playerkit::amcl_offline
