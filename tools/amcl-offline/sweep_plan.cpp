#include "sweep_plan.hpp"

#include <algorithm>
#include <cctype>
#include <charconv>
#include <iostream>
#include <set>

#include <nlohmann/json.hpp>

#include "exit_status.hpp"
#include "output_file.hpp"

namespace playerkit::amcl_offline {
namespace sweep_plan_detail {

// A value in a run id (a file name): characters other than letters, digits,
// '.' and '-' become '+' ("100,5000" -> "100+5000").
std::string id_part(const std::string& value) {
  std::string part = value;
  for (char& c : part) {
    if (std::isalnum(static_cast<unsigned char>(c)) == 0 && c != '.' && c != '-') c = '+';
  }
  return part;
}

// Shortest text that reads back as the same double (0.05, not 0.05000000000000000277).
std::string number_text(double value) {
  char buffer[64];
  const auto result = std::to_chars(buffer, buffer + sizeof buffer, value);
  return std::string(buffer, result.ptr);
}


}  // namespace sweep_plan_detail

std::vector<SweepRun> expand_sweep(const SweepSpec& spec) {
  std::vector<SweepRun> runs;
  for (std::size_t log = 0; log < spec.logs.size(); ++log) {
    // Odometer over the parameter axes: the last axis turns fastest.
    std::vector<std::size_t> at(spec.parameters.size(), 0);
    for (bool more = true; more;) {
      for (const std::uint64_t seed : spec.seeds) {
        SweepRun run;
        run.log = log;
        run.seed = seed;
        run.id = spec.logs[log].name;
        for (std::size_t p = 0; p < spec.parameters.size(); ++p) {
          const auto& axis = spec.parameters[p];
          run.parameters.emplace_back(axis.name, axis.values[at[p]]);
          run.id += "_" + axis.name + "=" + sweep_plan_detail::id_part(axis.values[at[p]]);
        }
        run.id += "_seed=" + std::to_string(seed);
        runs.push_back(std::move(run));
      }
      more = false;
      for (std::size_t p = spec.parameters.size(); p-- > 0;) {
        if (++at[p] < spec.parameters[p].values.size()) {
          more = true;
          break;
        }
        at[p] = 0;
      }
    }
  }
  std::set<std::string> ids;
  for (const auto& run : runs) {
    if (!ids.insert(run.id).second) {
      throw tools::UsageError("two runs would share the id " + run.id +
                              ": parameter values may not differ only in characters other than letters, digits, '.' and '-'");
    }
  }
  return runs;
}

std::string shell_quote(const std::string& word) {
  const bool plain = !word.empty() && std::all_of(word.begin(), word.end(), [](char c) {
    return std::isalnum(static_cast<unsigned char>(c)) != 0 || std::string_view("_./,+=:@%-").find(c) != std::string_view::npos;
  });
  if (plain) return word;
  std::string quoted = "'";
  for (const char c : word) quoted += c == '\'' ? std::string("'\\''") : std::string(1, c);
  return quoted + "'";
}

std::string sweep_job_line(const SweepSpec& spec, const SweepRun& run, const std::filesystem::path& program,
                           const std::filesystem::path& dir) {
  const SweepLog& log = spec.logs.at(run.log);
  const auto q = [](const std::filesystem::path& path) { return shell_quote(path.string()); };
  const std::string bin = q(program);
  const std::string result = q(dir / "runs" / run.id);  // + .csv, .eval.json, ...
  std::string line = "rm -f " + result + ".eval.json " + result + ".failed && (";
  std::filesystem::path input = log.log;
  if (log.perturb_seed) {
    // One perturbed copy per log and seed, shared by its runs: perturb writes
    // a temporary and renames it, so two jobs making it at once both leave
    // the same whole file.
    input = dir / "logs" / (log.name + "-perturb-" + std::to_string(*log.perturb_seed) + ".log.gz");
    line += "(test -e " + q(input) + " || " + bin + " perturb " + q(log.log) + " -o " + q(input) +
            " --seed " + std::to_string(*log.perturb_seed) + ") && ";
  }
  line += bin + " localize " + q(input) + " --map " + q(log.map);
  if (log.scale) line += " --scale " + sweep_plan_detail::number_text(*log.scale);
  if (log.negate) line += " --negate";
  if (log.origin) line += " --origin " + shell_quote(*log.origin);
  line += log.start == SweepStart::global ? " --global" : " --init-pose truth";
  for (const auto& [name, value] : run.parameters) {
    if (is_boolean_sweep_parameter(name)) {
      if (value == "true") line += " --" + name;
    } else {
      line += " --" + name + " " + shell_quote(value);
    }
  }
  line += " --seed " + std::to_string(run.seed) + " -o " + result + ".csv";
  line += " && " + bin + " eval " + result + ".csv --truth " + q(log.truth) + " --json > " + result +
          ".eval.json.tmp && mv " + result + ".eval.json.tmp " + result + ".eval.json";
  line += ") 2> " + result + ".err || (touch " + result + ".failed; exit 1)";
  return line;
}

std::string sweep_sbatch_script(const std::filesystem::path& dir, std::size_t runs) {
  const std::string jobs = (dir / "jobs.txt").string();
  std::string text = "#!/bin/bash\n";
  text += "# amcl-offline sweep: " + std::to_string(runs) + " runs as a Slurm job array. Task i runs line i+1 of\n";
  text += "# " + jobs + "; each writes only its own files in " + (dir / "runs").string() + ".\n";
  text += "#   sbatch " + (dir / "sweep.sbatch").string() + "\n";
  text += "# then, when the array is done: amcl-offline sweep collect " + dir.string() + "\n";
  text += "#SBATCH --job-name=amcl-sweep\n";
  text += "#SBATCH --array=0-" + std::to_string(runs == 0 ? 0 : runs - 1) + "\n";
  text += "#SBATCH --ntasks=1\n";
  text += "#SBATCH --cpus-per-task=1\n";
  text += "#SBATCH --output=" + (dir / "runs" / "slurm-%A_%a.out").string() + "\n";
  text += "line=$(sed -n \"$((SLURM_ARRAY_TASK_ID + 1))p\" " + shell_quote(jobs) + ")\n";
  text += "exec /bin/sh -c \"$line\"\n";
  return text;
}

std::string sweep_plan_json(const SweepSpec& spec, const std::vector<SweepRun>& runs) {
  nlohmann::ordered_json parameters = nlohmann::ordered_json::array();
  for (const auto& axis : spec.parameters) parameters.push_back(axis.name);
  nlohmann::ordered_json list = nlohmann::ordered_json::array();
  for (const auto& run : runs) {
    nlohmann::ordered_json values = nlohmann::ordered_json::object();
    for (const auto& [name, value] : run.parameters) values[name] = value;
    list.push_back({{"id", run.id}, {"log", spec.logs[run.log].name}, {"parameters", values}, {"seed", run.seed}});
  }
  return nlohmann::ordered_json{{"parameters", parameters}, {"runs", list}}.dump(2) + "\n";
}

std::vector<std::string> write_sweep_plan(const SweepSpec& spec, const std::vector<SweepRun>& runs,
                                          const std::filesystem::path& program, const std::filesystem::path& dir) {
  std::filesystem::create_directories(dir / "runs");
  std::filesystem::create_directories(dir / "logs");
  std::vector<std::string> lines;
  for (const auto& run : runs) lines.push_back(sweep_job_line(spec, run, program, dir));
  const auto write = [](const std::filesystem::path& path, const std::string& text) {
    tools::OutputFile file(path.string(), std::cout);
    file.stream() << text;
    file.check();
    file.commit();
  };
  std::string jobs;
  for (const auto& line : lines) jobs += line + "\n";
  write(dir / "jobs.txt", jobs);
  write(dir / "sweep.sbatch", sweep_sbatch_script(dir, runs.size()));
  write(dir / "plan.json", sweep_plan_json(spec, runs));
  std::filesystem::permissions(dir / "sweep.sbatch", std::filesystem::perms::owner_exec | std::filesystem::perms::group_exec,
                               std::filesystem::perm_options::add);
  return lines;
}

}  // namespace playerkit::amcl_offline
