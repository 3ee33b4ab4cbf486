#include "sweep_collect.hpp"

#include <fstream>
#include <iomanip>
#include <regex>
#include <sstream>
#include <stdexcept>

#include <nlohmann/json.hpp>

namespace playerkit::amcl_offline {
namespace sweep_collect_detail {

std::optional<std::string> read_text(const std::filesystem::path& path) {
  std::ifstream in(path, std::ios::binary);
  if (!in) return std::nullopt;
  std::ostringstream text;
  text << in.rdbuf();
  return text.str();
}

nlohmann::json read_json(const std::filesystem::path& path, const std::string& text) {
  try {
    return nlohmann::json::parse(text);
  } catch (const nlohmann::json::exception& e) {
    throw std::runtime_error(path.string() + ": not JSON: " + e.what());
  }
}

void read_evaluation(const std::filesystem::path& path, const std::string& text, SweepResult& result) {
  const nlohmann::json json = read_json(path, text);
  try {
    const bool converged = json.at("converged").get<bool>();
    const auto& stats = json.at(converged ? "after_convergence" : "all");
    result.position_rmse_m = stats.at("position_rmse_m").get<double>();
    result.position_max_m = stats.at("position_max_m").get<double>();
    result.heading_rmse_deg = stats.at("heading_rmse_rad").get<double>() * 180.0 / 3.14159265358979323846;
    if (converged) result.converged_after_s = json.at("convergence_time_s").get<double>();
    result.lost = json.at("lost_episodes").get<std::size_t>();
  } catch (const nlohmann::json::exception& e) {
    throw std::runtime_error(path.string() + ": not an eval --json result: " + e.what());
  }
}

std::string fixed(double value, int digits) {
  std::ostringstream text;
  text << std::fixed << std::setprecision(digits) << value;
  return text.str();
}

const char* status_name(SweepStatus status) {
  switch (status) {
    case SweepStatus::ok: return "ok";
    case SweepStatus::failed: return "failed";
    case SweepStatus::missing: return "missing";
  }
  return "?";
}

std::vector<std::string> header(const SweepTable& table) {
  std::vector<std::string> cells{"log"};
  cells.insert(cells.end(), table.parameters.begin(), table.parameters.end());
  for (const char* name : {"seed", "status", "rmse_m", "max_m", "rmse_deg", "converged_s", "lost", "wall_s", "realtime"}) {
    cells.emplace_back(name);
  }
  return cells;
}

// Timing last: a comparison of two sweeps' figures cuts it off.
std::vector<std::string> cells(const SweepResult& run) {
  std::vector<std::string> row{run.log};
  row.insert(row.end(), run.parameters.begin(), run.parameters.end());
  row.push_back(std::to_string(run.seed));
  row.emplace_back(status_name(run.status));
  if (run.status != SweepStatus::ok) {
    row.insert(row.end(), 7, "");
    return row;
  }
  row.push_back(fixed(run.position_rmse_m, 3));
  row.push_back(fixed(run.position_max_m, 3));
  row.push_back(fixed(run.heading_rmse_deg, 2));
  row.push_back(run.converged_after_s ? fixed(*run.converged_after_s, 1) : "never");
  row.push_back(std::to_string(run.lost));
  row.push_back(run.wall_s ? fixed(*run.wall_s, 2) : "");
  row.push_back(run.real_time_factor ? fixed(*run.real_time_factor, 0) : "");
  return row;
}

std::string csv_cell(const std::string& cell) {
  if (cell.find_first_of(",\"\n") == std::string::npos) return cell;
  std::string quoted = "\"";
  for (const char c : cell) quoted += c == '"' ? std::string("\"\"") : std::string(1, c);
  return quoted + "\"";
}

nlohmann::ordered_json json_row(const SweepTable& table, const SweepResult& run) {
  nlohmann::ordered_json parameters = nlohmann::ordered_json::object();
  for (std::size_t i = 0; i < table.parameters.size(); ++i) parameters[table.parameters[i]] = run.parameters[i];
  nlohmann::ordered_json row{{"id", run.id}, {"log", run.log}, {"parameters", parameters}, {"seed", run.seed},
                             {"status", status_name(run.status)}};
  const auto optional = [](const std::optional<double>& value) { return value ? nlohmann::ordered_json(*value) : nlohmann::ordered_json(); };
  if (run.status == SweepStatus::ok) {
    row["position_rmse_m"] = run.position_rmse_m;
    row["position_max_m"] = run.position_max_m;
    row["heading_rmse_deg"] = run.heading_rmse_deg;
    row["converged_after_s"] = optional(run.converged_after_s);
    row["lost_episodes"] = run.lost;
    row["wall_s"] = optional(run.wall_s);
    row["real_time_factor"] = optional(run.real_time_factor);
  }
  return row;
}

}  // namespace sweep_collect_detail

void read_localize_summary(const std::string& stderr_text, SweepResult& result) {
  // "amcl-offline: 237 scans (236 updates) in 0.21 s wall, 48.9 s of log: 233x real time"
  static const std::regex wall(R"( in ([0-9.]+) s wall)");
  static const std::regex real_time(R"(: ([0-9.]+)x real time)");
  std::smatch match;
  if (std::regex_search(stderr_text, match, wall)) result.wall_s = std::stod(match[1].str());
  if (std::regex_search(stderr_text, match, real_time)) result.real_time_factor = std::stod(match[1].str());
}

SweepTable collect_sweep(const std::filesystem::path& dir) {
  namespace detail = sweep_collect_detail;
  const auto plan_path = dir / "plan.json";
  const auto plan_text = detail::read_text(plan_path);
  if (!plan_text) throw std::runtime_error(plan_path.string() + ": cannot read (is " + dir.string() + " a sweep's directory? `sweep plan` writes it)");
  const nlohmann::json plan = detail::read_json(plan_path, *plan_text);
  SweepTable table;
  try {
    for (const auto& name : plan.at("parameters")) table.parameters.push_back(name.get<std::string>());
    for (const auto& entry : plan.at("runs")) {
      SweepResult run;
      run.id = entry.at("id").get<std::string>();
      run.log = entry.at("log").get<std::string>();
      run.seed = entry.at("seed").get<std::uint64_t>();
      for (const auto& name : table.parameters) run.parameters.push_back(entry.at("parameters").at(name).get<std::string>());
      table.runs.push_back(std::move(run));
    }
  } catch (const nlohmann::json::exception& e) {
    throw std::runtime_error(plan_path.string() + ": not a sweep plan: " + e.what());
  }
  for (auto& run : table.runs) {
    const auto base = dir / "runs" / run.id;
    if (const auto eval = detail::read_text(base.string() + ".eval.json")) {
      detail::read_evaluation(base.string() + ".eval.json", *eval, run);
      run.status = SweepStatus::ok;
      if (const auto err = detail::read_text(base.string() + ".err")) read_localize_summary(*err, run);
    } else if (std::filesystem::exists(base.string() + ".failed")) {
      run.status = SweepStatus::failed;
    }
  }
  return table;
}

void write_sweep_table(const SweepTable& table, SweepTableFormat format, std::ostream& out) {
  namespace detail = sweep_collect_detail;
  if (format == SweepTableFormat::json) {
    nlohmann::ordered_json runs = nlohmann::ordered_json::array();
    for (const auto& run : table.runs) runs.push_back(detail::json_row(table, run));
    out << nlohmann::ordered_json{{"parameters", table.parameters}, {"runs", runs}}.dump(2) << "\n";
    return;
  }
  const auto head = detail::header(table);
  if (format == SweepTableFormat::csv) {
    const auto line = [&out](const std::vector<std::string>& cells) {
      for (std::size_t i = 0; i < cells.size(); ++i) out << (i ? "," : "") << detail::csv_cell(cells[i]);
      out << "\n";
    };
    line(head);
    for (const auto& run : table.runs) line(detail::cells(run));
    return;
  }
  const auto line = [&out](const std::vector<std::string>& cells) {
    out << "|";
    for (const auto& cell : cells) out << " " << cell << " |";
    out << "\n";
  };
  line(head);
  // Names left, figures right.
  out << "|";
  for (std::size_t i = 0; i < head.size(); ++i) out << (i <= table.parameters.size() ? "---|" : "---:|");
  out << "\n";
  for (const auto& run : table.runs) line(detail::cells(run));
}

std::string sweep_tally(const SweepTable& table) {
  std::size_t ok = 0, failed = 0, missing = 0;
  for (const auto& run : table.runs) {
    (run.status == SweepStatus::ok ? ok : run.status == SweepStatus::failed ? failed : missing) += 1;
  }
  return std::to_string(table.runs.size()) + " runs: " + std::to_string(ok) + " ok, " + std::to_string(failed) +
         " failed, " + std::to_string(missing) + " missing";
}

}  // namespace playerkit::amcl_offline
