// player-view: see what a Player server's robot sees, as pictures. See --help.

#include <CLI/CLI.hpp>
#include <iostream>
#include <string>

#include "parse_errors.hpp"
#include "live.hpp"
#include "pictures.hpp"
#include "stop_signals.hpp"
#include "view_options.hpp"

namespace {

constexpr const char* kFooter = R"(What is drawn, top-down, north up, the robot at the centre:
  the map (--map), laser scans (points, the free-space fan, bright returns in
  orange), sonar and IR cones, the odometry trail, localize hypotheses as
  ellipses, fiducials with their ids, the true pose in a simulator (green outline), the robot (red), a
  legend with each device's rate ("laser:0 5.0 Hz") and a scale bar. The robot
  is placed by truth when the server has it, else by the best localize
  hypothesis, else by odometry.

Devices: the ones named, or by default every device the server lists that
opens for reading (those that do not are skipped with a message).

Maps: a Player image (.pgm/.pnm/.png with --scale M_PER_PX, centred on the
origin as Player 1.5's map driver placed it, or with its bottom-left corner at
--origin X,Y: 0,0 for the bitmap of a Stage 1.3 world) or a ROS map_server
.yaml, as amcl-offline takes them.

The live page (--http): open http://127.0.0.1:PORT/ in a browser; it draws
the same as the pictures, follows the robot (drag to pan, wheel to zoom) and
shows each device's rate. Any number of pages share the tool's one connection
to the server. The page is served on 127.0.0.1 only, unless --bind names
another address (a warning says so: the page has no password).
When the robot's server goes away, the page says so and the tool reconnects
every second; the first connection must work.

Driving (--drive): the arrow keys or the page's pad send velocity commands to
the robot's first position device (motors switched on when driving starts).
The robot stops when the key or pad is released, the page loses focus or
closes, or the page falls silent for 0.6 s.

Examples:
  player-view localhost:6665 --http 8080      then open http://127.0.0.1:8080/
  player-view --http 8080 --map data/worlds/cave.yaml
  player-view --http 8080 --drive --speed 0.2 --turn 20
  player-view localhost:6665 --snapshot robot.png
  player-view :7000 laser:0 position:0 --snapshot scan.png --after 3 --size 640x480 --span 20
  player-view --snapshot cave.png --map data/worlds/cave.yaml
  player-view --snapshot cave.png --map data/worlds/cave.pnm --scale 0.03 --negate --origin 0,0
  player-view --record frames/ --every 0.5 --count 20    frames/frame-000001.png, ...

Stdout: with --record, the name of each picture written, one a line.
Messages go to stderr, among them "serving http://127.0.0.1:PORT/".
Signals: SIGINT and SIGTERM write the snapshot at once, end a recording, or
stop serving; exit 0.
Exit status: 0 done, 1 runtime error (cannot connect, a named device refused,
connection lost (pictures), unreadable map, picture not writable, HTTP port
taken, no position device for --drive),
2 usage error.)";

}  // namespace

int main(int argc, char** argv) {
  namespace view = playerkit::player_view;
  CLI::App app{
      "player-view [HOST[:PORT]] [DEVICE...] --http PORT | --snapshot FILE.png | --record DIR --every S:\n"
      "connect to a Player server (by default localhost:6665) and show what its robot sees,\n"
      "live in a web browser or as pictures."};
  app.footer(kFooter);
  app.set_version_flag("--version", std::string("player-view (playerkit) ") + PLAYERKIT_VERSION);

  view::CommandLine command_line;
  app.add_option("TARGETS", command_line.targets,
                 "the server if not localhost:6665, then devices: laser:0, position (index 0), 6:1")
      ->type_name("");
  app.add_option("--http", command_line.http, "serve the live page on this port (0: a free one, printed)")
      ->type_name("PORT");
  app.add_option("--bind", command_line.bind, "with --http: the address to listen on (default 127.0.0.1)")
      ->type_name("ADDR");
  app.add_flag("--drive", command_line.drive,
               "with --http: arrow keys and the page's pad drive the robot (its first position device)");
  app.add_option("--speed", command_line.speed, "with --drive: forward speed, m/s")
      ->type_name("M/S")
      ->capture_default_str();
  app.add_option("--turn", command_line.turn, "with --drive: turn rate, degrees/s")
      ->type_name("DEG/S")
      ->capture_default_str();
  app.add_option("--snapshot", command_line.snapshot, "write one PNG after --after seconds of data, then exit")
      ->type_name("FILE");
  app.add_option("--after", command_line.after, "seconds of data before the snapshot (default 1)")
      ->type_name("SECONDS");
  app.add_option("--record", command_line.record, "write DIR/frame-000001.png, ... every --every seconds")
      ->type_name("DIR");
  app.add_option("--every", command_line.every, "seconds between recorded pictures")->type_name("SECONDS");
  app.add_option("-n,--count", command_line.count, "with --record: stop after N pictures")->type_name("N");
  app.add_option("--size", command_line.size, "the picture's size in pixels")
      ->type_name("WxH")
      ->capture_default_str();
  app.add_option("--span", command_line.span, "metres across the picture's width")
      ->type_name("METRES")
      ->capture_default_str();
  app.add_option("--map", command_line.map, "draw this map under the robot (image or ROS .yaml)")
      ->type_name("FILE");
  app.add_option("--scale", command_line.scale, "a map image's metres per pixel")->type_name("M");
  app.add_flag("--negate", command_line.negate, "a map image's white pixels are walls");
  app.add_option("--origin", command_line.origin, "a map image's bottom-left corner (default: centred)")
      ->type_name("X,Y");
  app.add_option("--key", command_line.key, "authenticate with this key first (servers started with -k)")
      ->type_name("KEY");
  app.add_option("--timeout", command_line.timeout, "seconds to wait for the connection and each reply")
      ->type_name("SECONDS")
      ->capture_default_str();

  try {
    app.parse(argc, argv);
  } catch (const CLI::ParseError& e) {
    return playerkit::tools::report_parse_error(app, e, std::cerr);
  }

  view::ViewOptions options;
  try {
    options = view::make_view_options(command_line);
  } catch (const view::UsageError& e) {
    std::cerr << "player-view: " << e.what() << "\nRun with --help for more information.\n";
    return view::kExitUsage;
  }

  playerkit::tools::install_stop_signals();
  const auto stop = [] { return playerkit::tools::stop_requested(); };
  if (options.output == view::Output::kHttp) return view::run_live(options, std::cerr, stop);
  return view::run_pictures(options, std::cout, std::cerr, stop);
}
