// player-log: inspect, convert, cut and record Player (and CARMEN) logs. See --help.

#include <CLI/CLI.hpp>
#include <iostream>
#include <string>
#include <unistd.h>

#include "parse_errors.hpp"
#include "log/log_parse_error.hpp"
#include "log_convert.hpp"
#include "log_info.hpp"
#include "log_options.hpp"
#include "log_record.hpp"
#include "log_replay.hpp"
#include "log_tool.hpp"
#include "stop_signals.hpp"

namespace {

namespace plog = playerkit::plog;

constexpr const char* kFooter = R"(Formats: Player 1.5 text logs (file version 0.0.0 and 1.6.5's 0.2.0) and CARMEN
logs, told apart by their content; either may be gzip-compressed (.gz).

Examples:
  player-log info intel.log.gz                 format, devices, counts, rates, span, gaps
  player-log info run.log --json               the same as one JSON object
  player-log convert intel.log.gz -o intel.player.log     CARMEN -> Player
  player-log convert run.log -o run.carmen.log --to carmen
  player-log convert run.log -o - --to jsonl | jq .data.range_count
  player-log convert run.log -o laser.csv --devices laser:0
  player-log cut run.log -o part.log --start 10 --end 20 --devices laser:0
  player-log record laser:0 position:0 -o run.log --duration 60
  player-log record robot1:7000 laser -o run.log -n 100
  player-cat laser --format log | player-log record - -o run.log
  player-log replay run.log                    serve run.log's devices on port 6665
  player-log replay intel.log.gz -p 7000 --rate 10 --devices laser:0,position:0
  player-log replay run.log --burst --loop     as fast as the clients read, for ever

CARMEN -> Player: FLASER gives laser:0, position:0 (the odometry pose) and
truth:0 (the laser's pose); ODOM gives position:0. Player -> CARMEN: the reverse
(laser:0 -> FLASER, position:0 -> ODOM). Player's units hold mm and whole degrees.

Stdout carries data only (info, or -o -); messages go to stderr. Long runs show
progress on stderr when it is a terminal. Malformed lines are skipped and
counted (the first few shown as file:line:col: what), or fatal with --strict.
Replay serves until SIGINT/SIGTERM (exit 0), also after the end of the log;
clients get every message as long as they keep within 256 messages of the
replay, and with --burst whatever their pace.
Signals: SIGINT and SIGTERM stop record cleanly (every line received is written), exit 0.
Output files: -o may not be the input (also as ./a.log, a symlink or a hard link: exit 2).
convert and cut write a temporary beside the output and rename it at the end: an error
or a signal leaves no output and an older file untouched. record writes to its name as
it goes (tail -f works), opened once the devices are granted. NAME.gz is written gzip.
Exit status: 0 done, 1 runtime error (missing or unreadable file, malformed
line with --strict, cannot connect, no such device), 2 usage error.)";


// Runs a subcommand, turning its errors into messages and exit statuses.
template <typename Body>
int guarded(Body&& body) {
  try {
    body();
    return plog::kExitOk;
  } catch (const plog::UsageError& e) {
    std::cerr << "player-log: " << e.what() << "\nRun with --help for more information.\n";
    return plog::kExitUsage;
  } catch (const std::exception& e) {
    std::cerr << "player-log: " << e.what() << "\n";
    return plog::kExitFailure;
  }
}

}  // namespace

