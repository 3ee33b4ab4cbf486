#include "eval_command.hpp"

#include <algorithm>
#include <filesystem>
#include <iomanip>
#include <sstream>
#include <stdexcept>
#include <string>

#include <nlohmann/json.hpp>

#include "algorithms/geometry/pose2.hpp"
#include "localization/scan_order_matching.hpp"
#include "localization/trajectory.hpp"
#include "log/log_clock_reader.hpp"

namespace playerkit::amcl_offline {
namespace {

double degrees(double radians) { return radians / geometry::kRadiansPerDegree; }

void write_report(const EvalRun& run, const localization::TrajectoryEvaluation& result, std::ostream& out) {
  const auto row = [&](const char* name, const localization::ErrorStatistics& stats) {
    out << std::left << std::setw(18) << name << std::right << std::fixed << std::setprecision(3) << std::setw(8)
        << stats.position_rmse_m << std::setw(8) << stats.position_max_m << std::setprecision(2) << std::setw(9)
        << degrees(stats.heading_rmse_rad) << std::setw(9) << degrees(stats.heading_max_rad) << std::setw(8)
        << stats.count << "\n";
  };
  out << "matched " << result.matched << " of " << result.estimates << " estimates";
  if (result.matched_by_scan_order) out << " by scan order (" << run.truth << " has no usable times; seconds are file order)";
  out << "\n";
  out << std::left << std::setw(18) << "" << std::right << std::setw(8) << "rmse_m" << std::setw(8) << "max_m"
      << std::setw(9) << "rmse_deg" << std::setw(9) << "max_deg" << std::setw(8) << "rows" << "\n";
  row("all", result.all);
  if (result.converged()) {
    row("after convergence", result.after_convergence);
    out << std::setprecision(1) << "converged after " << *result.convergence_time_s << " s";
    if (result.convergence_distance_m) out << " and " << *result.convergence_distance_m << " m";
    out << "; lost " << result.lost_episodes << " time(s) afterwards";
    if (result.lost_episodes > 0) out << ", the longest for " << result.longest_lost_s << " s";
    out << "\n";
  } else {
    out << "never converged (within " << result.options.converged_position_m << " m and "
        << degrees(result.options.converged_heading_rad) << " deg)\n";
  }
  const localization::CoverageStatistics& coverage = result.coverage;
  if (coverage.rows > 0) {
    out << std::setprecision(1) << "the claimed 2-sigma held the truth in " << 100.0 * coverage.share() << "% of "
        << coverage.rows << " rows; " << coverage.confidently_wrong << " confidently wrong (off by more than "
        << std::setprecision(2) << result.options.confident_position_m << " m or " << std::setprecision(0)
        << degrees(result.options.confident_heading_rad) << " deg outside it)\n";
  }
}

// "97.3%", or "-" for an estimate that claims no spread.
std::string coverage_cell(const localization::CoverageStatistics& coverage) {
  if (coverage.rows == 0) return "-";
  std::ostringstream text;
  text << std::fixed << std::setprecision(1) << 100.0 * coverage.share() << "%";
  return text.str();
}

// One table row's cells, as text: the run, then its figures.
struct Row {
  std::vector<std::string> cells;
};

std::string fixed(double value, int digits) {
  std::ostringstream text;
  text << std::fixed << std::setprecision(digits) << value;
  return text.str();
}

const std::vector<std::string> kColumns{"estimate", "truth",       "matched", "rmse_m",    "max_m",
                                        "rmse_deg", "max_deg",     "converged_s", "lost", "in_2sigma"};

Row row_of(const EvalRun& run, const localization::TrajectoryEvaluation& result) {
  return {{run.estimate, run.truth, std::to_string(result.matched) + "/" + std::to_string(result.estimates),
           fixed(result.all.position_rmse_m, 3), fixed(result.all.position_max_m, 3),
           fixed(degrees(result.all.heading_rmse_rad), 2), fixed(degrees(result.all.heading_max_rad), 2),
           result.converged() ? fixed(*result.convergence_time_s, 1) : "never",
           std::to_string(result.lost_episodes), coverage_cell(result.coverage)}};
}

// Over all runs: mean RMSEs, worst maxima, how many converged, losses summed.
struct Summary {
  std::size_t runs = 0, converged = 0, lost = 0;
  double rmse_m_mean = 0, max_m = 0, rmse_deg_mean = 0, max_deg = 0;
  localization::CoverageStatistics coverage;  // every run's rows pooled
};

Summary summarize(const std::vector<localization::TrajectoryEvaluation>& results) {
  Summary summary;
  summary.runs = results.size();
  for (const auto& result : results) {
    summary.rmse_m_mean += result.all.position_rmse_m / static_cast<double>(results.size());
    summary.rmse_deg_mean += degrees(result.all.heading_rmse_rad) / static_cast<double>(results.size());
    summary.max_m = std::max(summary.max_m, result.all.position_max_m);
    summary.max_deg = std::max(summary.max_deg, degrees(result.all.heading_max_rad));
    summary.converged += result.converged() ? 1 : 0;
    summary.lost += result.lost_episodes;
    summary.coverage.rows += result.coverage.rows;
    summary.coverage.inside_2sigma += result.coverage.inside_2sigma;
    summary.coverage.confidently_wrong += result.coverage.confidently_wrong;
  }
  return summary;
}

Row summary_row(const Summary& summary) {
  return {{"all " + std::to_string(summary.runs) + " runs", "", "", fixed(summary.rmse_m_mean, 3),
           fixed(summary.max_m, 3), fixed(summary.rmse_deg_mean, 2), fixed(summary.max_deg, 2),
           std::to_string(summary.converged) + "/" + std::to_string(summary.runs) + " converged",
           std::to_string(summary.lost), coverage_cell(summary.coverage)}};
}

void write_json_table(const EvalOptions& options, const std::vector<localization::TrajectoryEvaluation>& results,
                      std::ostream& out) {
  nlohmann::json runs = nlohmann::json::array();
  for (std::size_t i = 0; i < results.size(); ++i) {
    runs.push_back({{"estimate", options.runs[i].estimate},
                    {"truth", options.runs[i].truth},
                    {"evaluation", nlohmann::json::parse(results[i].to_json())}});
  }
  const Summary summary = summarize(results);
  const nlohmann::json all{{"runs", summary.runs},
                           {"converged", summary.converged},
                           {"position_rmse_m_mean", summary.rmse_m_mean},
                           {"position_max_m", summary.max_m},
                           {"heading_rmse_deg_mean", summary.rmse_deg_mean},
                           {"heading_max_deg", summary.max_deg},
                           {"lost_episodes", summary.lost},
                           {"inside_2sigma_share", summary.coverage.rows > 0 ? nlohmann::json(summary.coverage.share())
                                                                             : nlohmann::json(nullptr)},
                           {"confidently_wrong", summary.coverage.confidently_wrong}};
  out << nlohmann::json{{"runs", runs}, {"all", all}}.dump(2) << "\n";
}

}  // namespace

localization::TrajectoryEvaluation evaluate_run(const EvalRun& run) {
  const auto estimate = localization::read_trajectory_csv(std::filesystem::path(run.estimate));
  const bool truth_is_csv = std::filesystem::path(run.truth).extension() == ".csv";
  const localization::Trajectory truth = truth_is_csv ? localization::read_trajectory_csv(std::filesystem::path(run.truth))
                                                      : localization::truth_from_log(run.truth);
  if (truth.empty()) throw std::runtime_error(run.truth + ": no true poses (a log needs truth or corrected poses)");
  // A log without usable times has only file order to pair by.
  const bool by_scan_order = !truth_is_csv && log::audit_log_times(run.truth)->synthetic();
  auto result = localization::evaluate_trajectory(
      by_scan_order ? localization::retimed_by_scan_order(estimate, truth) : estimate, truth);
  result.matched_by_scan_order = by_scan_order;
  return result;
}

void write_eval_table(const EvalOptions& options, const std::vector<localization::TrajectoryEvaluation>& results,
                      std::ostream& out) {
  if (options.format == EvalFormat::json) {
    write_json_table(options, results, out);
    return;
  }
  std::vector<Row> rows;
  for (std::size_t i = 0; i < results.size(); ++i) rows.push_back(row_of(options.runs[i], results[i]));
  rows.push_back(summary_row(summarize(results)));
  if (options.format == EvalFormat::markdown) {
    const auto line = [&out](const std::vector<std::string>& cells) {
      out << "|";
      for (const auto& cell : cells) out << " " << cell << " |";
      out << "\n";
    };
    line(kColumns);
    out << "|---|---|---:|---:|---:|---:|---:|---:|---:|---:|\n";
    for (const Row& row : rows) line(row.cells);
    return;
  }
  std::vector<std::size_t> widths;
  for (const auto& name : kColumns) widths.push_back(name.size());
  for (const Row& row : rows) {
    for (std::size_t c = 0; c < row.cells.size(); ++c) widths[c] = std::max(widths[c], row.cells[c].size());
  }
  const auto line = [&](const std::vector<std::string>& cells) {
    for (std::size_t c = 0; c < cells.size(); ++c) {
      // Names left, figures right.
      if (c < 2) {
        out << std::left << std::setw(static_cast<int>(widths[c])) << cells[c];
      } else {
        out << std::right << std::setw(static_cast<int>(widths[c])) << cells[c];
      }
      out << (c + 1 < cells.size() ? "  " : "\n");
    }
  };
  line(kColumns);
  for (const Row& row : rows) line(row.cells);
}

int run_eval(const EvalOptions& options, std::ostream& out, std::ostream& err) {
  std::vector<localization::TrajectoryEvaluation> results;
  for (const EvalRun& run : options.runs) results.push_back(evaluate_run(run));
  if (results.size() == 1 && options.format == EvalFormat::text) {
    write_report(options.runs.front(), results.front(), out);
  } else if (results.size() == 1 && options.format == EvalFormat::json) {
    out << results.front().to_json() << "\n";
  } else {
    write_eval_table(options, results, out);
  }
  (void)err;
  return tools::kExitOk;
}

}  // namespace playerkit::amcl_offline
