#pragma once
// The spec of `amcl-offline sweep`: which logs (each with its map and truth),
// how the filter starts, a grid of localize parameters and the seeds. A small
// JSON file, so that a dataset or an ablation is written down once and its
// runs can be planned, run here or on a cluster, and collected again:
//
//   {
//     "logs": [{"name": "orebro", "log": "orebro-corrected.log.gz",
//               "map": "orebro.yaml", "perturb_seed": 1}],
//     "start": "truth",
//     "parameters": {"particles": ["100,5000", "500,5000"], "sigma-hit": [0.1, 0.2]},
//     "seeds": [1, 2]
//   }
//
// Relative paths are taken from the spec file's directory and made absolute,
// so the planned jobs run from any working directory of any machine that
// sees the same filesystem.

#include <cstdint>
#include <filesystem>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace playerkit::amcl_offline {

enum class SweepStart { truth, global };

struct SweepLog {
  std::string name;                  // in run ids and the table; [A-Za-z0-9.-] (ids join with _)
  std::filesystem::path log;         // absolute
  std::filesystem::path map;         // absolute
  std::filesystem::path truth;       // absolute; the log itself by default
  std::optional<double> scale;       // localize --scale (map images)
  bool negate = false;               // localize --negate
  std::optional<std::string> origin; // localize --origin X,Y
  // When set, each run first perturbs the (corrected) log with this seed
  // (amcl-offline perturb's default model) and localizes on the copy.
  std::optional<std::uint64_t> perturb_seed;
  SweepStart start = SweepStart::truth;
};

// One axis of the grid: a localize flag (without its dashes) and its values
// as command-line text. A boolean flag (every-reading) has "true"/"false".
struct SweepParameter {
  std::string name;
  std::vector<std::string> values;
};

struct SweepSpec {
  std::vector<SweepLog> logs;
  std::vector<SweepParameter> parameters;  // in the spec's order
  std::vector<std::uint64_t> seeds;        // localize --seed
};

// The localize flags a grid may vary; the sweep itself sets the log, map,
// start, seed and outputs.
const std::vector<std::string>& sweep_parameter_names();
bool is_boolean_sweep_parameter(std::string_view name);

// Throws tools::UsageError: "SOURCE:LINE:COL: ..." for JSON syntax, else
// "SOURCE: FIELD.PATH: ..." naming the field at fault.
SweepSpec parse_sweep_spec(std::string_view text, const std::string& source, const std::filesystem::path& base_dir);

// Reads and parses a spec file (relative paths from its directory).
SweepSpec read_sweep_spec(const std::filesystem::path& file);

}  // namespace playerkit::amcl_offline
