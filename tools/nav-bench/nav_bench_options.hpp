#pragma once
// nav-bench's flags turned into what the run needs, with the checks and
// their messages (tools::UsageError: exit status 2).

#include <cstdint>
#include <filesystem>
#include <string>

#include "exit_status.hpp"

namespace playerkit::nav_bench {

using tools::UsageError;

enum class ReportFormat { text, json };

struct NavBenchCommandLine {
  std::string world;   // a Stage world file
  std::string config;  // the amcl, vfh and wavefront sections
  int goals = 50;
  std::uint64_t seed = 1;
  std::string format = "text";
  std::string trace;   // empty: none
};

struct NavBenchOptions {
  std::filesystem::path world;
  std::filesystem::path config;
  int goals = 50;
  std::uint64_t seed = 1;
  ReportFormat format = ReportFormat::text;
  std::filesystem::path trace;
};

NavBenchOptions make_nav_bench_options(const NavBenchCommandLine& line);

}  // namespace playerkit::nav_bench
