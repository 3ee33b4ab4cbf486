// nav-bench: the navigation loop (amcl, wavefront, vfh on a simulated
// Pioneer) sent to random goals in a Stage world, in simulated time; prints
// how it went. See --help.

#include <CLI/CLI.hpp>
#include <fstream>
#include <iostream>

#include <nlohmann/json.hpp>

#include "exit_status.hpp"
#include "goal_sampler.hpp"
#include "nav_bench_options.hpp"
#include "nav_report.hpp"
#include "navigation_loop.hpp"
#include "navigation_setup.hpp"
#include "parse_errors.hpp"

namespace {

namespace bench = playerkit::nav_bench;

constexpr const char* kFooter = R"(The loop is Player's classic one with this configuration's amcl, vfh and
wavefront sections (their maps replaced by the world's): the same pure cores
the drivers run, stepped in simulated time in one thread, so a world, a
configuration and a seed give the same run on any machine. Goals: uniformly
random free places 2 m or more from the previous one, reachable with the
planner's clearance, drawn from the seed. A goal succeeds when wavefront
says reached with the true pose within 0.30 m and 15 degrees of it, within
3 x its plan at 0.3 m/s + 20 s. The robot is relocalized on the truth after
a goal that ends with the estimate more than 0.5 m off, and says so.

Examples:
  nav-bench data/worlds/simple.world --config data/config/nav-sim.cfg --goals 5
  nav-bench data/worlds/nav-autolab.world --config data/config/nav-sim.cfg --seed 3 --format json
  scripts/nav-bench cave --goals 50        the same with a bundled world's name

Output: stdout, one line per goal and the totals (text), or
{"totals": {goals, success_pct, collisions, min_clearance_m, clearance_p1_m,
path_ratio_mean, time_mean_s, stuck_events, flips_per_m, replan_ms_max,
vfh_ms_p99, loc_err_mean_m, relocalized}, "goals": [...]} (json). Progress on stderr.

Exit status: 0 done, 1 runtime error (a bad world or configuration), 2 usage error.)";

int run(const bench::NavBenchOptions& options) {
  const bench::NavigationSetup setup = bench::read_navigation_setup(options.config);
  bench::NavigationLoop loop(options.world, setup, options.seed);
  std::ofstream trace;
  if (!options.trace.empty()) {
    trace.open(options.trace);
    if (!trace) throw std::runtime_error("cannot write the trace " + options.trace.string());
    trace << "time,truth_x,truth_y,truth_yaw,estimate_x,estimate_y,estimate_yaw,odometry_x,odometry_y,odometry_yaw,"
             "speed,turn_rate,vfh_goal_x,vfh_goal_y,vfh_goal_yaw,vfh_goal_active,stalled,vfh_phase\n";
    loop.set_step_observer([&trace](const bench::StepRecord& step) {
      trace << step.time << ',' << step.truth.x << ',' << step.truth.y << ',' << step.truth.yaw << ','
            << step.estimate.x << ',' << step.estimate.y << ',' << step.estimate.yaw << ',' << step.odometry.x << ','
            << step.odometry.y << ',' << step.odometry.yaw << ',' << step.speed << ',' << step.turn_rate << ','
            << step.local_goal.x << ',' << step.local_goal.y << ',' << step.local_goal.yaw << ','
            << step.local_goal_active << ',' << step.stalled << ',' << step.vfh_phase << '\n';
    });
  }
  const auto goals = bench::sample_goals(loop.reference_planner(), loop.true_pose(),
                                         {.count = options.goals, .seed = options.seed});
  std::vector<bench::GoalOutcome> outcomes;
  for (std::size_t i = 0; i < goals.size(); ++i) {
    outcomes.push_back(loop.drive_to(goals[i]));
    const bench::GoalOutcome& last = outcomes.back();
    std::cerr << "nav-bench: goal " << i + 1 << "/" << goals.size() << " (" << goals[i].x << ", " << goals[i].y
              << "): " << last.ending << " after " << last.time_s << " s\n";
  }
  const bench::RunTotals totals = bench::summarize(outcomes, loop.clearances(), loop.vfh_milliseconds());
  if (options.format == bench::ReportFormat::json) {
    std::cout << bench::to_json(outcomes, totals).dump(2) << "\n";
  } else {
    std::cout << bench::to_text(outcomes, totals);
  }
  return playerkit::tools::kExitOk;
}

}  // namespace

int main(int argc, char** argv) {
  CLI::App app{"nav-bench: the navigation loop (amcl, wavefront, vfh) driven to random goals in a simulated world"};
  app.footer(kFooter);
  app.set_version_flag("--version", std::string("nav-bench (playerkit) ") + PLAYERKIT_VERSION);
  bench::NavBenchCommandLine line;
  app.add_option("world", line.world, "Stage world file (its first robot with a laser is driven)")->required();
  app.add_option("--config", line.config, "configuration with the amcl, vfh and wavefront sections")->required();
  app.add_option("--goals", line.goals, "how many goals (default 50)");
  app.add_option("--seed", line.seed, "seed of the goals, the world's noise and the filter (default 1)");
  app.add_option("--format", line.format, "text or json (default text)");
  app.add_option("--trace", line.trace, "also write every step as CSV to this file (truth, estimate, commands)");
  try {
    app.parse(argc, argv);
  } catch (const CLI::ParseError& error) {
    return playerkit::tools::report_parse_error(app, error, std::cerr);
  }
  try {
    return run(bench::make_nav_bench_options(line));
  } catch (const bench::UsageError& e) {
    std::cerr << "nav-bench: " << e.what() << "\nRun with --help for more information.\n";
    return playerkit::tools::kExitUsage;
  } catch (const std::exception& e) {
    std::cerr << "nav-bench: " << e.what() << "\n";
    return playerkit::tools::kExitFailure;
  }
}