int main(int argc, char** argv) {
  CLI::App app{"player-log SUBCOMMAND ...: inspect, convert, cut, record and replay Player and CARMEN logs."};
  app.footer(kFooter);
  app.set_version_flag("--version", std::string("player-log (playerkit) ") + PLAYERKIT_VERSION);
  app.require_subcommand(1);

  auto* info = app.add_subcommand("info", "format, devices with counts and rates, time span, gaps, malformed lines");
  std::string info_file;
  bool json = false;
  bool info_strict = false;
  info->add_option("FILE", info_file, "the log")->required();
  info->add_flag("--json", json, "one JSON object instead of text");
  info->add_flag("--strict", info_strict, "a malformed line is an error (exit 1)");

  auto* convert = app.add_subcommand("convert", "Player <-> CARMEN, or to JSON lines / CSV");
  plog::ConvertCommandLine convert_line;
  convert->add_option("IN", convert_line.input, "the log to read")->required();
  convert->add_option("-o,--output", convert_line.output, "where to write (- for stdout)")->required();
  convert->add_option("--to", convert_line.to,
                      "player, carmen, jsonl or csv (default: by -o's extension, else the other log format)");
  convert->add_option("--devices", convert_line.devices, "only these devices: laser:0,position:0");
  convert->add_flag("--si", convert_line.si, "jsonl/csv: metres and radians instead of wire units");
  convert->add_flag("--strict", convert_line.strict, "a malformed line is an error (exit 1)");

  auto* cut = app.add_subcommand("cut", "a time window and/or some devices of a Player log");
  plog::CutCommandLine cut_line;
  cut->add_option("FILE", cut_line.input, "the Player log")->required();
  cut->add_option("-o,--output", cut_line.output, "where to write (- for stdout)")->required();
  cut->add_option("--start", cut_line.start, "from S seconds after the log's first time")->type_name("S");
  cut->add_option("--end", cut_line.end, "up to S seconds after the log's first time")->type_name("S");
  cut->add_option("--devices", cut_line.devices, "only these devices: laser:0,position:0 (sync lines stay)");
  cut->add_flag("--strict", cut_line.strict, "a malformed line is an error (exit 1)");

  auto* record = app.add_subcommand("record", "record devices of a server (or player-cat --format log on stdin)");
  plog::RecordCommandLine record_line;
  record->add_option("TARGETS", record_line.targets, "[HOST[:PORT]] DEVICE..., or - to read log lines from stdin")
      ->required();
  record->add_option("-o,--output", record_line.output, "the log to write (- for stdout)")->required();
  record->add_option("--duration", record_line.duration, "stop after S seconds")->type_name("S");
  record->add_option("-n,--count", record_line.count, "stop after N data messages")->type_name("N");
  record->add_option("--timeout", record_line.timeout, "seconds to wait for the connection and each reply")
      ->capture_default_str();
  record->add_flag("--strict", record_line.strict, "stdin: a malformed line is an error (exit 1)");
  record->add_option("--frequency", record_line.frequency,
                     "the server's data rounds per second (default 10, as Player 1.5; each round carries a "
                     "device's newest sample only, so record a 40 Hz laser at 40 or more)")
      ->type_name("HZ");

  auto* replay = app.add_subcommand("replay", "serve a log's devices to clients, as player-serve -r does, without a config");
  plog::ReplayCommandLine replay_line;
  replay->add_option("FILE", replay_line.input, "Player or CARMEN log (.gz too)")->required();
  replay->add_option("-p,--port", replay_line.port, "TCP port (0: any free one)")->capture_default_str();
  replay->add_option("--bind", replay_line.bind_address, "address to listen on")->capture_default_str();
  replay->add_option("-r,--rate", replay_line.rate, "speed factor (2 = twice as fast as logged)")
      ->capture_default_str();
  replay->add_flag("-l,--loop", replay_line.loop, "start again at the end of the log");
  replay->add_option("--start", replay_line.start, "skip the first S seconds of the log")->type_name("S");
  replay->add_option("--duration", replay_line.duration, "serve S seconds of log (per pass)")->type_name("S");
  replay->add_option("--devices", replay_line.devices, "only these, e.g. laser:0,position:0");
  replay->add_flag("--burst", replay_line.burst, "as fast as the clients read, never dropping a message");
  replay->add_flag("-q,--quiet", replay_line.quiet, "errors only");

  try {
    app.parse(argc, argv);
  } catch (const CLI::ParseError& e) {
    return playerkit::tools::report_parse_error(app, e, std::cerr);
  }

  plog::Progress progress(std::cerr, isatty(STDERR_FILENO) == 1);
  if (info->parsed()) {
    return guarded([&] {
      const auto summary = plog::summarize_log(info_file, info_strict, progress);
      if (json) std::cout << plog::summary_json(summary).dump(2) << "\n";
      else plog::print_summary(summary, std::cout);
      for (const auto& text : summary.malformed_texts) std::cerr << text << "\n";
    });
  }
  if (convert->parsed()) {
    return guarded([&] { plog::run_convert(plog::make_convert_options(convert_line), std::cout, std::cerr, progress); });
  }
  if (cut->parsed()) {
    return guarded([&] { plog::run_cut(plog::make_cut_options(cut_line), std::cout, std::cerr, progress); });
  }
  if (replay->parsed()) {
    int status = plog::kExitUsage;
    const int parsed =
        guarded([&] { status = plog::run_replay(plog::make_replay_options(replay_line), std::cerr, progress); });
    return parsed == plog::kExitOk ? status : parsed;
  }
  int status = plog::kExitUsage;
  const int parsed = guarded([&] {
    const auto record_options = plog::make_record_options(record_line);
    playerkit::tools::install_stop_signals();
    status = plog::run_record(record_options, std::cin, std::cout, std::cerr,
                              [] { return playerkit::tools::stop_requested(); });
  });
  return parsed == plog::kExitOk ? status : parsed;
}
