#include "sweep_command.hpp"

#include <algorithm>
#include <chrono>
#include <cerrno>
#include <map>
#include <sstream>
#include <iomanip>

#include <sys/wait.h>
#include <unistd.h>

#include "output_file.hpp"
#include "stop_signals.hpp"
#include "sweep_plan.hpp"

namespace playerkit::amcl_offline {
namespace sweep_command_detail {

SweepTableFormat table_format(const std::string& name) {
  if (name == "csv") return SweepTableFormat::csv;
  if (name == "markdown") return SweepTableFormat::markdown;
  if (name == "json") return SweepTableFormat::json;
  throw tools::UsageError("--format: csv, markdown or json, not '" + name + "'");
}

std::filesystem::path directory(const std::string& dir, const char* flag) {
  if (dir.empty()) throw tools::UsageError(std::string(flag) + ": the sweep's directory may not be empty");
  return std::filesystem::absolute(dir).lexically_normal();
}

// A child running `/bin/sh -c command`; -1 when it could not be started.
pid_t start(const std::string& command) {
  const pid_t pid = fork();
  if (pid == 0) {
    execl("/bin/sh", "sh", "-c", command.c_str(), static_cast<char*>(nullptr));
    _exit(127);
  }
  return pid;
}

std::string how_it_ended(int status) {
  if (WIFEXITED(status)) return "exit status " + std::to_string(WEXITSTATUS(status));
  if (WIFSIGNALED(status)) return "signal " + std::to_string(WTERMSIG(status));
  return "status " + std::to_string(status);
}

}  // namespace sweep_command_detail

const char* const kSweepHelpFooter = R"(The spec (JSON; relative paths from its own directory):
  {"logs": [{"name": "orebro", "log": "orebro-corrected.log.gz", "map": "orebro.yaml",
             "perturb_seed": 1},
            {"name": "fr101", "log": "fr101.log.gz", "map": "fr101.yaml", "truth": "fr101.log.gz",
             "start": "global"}],
   "start": "truth",
   "parameters": {"particles": ["100,5000", "500,5000"], "sigma-hit": [0.1, 0.2]},
   "seeds": [1, 2]}
A log entry may also give scale, negate and origin (localize's map flags). perturb_seed:
the runs localize a copy perturbed with that seed (perturb's default model). start: truth
(--init-pose truth) or global. parameters: any of --particles --model --laser-beams
--alpha-slow --alpha-fast --odom-noise --update-thresh --sigma-hit --init-var
--every-reading (true/false), each with its values; the runs are every log x every
combination of values x every seed (localize --seed).

DIR gets jobs.txt (a shell command per run, every path absolute), sweep.sbatch (a Slurm
array, task i runs line i+1), plan.json, and per run runs/ID.csv, ID.eval.json, ID.err
(stderr) and ID.failed when the job failed. Run ids name the log, the values and the seed:
orebro_particles=100+5000_sigma-hit=0.1_seed=1.

Examples:
  amcl-offline sweep run sweep.json -o sweep -j 2 --format markdown --plot rmse.png
  amcl-offline sweep plan sweep.json -o /shared/sweep        then, on any machine sharing /shared:
  parallel --jobs 2 < /shared/sweep/jobs.txt                  here, or over ssh:
  parallel --joblog /shared/sweep/joblog --sshloginfile HOSTS < /shared/sweep/jobs.txt
  sbatch /shared/sweep/sweep.sbatch                           a Slurm array
  amcl-offline sweep collect /shared/sweep --format markdown -o table.md --plot rmse.png

collect's table: a row per run (log, parameter values, seed, status ok/failed/missing,
position RMSE and max (m), heading RMSE (deg), converged after (s), lost count, wall time
(s), real-time factor); errors after convergence, or over all rows when it never converged.
Exit status: sweep run 1 when any run failed; collect 1 when any run failed or has no
result yet (the table is written all the same).)";

SweepPlanOptions make_sweep_plan_options(const SweepPlanCommand& command, const std::filesystem::path& self) {
  SweepPlanOptions options;
  options.spec = read_sweep_spec(command.spec);
  options.dir = sweep_command_detail::directory(command.dir, "-o");
  if (command.program) {
    if (command.program->empty()) throw tools::UsageError("--amcl-offline may not be empty");
    options.program = std::filesystem::absolute(*command.program).lexically_normal();
  } else {
    options.program = self;
  }
  return options;
}

SweepCollectOptions make_sweep_collect_options(const SweepCollectCommand& command) {
  SweepCollectOptions options;
  options.dir = sweep_command_detail::directory(command.dir, "DIR");
  options.format = sweep_command_detail::table_format(command.format);
  if (command.output.empty()) throw tools::UsageError("-o may not be empty (- for stdout)");
  options.output = command.output;
  if (command.plot && command.plot->empty()) throw tools::UsageError("--plot may not be empty");
  options.plot = command.plot;
  return options;
}

SweepRunOptions make_sweep_run_options(const SweepRunCommand& command, const std::filesystem::path& self) {
  SweepRunOptions options;
  if (command.jobs < 1) throw tools::UsageError("-j: at least 1 job at a time");
  options.jobs = command.jobs;
  options.plan = make_sweep_plan_options({command.spec, command.dir, std::nullopt}, self);
  options.collect = make_sweep_collect_options({command.dir, command.format, command.output, command.plot});
  return options;
}

std::filesystem::path this_program(const char* argv0) {
  std::error_code error;
  auto self = std::filesystem::read_symlink("/proc/self/exe", error);
  if (!error) return self;
  return std::filesystem::absolute(argv0 != nullptr ? argv0 : "amcl-offline").lexically_normal();
}

std::size_t run_sweep_jobs(const std::vector<SweepJob>& jobs, unsigned parallel, std::ostream& err) {
  namespace detail = sweep_command_detail;
  using Clock = std::chrono::steady_clock;
  struct Running {
    std::size_t index;
    Clock::time_point started;
  };
  std::map<pid_t, Running> running;
  std::size_t next = 0, done = 0, failed = 0;
  const auto report = [&](std::size_t index, const std::string& what) {
    err << "amcl-offline: sweep: [" << ++done << "/" << jobs.size() << "] " << jobs[index].id << " " << what << "\n";
  };
  while (next < jobs.size() || !running.empty()) {
    // Fill the free slots, unless asked to stop.
    while (next < jobs.size() && running.size() < std::max(parallel, 1U) && !tools::stop_requested()) {
      const pid_t pid = detail::start(jobs[next].command);
      if (pid < 0) {
        ++failed;
        report(next, "could not be started");
      } else {
        running[pid] = {next, Clock::now()};
      }
      ++next;
    }
    if (running.empty()) break;
    int status = 0;
    const pid_t pid = waitpid(-1, &status, 0);
    if (pid < 0) {
      if (errno == EINTR) continue;  // a signal: the loop checks stop_requested
      break;
    }
    const auto found = running.find(pid);
    if (found == running.end()) continue;  // not one of ours
    const double seconds = std::chrono::duration<double>(Clock::now() - found->second.started).count();
    std::ostringstream took;
    took << std::fixed << std::setprecision(1) << seconds << " s";
    if (WIFEXITED(status) && WEXITSTATUS(status) == 0) {
      report(found->second.index, "done in " + took.str());
    } else {
      ++failed;
      report(found->second.index, "FAILED (" + detail::how_it_ended(status) + ", after " + took.str() + ")");
    }
    running.erase(found);
  }
  if (next < jobs.size()) {
    err << "amcl-offline: sweep: stopped; " << jobs.size() - next << " runs not started\n";
    failed += jobs.size() - next;
  }
  return failed;
}

int run_sweep_plan(const SweepPlanOptions& options, std::ostream& err) {
  const auto runs = expand_sweep(options.spec);
  write_sweep_plan(options.spec, runs, options.program, options.dir);
  err << "amcl-offline: sweep: " << runs.size() << " runs planned in " << (options.dir / "jobs.txt").string()
      << " (and sweep.sbatch, plan.json)\n";
  return tools::kExitOk;
}

int run_sweep_collect(const SweepCollectOptions& options, std::ostream& out, std::ostream& err) {
  const SweepTable table = collect_sweep(options.dir);
  tools::OutputFile output(options.output, out);
  write_sweep_table(table, options.format, output.stream());
  output.check();
  output.commit();
  if (options.plot) write_sweep_plot(table, *options.plot);
  err << "amcl-offline: sweep: " << sweep_tally(table) << "\n";
  for (const auto& run : table.runs) {
    if (run.status == SweepStatus::failed) {
      err << "amcl-offline: sweep: " << run.id << " failed; its stderr: " << (options.dir / "runs" / (run.id + ".err")).string() << "\n";
    }
  }
  const bool all_ok = std::all_of(table.runs.begin(), table.runs.end(), [](const SweepResult& run) { return run.status == SweepStatus::ok; });
  return all_ok ? tools::kExitOk : tools::kExitFailure;
}

int run_sweep_run(const SweepRunOptions& options, std::ostream& out, std::ostream& err) {
  const auto runs = expand_sweep(options.plan.spec);
  const auto lines = write_sweep_plan(options.plan.spec, runs, options.plan.program, options.plan.dir);
  std::vector<SweepJob> jobs;
  for (std::size_t i = 0; i < runs.size(); ++i) jobs.push_back({runs[i].id, lines[i]});
  err << "amcl-offline: sweep: " << jobs.size() << " runs, " << options.jobs << " at a time\n";
  tools::install_stop_signals();
  const std::size_t failed = run_sweep_jobs(jobs, options.jobs, err);
  const int collected = run_sweep_collect(options.collect, out, err);
  return failed > 0 ? tools::kExitFailure : collected;
}

}  // namespace playerkit::amcl_offline
