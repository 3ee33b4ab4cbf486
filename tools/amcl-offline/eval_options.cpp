#include "eval_options.hpp"

#include <algorithm>
#include <filesystem>
#include <system_error>

namespace playerkit::amcl_offline {
namespace {

EvalFormat parse_eval_format(const EvalCommand& command) {
  if (command.json) {
    if (!command.format.empty() && command.format != "json") {
      throw tools::UsageError("--json and --format " + command.format + " exclude each other");
    }
    return EvalFormat::json;
  }
  if (command.format.empty() || command.format == "text") return EvalFormat::text;
  if (command.format == "markdown" || command.format == "md") return EvalFormat::markdown;
  if (command.format == "json") return EvalFormat::json;
  throw tools::UsageError("--format: '" + command.format + "' is not text, markdown or json");
}

// A directory's *.csv files, sorted; the path itself otherwise (a missing
// file is reported when it is read, naming it).
std::vector<std::string> expand_estimate(const std::string& path) {
  std::error_code error;
  if (!std::filesystem::is_directory(path, error)) return {path};
  std::vector<std::string> found;
  for (std::filesystem::directory_iterator entry(path, error), end; !error && entry != end; entry.increment(error)) {
    if (entry->path().extension() == ".csv" && entry->is_regular_file()) found.push_back(entry->path().string());
  }
  if (error) throw tools::UsageError(path + ": cannot list the directory: " + error.message());
  if (found.empty()) throw tools::UsageError(path + ": a directory without .csv estimates");
  std::sort(found.begin(), found.end());
  return found;
}

}  // namespace

EvalOptions make_eval_options(const EvalCommand& command) {
  EvalOptions options;
  options.format = parse_eval_format(command);
  std::vector<std::string> estimates;
  for (const std::string& path : command.estimates) {
    const auto expanded = expand_estimate(path);
    estimates.insert(estimates.end(), expanded.begin(), expanded.end());
  }
  if (estimates.empty()) throw tools::UsageError("ESTIMATE: no estimate to score");
  if (command.truths.size() != 1 && command.truths.size() != estimates.size()) {
    throw tools::UsageError("--truth: give one for every estimate, or one for all (" +
                            std::to_string(estimates.size()) + " estimates, " +
                            std::to_string(command.truths.size()) + " truths)");
  }
  for (std::size_t i = 0; i < estimates.size(); ++i) {
    options.runs.push_back({estimates[i], command.truths.size() == 1 ? command.truths[0] : command.truths[i]});
  }
  return options;
}

}  // namespace playerkit::amcl_offline
