#pragma once
// `amcl-offline sweep collect DIR`: every planned run's result in one table,
// wherever the jobs ran (sweep run, GNU parallel, Slurm): it reads only the
// files a job leaves in DIR/runs (sweep_plan.hpp). A run is "ok" when its
// ID.eval.json is there, "failed" when its job left ID.failed, else
// "missing" (not run yet, or still running).
//
// Errors are those after convergence when the run converged, else over all
// its rows (then "converged" says never). Wall time and real-time factor
// come from localize's summary line in ID.err (logs without usable times
// have no real-time factor).

#include <cstdint>
#include <filesystem>
#include <optional>
#include <ostream>
#include <string>
#include <vector>

namespace playerkit::amcl_offline {

enum class SweepStatus { ok, failed, missing };

struct SweepResult {
  std::string id;
  std::string log;
  std::vector<std::string> parameters;  // values, in SweepTable::parameters' order
  std::uint64_t seed = 0;
  SweepStatus status = SweepStatus::missing;
  // Set when ok:
  double position_rmse_m = 0, position_max_m = 0, heading_rmse_deg = 0;
  std::optional<double> converged_after_s;  // empty: never converged
  std::size_t lost = 0;
  std::optional<double> wall_s, real_time_factor;
};

struct SweepTable {
  std::vector<std::string> parameters;  // the grid's axes (flag names)
  std::vector<SweepResult> runs;        // plan.json's order
};

enum class SweepTableFormat { csv, markdown, json };

// Throws std::runtime_error when DIR has no readable plan.json or a result
// file is not what eval --json writes.
SweepTable collect_sweep(const std::filesystem::path& dir);

// The wall time and real-time factor on localize's summary line, when there.
void read_localize_summary(const std::string& stderr_text, SweepResult& result);

void write_sweep_table(const SweepTable& table, SweepTableFormat format, std::ostream& out);

// "8 runs: 7 ok, 1 failed, 0 missing"
std::string sweep_tally(const SweepTable& table);

// A PNG (lib/image's encoder): position RMSE of every ok run, a panel per
// parameter with more than one value (x: its values), points coloured by
// log; a single panel by log when no parameter varies.
void write_sweep_plot(const SweepTable& table, const std::filesystem::path& png);

}  // namespace playerkit::amcl_offline
