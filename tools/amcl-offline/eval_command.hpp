#pragma once
// `amcl-offline eval`: each run's estimate scored against its truth
// (localization::evaluate_trajectory). One run prints its full report (text,
// or one JSON object); several, or --format markdown, print one table with a
// row per run and a last row over all of them: the report to paste.

#include <ostream>
#include <vector>

#include "eval_options.hpp"
#include "localization/trajectory_evaluation.hpp"

namespace playerkit::amcl_offline {

// One run's score. A truth log without usable times pairs by scan order.
localization::TrajectoryEvaluation evaluate_run(const EvalRun& run);

int run_eval(const EvalOptions& options, std::ostream& out, std::ostream& err);

// The table of several runs' scores (results[i] is options.runs[i]'s).
void write_eval_table(const EvalOptions& options, const std::vector<localization::TrajectoryEvaluation>& results,
                      std::ostream& out);

}  // namespace playerkit::amcl_offline
