// amcl-offline: post-hoc localization of recorded logs. See --help.

#include <CLI/CLI.hpp>
#include <iostream>
#include <unistd.h>

#include "parse_errors.hpp"
#include "commands.hpp"
#include "eval_command.hpp"
#include "plan_command.hpp"
#include "stop_signals.hpp"
#include "sweep_command.hpp"

namespace {

namespace offline = playerkit::amcl_offline;

constexpr const char* kFooter = R"(Logs: Player text logs or CARMEN logs (Radish), told apart by content, .gz too.
Odometry comes from the log's position data (CARMEN: the odom fields of FLASER).
Maps: a Player image (.pgm/.pnm/.png with --scale M_PER_PX, centred on the
origin as Player 1.5's map driver placed it, or with its bottom-left corner at
--origin X,Y: 0,0 for the bitmap of a Stage 1.3 world) or a ROS map_server .yaml.

Examples:
  amcl-offline map intel.log.gz -o intel.pgm --resolution 0.05      map + intel.yaml
  amcl-offline perturb intel.log.gz -o intel-odom.log --seed 1      degrade odometry, keep truth
  amcl-offline localize intel-odom.log --map intel.yaml --init-pose truth -o est.csv --plot est.png
  amcl-offline localize run.log --map cave.pnm --scale 0.03 --negate --global --seed 7
  amcl-offline localize sim.log --map cave.pnm --scale 0.03 --negate --origin 0,0 --init-pose truth
  amcl-offline eval est.csv --truth intel.log.gz
  amcl-offline eval runs/ --truth intel.log.gz --format markdown    a table: a row per runs/*.csv
  amcl-offline sweep run sweep.json -o sweep/ -j 2 --format markdown   logs x parameters x seeds

localize writes one row per scan: time,x,y,yaw,std_x,std_y,std_yaw,particles,cov_xy
(metres, radians; --format log: Player log localize:0 lines instead), and a one-line summary on stderr: scans, wall time,
real-time factor; then a warning for each stretch where the filter's own 2-sigma
passed 1 m or 60 degrees (lost, by its own account). eval reports the absolute
trajectory error (RMSE and max of position and heading), the time and distance
to convergence (within 0.3 m and 10 degrees for 5 s), and how often the truth
lay inside the claimed 2-sigma ellipse and heading interval.

Output files: -o and --plot may not name an input (also as ./x, a symlink or a hard
link: exit 2). Each is written to a temporary beside it and renamed at the end, so a
failure or a signal leaves an older file untouched; a name ending in .gz is written gzip.

Exit status: 0 done, 1 runtime error (unreadable log or map, cannot write),
2 usage error.)";

template <typename Body>
int guarded(Body&& body) {
  try {
    return body();
  } catch (const offline::UsageError& e) {
    std::cerr << "amcl-offline: " << e.what() << "\nRun with --help for more information.\n";
    return offline::kExitUsage;
  } catch (const std::exception& e) {
    std::cerr << "amcl-offline: " << e.what() << "\n";
    return offline::kExitFailure;
  }
}

}  // namespace

int main(int argc, char** argv) {
  CLI::App app{"amcl-offline SUBCOMMAND ...: Monte-Carlo localization on recorded logs, after the fact."};
  app.footer(kFooter);
  app.set_version_flag("--version", std::string("amcl-offline (playerkit) ") + PLAYERKIT_VERSION);
  app.require_subcommand(1);

  offline::MapCommand map;
  auto* map_app = app.add_subcommand("map", "build a map (PGM + YAML) from a log whose poses are correct");
  map_app->add_option("LOG", map.log, "log with truth or corrected poses")->required();
  map_app->add_option("-o,--output", map.output, "the .pgm to write (its .yaml goes beside it)")->required();
  map_app->add_option("--resolution", map.resolution, "metres per cell")->capture_default_str();
  map_app->add_option("--max-range", map.max_range, "readings beyond this only clear space (m)")->capture_default_str();
  map_app->add_option("--no-return-clears", map.no_return_clears,
                      "how far a no-return (max-range) reading clears space (m); 0: not at all, as glass and "
                      "black walls return nothing either")
      ->capture_default_str();
  map_app->add_flag("--use-odometry", map.use_odometry, "use odometry for scans without a true pose");

  offline::PerturbCommand perturb;
  auto& model = perturb.model;
  auto* perturb_app = app.add_subcommand("perturb", "copy a log with its odometry degraded, the true poses kept");
  perturb_app->add_option("LOG", perturb.log, "Player or CARMEN log")->required();
  perturb_app->add_option("-o,--output", perturb.output, "the log to write (- for stdout)")->required();
  perturb_app->add_option("--seed", perturb.seed, "random seed")->capture_default_str();
  perturb_app->add_option("--scale-error", model.translation_scale_error, "fraction added to every distance")
      ->capture_default_str();
  perturb_app->add_option("--rot-scale-error", model.rotation_scale_error, "fraction added to every turn")
      ->capture_default_str();
  perturb_app->add_option("--drift", model.heading_drift_rad_per_m, "systematic heading drift (rad per metre)")
      ->capture_default_str();
  perturb_app->add_option("--trans-noise", model.translation_noise_m_per_sqrt_m, "distance noise (m per sqrt(m))")
      ->capture_default_str();
  perturb_app->add_option("--rot-noise", model.rotation_noise_rad_per_sqrt_rad, "turn noise (rad per sqrt(rad))")
      ->capture_default_str();
  perturb_app->add_option("--slip-noise", model.rotation_noise_rad_per_sqrt_m, "heading noise from driving (rad per sqrt(m))")
      ->capture_default_str();

  offline::LocalizeCommand localize;
  auto* localize_app = app.add_subcommand("localize", "run amcl over a log: one estimate per scan");
  localize_app->add_option("LOG", localize.log, "Player or CARMEN log")->required();
  localize_app->add_option("--map", localize.map, "map image or ROS .yaml")->required();
  localize_app->add_option("--scale", localize.scale, "metres per pixel of a map image");
  localize_app->add_flag("--negate", localize.negate, "map image: white is occupied");
  localize_app->add_option("--origin", localize.origin, "X,Y: where a map image's bottom-left corner lies (default: centred)");
  localize_app->add_option("--init-pose", localize.init_pose, "X,Y,YAW_DEG, or 'truth' (the first true pose; scans before it are skipped)");
  localize_app->add_option("--init-var", localize.init_var, "standard deviations SX,SY,SYAW_DEG (default 0.1,0.1,3)");
  localize_app->add_flag("--global", localize.global,
                         "start anywhere in the free space: a search with 200 particles per m^2 of it");
  localize_app->add_option("--particles", localize.particles, "MIN,MAX particles (default 100,5000)");
  localize_app->add_option("--model", localize.model, "laser model: likelihood or beam")->capture_default_str();
  localize_app->add_option("--laser-beams", localize.laser_beams, "beams used per scan (default 30)");
  localize_app->add_option("--alpha-slow", localize.alpha_slow,
                           "augmented MCL slow average rate, e.g. 0.001 (default 0: no random particles)");
  localize_app->add_option("--alpha-fast", localize.alpha_fast,
                           "augmented MCL fast average rate, e.g. 0.1, above the slow one (default 0)");
  localize_app->add_option("--odom-noise", localize.odom_noise_scale, "scale the motion model's noise (default 1)");
  localize_app->add_option("--update-thresh", localize.update_thresh, "D,A_DEG: update after this motion (default 0.2,30)");
  localize_app->add_option("--sigma-hit", localize.sigma_hit, "laser hit noise in metres (default 0.2)");
  localize_app->add_flag("--every-reading", localize.every_reading,
                         "score every reading, also those cut short by what the map lacks (people, doors), as 1.5 did");
  localize_app->add_option("--seed", localize.seed, "random seed")->capture_default_str();
  localize_app->add_option("--format", localize.format, "csv, json (lines) or log (Player localize:0 lines)")->capture_default_str();
  localize_app->add_option("-o,--output", localize.output, "where the rows go (- for stdout)")->capture_default_str();
  localize_app->add_option("--plot", localize.plot, "PNG of the map, the paths and the last scan");

  offline::EvalCommand eval;
  auto* eval_app = app.add_subcommand("eval", "trajectory error of estimates against the truth: one report, or a table of runs");
  eval_app->add_option("ESTIMATE", eval.estimates, "CSVs from localize, or directories of them")->required();
  eval_app->add_option("--truth", eval.truths,
                       "a log with true poses, or a CSV with time,x,y,yaw: once for all estimates, or once each")
      ->required();
  eval_app->add_option("--format", eval.format, "text (default), markdown or json");
  eval_app->add_flag("--json", eval.json, "the same as --format json");

  offline::PlanCommand plan;
  auto* plan_app = app.add_subcommand("plan", "a path on a map keeping robot radius + safety from walls and unknown space");
  plan_app->add_option("--map", plan.map, "map image or ROS .yaml")->required();
  plan_app->add_option("--scale", plan.scale, "metres per pixel of a map image");
  plan_app->add_flag("--negate", plan.negate, "map image: white is occupied");
  plan_app->add_option("--origin", plan.origin, "X,Y: where a map image's bottom-left corner lies (default: centred)");
  plan_app->add_option("--start", plan.start, "X,Y in metres");
  plan_app->add_option("--goal", plan.goal, "X,Y in metres");
  plan_app->add_option("--track", plan.track, "a localize CSV: with --at, its estimate then is the start");
  plan_app->add_option("--at", plan.at, "T: the last estimate of --track at or before T seconds");
  plan_app->add_flag("--compare", plan.compare, "the path of --track against the plan between its ends");
  plan_app->add_option("--robot-radius", plan.robot_radius, "metres")->capture_default_str();
  plan_app->add_option("--safety", plan.safety, "metres kept beyond the radius")->capture_default_str();
  plan_app->add_option("--format", plan.format, "csv (default) or json; with --compare text (default) or json");
  plan_app->add_option("-o,--output", plan.output, "where the output goes (- for stdout)")->capture_default_str();
  plan_app->add_option("--plot", plan.plot, "PNG of the map, the path(s), start and goal");
  plan_app->footer(offline::kPlanHelpFooter);

  auto* sweep_app = app.add_subcommand("sweep", "many logs x parameter values x seeds: plan, run here or on a cluster, collect");
  sweep_app->require_subcommand(1);
  sweep_app->footer(offline::kSweepHelpFooter);
  offline::SweepPlanCommand sweep_plan;
  auto* sweep_plan_app = sweep_app->add_subcommand("plan", "write the jobs (jobs.txt for GNU parallel, sweep.sbatch for Slurm) into DIR");
  sweep_plan_app->add_option("SPEC", sweep_plan.spec, "the sweep's JSON spec")->required();
  sweep_plan_app->add_option("-o,--output", sweep_plan.dir, "the sweep's directory DIR")->required();
  sweep_plan_app->add_option("--amcl-offline", sweep_plan.program,
                             "the amcl-offline the jobs run, as the machines running them see it (default: this one)");
  offline::SweepRunCommand sweep_run;
  auto* sweep_run_app = sweep_app->add_subcommand("run", "plan, run the jobs here N at a time, then collect");
  sweep_run_app->add_option("SPEC", sweep_run.spec, "the sweep's JSON spec")->required();
  sweep_run_app->add_option("-o,--output", sweep_run.dir, "the sweep's directory DIR")->required();
  sweep_run_app->add_option("-j,--jobs", sweep_run.jobs, "runs at a time")->capture_default_str();
  sweep_run_app->add_option("--format", sweep_run.format, "the table: csv, markdown or json")->capture_default_str();
  sweep_run_app->add_option("--table", sweep_run.output, "where the table goes (- for stdout)")->capture_default_str();
  sweep_run_app->add_option("--plot", sweep_run.plot, "PNG: position RMSE per parameter value");
  offline::SweepCollectCommand sweep_collect;
  auto* sweep_collect_app = sweep_app->add_subcommand("collect", "every run's result in DIR as one table, wherever the jobs ran");
  sweep_collect_app->add_option("DIR", sweep_collect.dir, "the sweep's directory")->required();
  sweep_collect_app->add_option("--format", sweep_collect.format, "csv, markdown or json")->capture_default_str();
  sweep_collect_app->add_option("-o,--output", sweep_collect.output, "where the table goes (- for stdout)")->capture_default_str();
  sweep_collect_app->add_option("--plot", sweep_collect.plot, "PNG: position RMSE per parameter value");

  try {
    app.parse(argc, argv);
  } catch (const CLI::ParseError& e) {
    return playerkit::tools::report_parse_error(app, e, std::cerr);
  }
  playerkit::tools::ignore_broken_pipes();
  if (map_app->parsed()) return guarded([&] { return offline::run_map(offline::make_map_options(map), std::cerr); });
  if (perturb_app->parsed()) return guarded([&] { return offline::run_perturb(perturb, std::cout, std::cerr); });
  if (localize_app->parsed()) {
    localize.progress = isatty(STDERR_FILENO) == 1;
    return guarded([&] { return offline::run_localize(offline::make_localize_options(localize), std::cout, std::cerr); });
  }
  if (sweep_plan_app->parsed()) {
    return guarded([&] { return offline::run_sweep_plan(offline::make_sweep_plan_options(sweep_plan, offline::this_program(argv[0])), std::cerr); });
  }
  if (sweep_run_app->parsed()) {
    return guarded([&] { return offline::run_sweep_run(offline::make_sweep_run_options(sweep_run, offline::this_program(argv[0])), std::cout, std::cerr); });
  }
  if (sweep_collect_app->parsed()) {
    return guarded([&] { return offline::run_sweep_collect(offline::make_sweep_collect_options(sweep_collect), std::cout, std::cerr); });
  }
  if (plan_app->parsed()) return guarded([&] { return offline::run_plan(offline::make_plan_options(plan), std::cout, std::cerr); });
  return guarded([&] { return offline::run_eval(offline::make_eval_options(eval), std::cout, std::cerr); });
}
