#include "sweep_plan.hpp"

#include <gtest/gtest.h>

#include "exit_status.hpp"

namespace playerkit::amcl_offline {
namespace sweep_plan_test {

SweepSpec two_logs() {
  SweepLog orebro;
  orebro.name = "orebro";
  orebro.log = "/d/orebro-corrected.log.gz";
  orebro.map = "/d/orebro.yaml";
  orebro.truth = orebro.log;
  orebro.perturb_seed = 1;
  SweepLog cave;
  cave.name = "cave";
  cave.log = "/d/my logs/cave.log";  // a space: quoted in the job
  cave.map = "/d/cave.pnm";
  cave.truth = "/d/cave-truth.csv";
  cave.scale = 0.05;
  cave.negate = true;
  cave.origin = "0,0";
  cave.start = SweepStart::global;
  return {{orebro, cave}, {{"particles", {"100,5000", "500,5000"}}, {"sigma-hit", {"0.1", "0.2"}}}, {1, 2}};
}

TEST(SweepPlan, TheCrossProductLogsThenParametersThenSeeds) {
  const auto runs = expand_sweep(two_logs());
  ASSERT_EQ(runs.size(), 16U);
  EXPECT_EQ(runs[0].id, "orebro_particles=100+5000_sigma-hit=0.1_seed=1");
  EXPECT_EQ(runs[1].id, "orebro_particles=100+5000_sigma-hit=0.1_seed=2");
  EXPECT_EQ(runs[2].id, "orebro_particles=100+5000_sigma-hit=0.2_seed=1");
  EXPECT_EQ(runs[4].id, "orebro_particles=500+5000_sigma-hit=0.1_seed=1");
  EXPECT_EQ(runs[7].id, "orebro_particles=500+5000_sigma-hit=0.2_seed=2");
  EXPECT_EQ(runs[8].id, "cave_particles=100+5000_sigma-hit=0.1_seed=1");
  EXPECT_EQ(runs[15].log, 1U);
  EXPECT_EQ(runs[15].seed, 2U);
  EXPECT_EQ(runs[15].parameters,
            (std::vector<std::pair<std::string, std::string>>{{"particles", "500,5000"}, {"sigma-hit", "0.2"}}));
}

TEST(SweepPlan, NoParametersIsOneRunPerLogAndSeed) {
  SweepSpec spec = two_logs();
  spec.parameters.clear();
  spec.seeds = {7};
  const auto runs = expand_sweep(spec);
  ASSERT_EQ(runs.size(), 2U);
  EXPECT_EQ(runs[0].id, "orebro_seed=7");
  EXPECT_EQ(runs[1].id, "cave_seed=7");
}

TEST(SweepPlan, IdsThatWouldCollideAreRefused) {
  SweepSpec spec = two_logs();
  spec.parameters = {{"particles", {"100,5000", "100 5000"}}};
  EXPECT_THROW(expand_sweep(spec), tools::UsageError);
}

TEST(SweepPlan, ShellQuoting) {
  EXPECT_EQ(shell_quote("/a/b-c_d.e,f+g=h:i"), "/a/b-c_d.e,f+g=h:i");
  EXPECT_EQ(shell_quote("a b"), "'a b'");
  EXPECT_EQ(shell_quote("it's"), "'it'\\''s'");
  EXPECT_EQ(shell_quote("$HOME;x"), "'$HOME;x'");
  EXPECT_EQ(shell_quote(""), "''");
}

TEST(SweepPlan, JobLinesAreCompleteCommands) {
  const SweepSpec spec = two_logs();
  const auto runs = expand_sweep(spec);
  EXPECT_EQ(sweep_job_line(spec, runs[0], "/opt/bin/amcl-offline", "/s"),
            "rm -f /s/runs/orebro_particles=100+5000_sigma-hit=0.1_seed=1.eval.json "
            "/s/runs/orebro_particles=100+5000_sigma-hit=0.1_seed=1.failed && ("
            "(test -e /s/logs/orebro-perturb-1.log.gz || /opt/bin/amcl-offline perturb /d/orebro-corrected.log.gz "
            "-o /s/logs/orebro-perturb-1.log.gz --seed 1) && "
            "/opt/bin/amcl-offline localize /s/logs/orebro-perturb-1.log.gz --map /d/orebro.yaml --init-pose truth "
            "--particles 100,5000 --sigma-hit 0.1 --seed 1 -o /s/runs/orebro_particles=100+5000_sigma-hit=0.1_seed=1.csv"
            " && /opt/bin/amcl-offline eval /s/runs/orebro_particles=100+5000_sigma-hit=0.1_seed=1.csv "
            "--truth /d/orebro-corrected.log.gz --json > /s/runs/orebro_particles=100+5000_sigma-hit=0.1_seed=1.eval.json.tmp"
            " && mv /s/runs/orebro_particles=100+5000_sigma-hit=0.1_seed=1.eval.json.tmp "
            "/s/runs/orebro_particles=100+5000_sigma-hit=0.1_seed=1.eval.json"
            ") 2> /s/runs/orebro_particles=100+5000_sigma-hit=0.1_seed=1.err"
            " || (touch /s/runs/orebro_particles=100+5000_sigma-hit=0.1_seed=1.failed; exit 1)");
  EXPECT_EQ(sweep_job_line(spec, runs[15], "/opt/bin/amcl-offline", "/s"),
            "rm -f /s/runs/cave_particles=500+5000_sigma-hit=0.2_seed=2.eval.json "
            "/s/runs/cave_particles=500+5000_sigma-hit=0.2_seed=2.failed && ("
            "/opt/bin/amcl-offline localize '/d/my logs/cave.log' --map /d/cave.pnm --scale 0.05 --negate --origin 0,0 "
            "--global --particles 500,5000 --sigma-hit 0.2 --seed 2 -o /s/runs/cave_particles=500+5000_sigma-hit=0.2_seed=2.csv"
            " && /opt/bin/amcl-offline eval /s/runs/cave_particles=500+5000_sigma-hit=0.2_seed=2.csv "
            "--truth /d/cave-truth.csv --json > /s/runs/cave_particles=500+5000_sigma-hit=0.2_seed=2.eval.json.tmp"
            " && mv /s/runs/cave_particles=500+5000_sigma-hit=0.2_seed=2.eval.json.tmp "
            "/s/runs/cave_particles=500+5000_sigma-hit=0.2_seed=2.eval.json"
            ") 2> /s/runs/cave_particles=500+5000_sigma-hit=0.2_seed=2.err"
            " || (touch /s/runs/cave_particles=500+5000_sigma-hit=0.2_seed=2.failed; exit 1)");
}

TEST(SweepPlan, ABooleanParameterIsItsFlagOrNothing) {
  SweepSpec spec = two_logs();
  spec.logs.resize(1);
  spec.logs[0].perturb_seed.reset();
  spec.parameters = {{"every-reading", {"true", "false"}}};
  spec.seeds = {0};
  const auto runs = expand_sweep(spec);
  ASSERT_EQ(runs.size(), 2U);
  EXPECT_NE(sweep_job_line(spec, runs[0], "/b", "/s").find("--init-pose truth --every-reading --seed 0 -o "), std::string::npos);
  EXPECT_NE(sweep_job_line(spec, runs[1], "/b", "/s").find("--init-pose truth --seed 0 -o "), std::string::npos);
}

TEST(SweepPlan, TheSlurmArrayRunsOneLineATask) {
  EXPECT_EQ(sweep_sbatch_script("/shared/sweep", 8),
            "#!/bin/bash\n"
            "# amcl-offline sweep: 8 runs as a Slurm job array. Task i runs line i+1 of\n"
            "# /shared/sweep/jobs.txt; each writes only its own files in /shared/sweep/runs.\n"
            "#   sbatch /shared/sweep/sweep.sbatch\n"
            "# then, when the array is done: amcl-offline sweep collect /shared/sweep\n"
            "#SBATCH --job-name=amcl-sweep\n"
            "#SBATCH --array=0-7\n"
            "#SBATCH --ntasks=1\n"
            "#SBATCH --cpus-per-task=1\n"
            "#SBATCH --output=/shared/sweep/runs/slurm-%A_%a.out\n"
            "line=$(sed -n \"$((SLURM_ARRAY_TASK_ID + 1))p\" /shared/sweep/jobs.txt)\n"
            "exec /bin/sh -c \"$line\"\n");
}

TEST(SweepPlan, ThePlanListsEveryRunForCollect) {
  SweepSpec spec = two_logs();
  spec.logs.resize(1);
  spec.parameters.resize(1);
  spec.seeds = {1};
  EXPECT_EQ(sweep_plan_json(spec, expand_sweep(spec)),
            R"({
  "parameters": [
    "particles"
  ],
  "runs": [
    {
      "id": "orebro_particles=100+5000_seed=1",
      "log": "orebro",
      "parameters": {
        "particles": "100,5000"
      },
      "seed": 1
    },
    {
      "id": "orebro_particles=500+5000_seed=1",
      "log": "orebro",
      "parameters": {
        "particles": "500,5000"
      },
      "seed": 1
    }
  ]
}
)");
}

}  // namespace sweep_plan_test
}  // namespace playerkit::amcl_offline
