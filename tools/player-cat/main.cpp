// player-cat: dump the data of a Player server's devices. See --help.

#include <CLI/CLI.hpp>
#include <iostream>
#include <string>

#include "parse_errors.hpp"
#include "cat.hpp"
#include "stop_signals.hpp"
#include "cat_options.hpp"

namespace {

constexpr const char* kFooter = R"(Formats:
  text  one line per message: device, time, then name=value for each data field
  json  one JSON object per line: type, device, index, time, timestamp, data
  csv   a header row, then one row per message; arrays become ranges.0, ranges.1, ...
        One device per stdout; --csv-dir DIR writes DIR/laser_0.csv, ... for several.
  log   Player 1.5 text log lines (writelog's format), with "sync" lines per round

Examples:
  player-cat laser:0                         laser:0 on localhost:6665 until Ctrl-C
  player-cat robot1:7000 laser:0 position    two devices of robot1's port 7000
  player-cat laser -n 10 --format json       ten messages as JSON lines
  player-cat laser --once --field range_count --field ranges.0
  player-cat power --duration 5 -t z --format csv > power.csv
  player-cat laser:0 sonar:0 --format csv --csv-dir out/    out/laser_0.csv, out/sonar_0.csv
  player-cat laser --format log > robot.log  a Player 1.5 log file (readlog's format)
  player-cat laser --mode pull-new --rate 2  ask for a round twice a second
  player-cat --list                          the server's devices and their drivers
  player-cat laser --si | head -n 3          metres and radians; stops quietly

Times: "time" is the server's clock when it sent the message; -t d and -t z
change only the time shown (text "t=", CSV and JSON "time"). "timestamp" is
when the driver made the data.

Stdout carries data only, a line at a time; messages go to stderr.
Signals: SIGINT and SIGTERM stop cleanly (output flushed), exit 0.
Exit status: 0 done (count, --once, --duration, a signal, or the reader of
stdout closed it), 1 runtime error (cannot connect, no such device, device not
opened, server gone, output not writable), 2 usage error (bad flag, device
name, or a --field the device's data does not have).)";


}  // namespace

int main(int argc, char** argv) {
  namespace cat = playerkit::cat;
  CLI::App app{
      "player-cat [HOST[:PORT]] DEVICE... [options]: connect to a Player server (by default\n"
      "localhost:6665), subscribe to the devices and print their data."};
  app.footer(kFooter);
  app.set_version_flag("--version", std::string("player-cat (playerkit) ") + PLAYERKIT_VERSION);

  cat::CommandLine command_line;
  app.add_option("TARGETS", command_line.targets,
                 "the server if not localhost:6665, then devices: laser:0, position (index 0), 6:1")
      ->type_name("");
  app.add_option("--format", command_line.format, "text, json, csv or log")
      ->type_name("FORMAT")
      ->capture_default_str();
  app.add_option("--csv-dir", command_line.csv_dir,
                 "with --format csv: write DIR/<interface>_<index>.csv per device")
      ->type_name("DIR");
  app.add_option("-n,--count", command_line.count, "stop after N data messages in total")->type_name("N");
  app.add_flag("--once", command_line.once, "one data message per device, then exit");
  app.add_option("--duration", command_line.duration, "stop after SECONDS")->type_name("SECONDS");
  app.add_option("--field", command_line.fields,
                 "print only this dotted path of the data (repeatable): range_count, ranges.0")
      ->type_name("PATH")
      ->allow_extra_args(false);  // --field a laser: "laser" is a device, not a second field
  app.add_option("--mode", command_line.mode, "push-new, push-all, pull-new or pull-all")
      ->type_name("MODE")
      ->capture_default_str();
  app.add_option(
         "--rate", command_line.rate,
         "push modes: the server's data frequency (Hz); pull modes: rounds asked per second (default 10)")
      ->type_name("HZ");
  app.add_option("--key", command_line.key, "authenticate with this key first (servers started with -k)")
      ->type_name("KEY");
  app.add_option("-t", command_line.timestamps,
                 "times shown: a absolute, d delta since the previous line, z from the first")
      ->type_name("a|d|z")
      ->capture_default_str();
  app.add_flag("--si", command_line.si,
               "SI units (metres, radians, m/s, volts) instead of the wire's (mm, 0.01 degrees, ...)");
  app.add_flag("--list", command_line.list,
               "print the server's devices with their drivers, one per line, and exit");
  app.add_option("--timeout", command_line.timeout, "seconds to wait for the connection and each reply")
      ->type_name("SECONDS")
      ->capture_default_str();

  try {
    app.parse(argc, argv);
  } catch (const CLI::ParseError& e) {
    return playerkit::tools::report_parse_error(app, e, std::cerr);
  }

  cat::CatOptions options;
  try {
    options = cat::make_cat_options(command_line);
  } catch (const cat::UsageError& e) {
    std::cerr << "player-cat: " << e.what() << "\nRun with --help for more information.\n";
    return cat::kExitUsage;
  }

  playerkit::tools::install_stop_signals();
  return cat::run_cat(options, std::cout, std::cerr, [] { return playerkit::tools::stop_requested(); });
}
