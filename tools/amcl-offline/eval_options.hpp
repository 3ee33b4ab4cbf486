#pragma once
// What `amcl-offline eval` was asked to do, checked: the estimates and truths
// as CLI11 fills them (EvalCommand) become the list of runs to score
// (EvalOptions), or a UsageError naming the flag at fault.
//
// Several runs at once: ESTIMATE may be given many times, and a directory
// stands for its *.csv files (sorted by name); --truth once scores every
// estimate against it, or once per estimate pairs them in order.

#include <string>
#include <vector>

#include "exit_status.hpp"

namespace playerkit::amcl_offline {

struct EvalCommand {
  std::vector<std::string> estimates;  // localize CSVs, or directories of them
  std::vector<std::string> truths;     // logs with true poses, or CSVs with time,x,y,yaw
  bool json = false;                   // --json: --format json
  std::string format;                  // text (default), markdown or json
};

enum class EvalFormat { text, markdown, json };

struct EvalRun {
  std::string estimate;
  std::string truth;
};

struct EvalOptions {
  std::vector<EvalRun> runs;
  EvalFormat format = EvalFormat::text;
};

// Throws tools::UsageError (an unreadable directory, a directory with no
// .csv, truths that pair with neither one nor every estimate, a bad format).
EvalOptions make_eval_options(const EvalCommand& command);

}  // namespace playerkit::amcl_offline
