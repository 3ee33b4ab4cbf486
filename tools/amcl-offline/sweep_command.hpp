#pragma once
// `amcl-offline sweep plan|run|collect`: the flags as CLI11 fills them
// (*Command) become checked options (*Options, or a UsageError naming the
// flag or the spec's field), and the subcommands run on them. The work is in
// sweep_spec (the spec file), sweep_plan (runs, job lines, Slurm script),
// sweep_collect (the table, the plot); here only what ties them together and
// the local runner.

#include <cstddef>
#include <filesystem>
#include <optional>
#include <ostream>
#include <string>
#include <vector>

#include "exit_status.hpp"
#include "sweep_collect.hpp"
#include "sweep_spec.hpp"

namespace playerkit::amcl_offline {

// `amcl-offline sweep --help`'s footer: the spec, the files, the cluster.
extern const char* const kSweepHelpFooter;

struct SweepPlanCommand {
  std::string spec;
  std::string dir;                     // -o
  std::optional<std::string> program;  // --amcl-offline: the binary the jobs run (default: this one)
};

struct SweepCollectCommand {
  std::string dir;
  std::string format = "csv";
  std::string output = "-";
  std::optional<std::string> plot;
};

struct SweepRunCommand {
  std::string spec;
  std::string dir;  // -o
  unsigned jobs = 1;
  std::string format = "csv";
  std::string output = "-";
  std::optional<std::string> plot;
};

struct SweepPlanOptions {
  SweepSpec spec;
  std::filesystem::path dir;      // absolute
  std::filesystem::path program;  // absolute
};

struct SweepCollectOptions {
  std::filesystem::path dir;
  SweepTableFormat format = SweepTableFormat::csv;
  std::string output = "-";
  std::optional<std::string> plot;
};

struct SweepRunOptions {
  SweepPlanOptions plan;
  unsigned jobs = 1;
  SweepCollectOptions collect;
};

// `self` is this program's absolute path (/proc/self/exe), used unless
// --amcl-offline names another. Throws tools::UsageError.
SweepPlanOptions make_sweep_plan_options(const SweepPlanCommand& command, const std::filesystem::path& self);
SweepCollectOptions make_sweep_collect_options(const SweepCollectCommand& command);
SweepRunOptions make_sweep_run_options(const SweepRunCommand& command, const std::filesystem::path& self);

// This program's absolute path: /proc/self/exe, else argv[0] made absolute.
std::filesystem::path this_program(const char* argv0);

struct SweepJob {
  std::string id;
  std::string command;  // a /bin/sh command line
};

// Runs the jobs with at most `parallel` at once (each `/bin/sh -c COMMAND`),
// reporting each end on `err`; a failed job does not stop the others. After
// SIGINT/SIGTERM (tools::stop_requested) no further job starts. Returns how
// many failed (or were not started).
std::size_t run_sweep_jobs(const std::vector<SweepJob>& jobs, unsigned parallel, std::ostream& err);

int run_sweep_plan(const SweepPlanOptions& options, std::ostream& err);
int run_sweep_collect(const SweepCollectOptions& options, std::ostream& out, std::ostream& err);
int run_sweep_run(const SweepRunOptions& options, std::ostream& out, std::ostream& err);

}  // namespace playerkit::amcl_offline
