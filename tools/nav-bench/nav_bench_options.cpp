#include "nav_bench_options.hpp"

#include <system_error>

namespace playerkit::nav_bench {

namespace {

std::filesystem::path existing_file(const std::string& path, const std::string& what) {
  if (path.empty()) throw UsageError("name " + what);
  std::error_code error;
  if (!std::filesystem::is_regular_file(path, error)) throw UsageError(what + " '" + path + "': no such file");
  return path;
}

}  // namespace

NavBenchOptions make_nav_bench_options(const NavBenchCommandLine& line) {
  NavBenchOptions options;
  options.world = existing_file(line.world, "a world file");
  options.config = existing_file(line.config, "a configuration file (--config) with amcl, vfh and wavefront");
  if (line.goals < 1 || line.goals > 10000) {
    throw UsageError("--goals " + std::to_string(line.goals) + ": from 1 to 10000");
  }
  options.goals = line.goals;
  options.seed = line.seed;
  options.trace = line.trace;
  if (line.format == "text") {
    options.format = ReportFormat::text;
  } else if (line.format == "json") {
    options.format = ReportFormat::json;
  } else {
    throw UsageError("--format '" + line.format + "': text or json");
  }
  return options;
}

}  // namespace playerkit::nav_bench
