#pragma once
// A sweep's runs (the cross product of logs x parameter values x seeds) and
// the files `sweep plan` writes into its directory DIR:
//
//   DIR/jobs.txt       one shell command per run: [perturb,] localize, eval --json;
//                      for `parallel < jobs.txt`, `sweep run`, and Slurm
//   DIR/sweep.sbatch   a Slurm array: task i runs line i+1 of jobs.txt
//   DIR/plan.json      the runs (id, log, parameter values, seed): what `sweep collect` reads
//   DIR/runs/ID.csv, ID.eval.json, ID.err (stderr), ID.failed (only when the job failed)
//
// Every path in them is absolute, so a job runs the same from any working
// directory on any machine that shares the filesystem. A job removes its old
// results first, so a rerun never shows an earlier run's figures.

#include <cstdint>
#include <filesystem>
#include <string>
#include <utility>
#include <vector>

#include "sweep_spec.hpp"

namespace playerkit::amcl_offline {

struct SweepRun {
  std::string id;  // e.g. "orebro_particles=100+5000_sigma-hit=0.1_seed=1"
  std::size_t log = 0;  // index into SweepSpec::logs
  std::vector<std::pair<std::string, std::string>> parameters;  // name, value; the spec's order
  std::uint64_t seed = 0;
};

// Logs outermost, then each parameter in the spec's order, seeds innermost.
// Throws tools::UsageError when two runs would get one id (values that
// differ only in characters an id replaces, e.g. "1,2" and "1+2").
std::vector<SweepRun> expand_sweep(const SweepSpec& spec);

// `word` as one shell word: as it is when it holds nothing a shell treats
// specially, else in single quotes.
std::string shell_quote(const std::string& word);

// The job of one run: a /bin/sh command line. `program` is the amcl-offline
// to run (absolute), `dir` the sweep directory (absolute).
std::string sweep_job_line(const SweepSpec& spec, const SweepRun& run, const std::filesystem::path& program,
                           const std::filesystem::path& dir);

// DIR/sweep.sbatch for `runs` jobs.
std::string sweep_sbatch_script(const std::filesystem::path& dir, std::size_t runs);

// plan.json's text.
std::string sweep_plan_json(const SweepSpec& spec, const std::vector<SweepRun>& runs);

// Writes jobs.txt, sweep.sbatch and plan.json into `dir` (created, with
// runs/ and logs/), each complete or not at all. Returns the job lines.
std::vector<std::string> write_sweep_plan(const SweepSpec& spec, const std::vector<SweepRun>& runs,
                                          const std::filesystem::path& program, const std::filesystem::path& dir);

}  // namespace playerkit::amcl_offline
