// player-send: send one command or request to a Player 1.5 server, or a stream
// of them from stdin. See --help.

#include <algorithm>
#include <chrono>
#include <cmath>
#include <iostream>
#include <optional>
#include <stdexcept>
#include <string>
#include <vector>

#include <CLI/CLI.hpp>

#include "parse_errors.hpp"
#include "catalog_help.hpp"
#include "client/client.hpp"
#include "client/endpoint.hpp"
#include "exit_codes.hpp"
#include "line_feed.hpp"
#include "outgoing_message.hpp"
#include "protocol/catalog.hpp"
#include "protocol/interfaces.hpp"
#include "sender.hpp"
#include "usage_error.hpp"

namespace {

using namespace playerkit;
using player_send::ExitCode;

constexpr const char* kGuide = R"(Examples:
  player-send position:0 cmd xspeed=200 yawspeed=10
  player-send robot1:7000 laser:0 req set-config min_angle=-9000 max_angle=9000 resolution=50
  player-send mcom:0 req push channel=news data.data=hello
  player-send mcom:0 req pop channel=news
  player-send player req devlist
  player-cat position:0 --format json | jq -c '...' | player-send --stdin --rate 10

Fields take the names of the Player 1.5 structs (listed below), with values in
wire units as the manual gives them (mm, mm/s, degrees; laser angles in 0.01
degrees). Unspecified fields are zero. List
elements: pose.0=100 or pose=[1,2,3]; nested structs: id.code=26. Values are
JSON (200, -5, [1,2], "text"); anything else is text (channel=news).

Access: before a command the device is opened for writing ('w', else 'a'); a
command to a device that cannot be written is not sent (exit 4). Requests open
the device for reading ('r') when they only ask, fully ('a') when they carry
settings; the `player` device needs no opening. A request to a device that
could not be opened is sent anyway and the server answers ERR.
Player stops a position device when its last client disconnects: a command
from player-send lasts only while another client holds the device, or while
player-send --stdin keeps its connection.

Replies: each request's reply is printed on stdout as one JSON object:
  {"type":"ack","device":"mcom","index":0,"request":"pop","data":{...},...}

--stdin reads one JSON object per line and sends each in order:
  {"device":"position:0","data":{"xspeed":200}}                     a command
  {"device":"mcom:0","request":"push","data":{"channel":"news"}}    a request
or the full form player-cat --format json prints ("type":"cmd" or "req",
"device":"position","index":0, "data"). "time"/"timestamp" are ignored, a
missing "data" is all zeros, {"raw":[bytes]} sends bytes as they are. A bad
line stops player-send with its line number on stderr and exit 2: the lines
before it were sent, nothing after it is read. NACK and ERR replies do not
stop it. Blank lines are skipped.

Exit status: 0 ACK (for commands: the server has read them), 1 connection
refused or lost, timeout, authentication refused, 2 usage (unknown device,
request, field or value; a bad --stdin line), 3 NACK (the device refused),
4 ERR (no access, no such device), or a command to a device that cannot be
opened for writing. With --stdin: 2 or 4 for the line that stopped it, else
the code of the first reply that was not an ACK.

Commands (cmd) and requests (req) by interface:
)";

std::chrono::milliseconds to_timeout(double seconds) {
  return std::chrono::milliseconds(std::max<long long>(1, std::llround(seconds * 1000.0)));
}

// "laser:0" or every interface for "all"; exit 2 for an unknown name.
int print_catalog(const std::string& name) {
  if (name == "all") {
    std::cout << player_send::catalog_help();
    return 0;
  }
  const auto* info = protocol::find_interface(name);
  const auto* messages = info ? protocol::find_messages(info->code) : nullptr;
  if (!messages) {
    std::cerr << "player-send: --list: unknown interface '" << name << "'\n";
    return player_send::to_int(ExitCode::kUsage);
  }
  const auto text = player_send::interface_help(*messages);
  std::cout << (text.empty() ? name + ": nothing to send (data only)\n" : text);
  return 0;
}

struct Arguments {
  std::vector<std::string> words;
  bool from_stdin = false;
  std::optional<double> rate_hz;
  double timeout_seconds = 5.0;
  std::optional<std::string> key;
  std::optional<std::string> list;
};

// The server, and for a single message the message itself, checked before connecting.
struct Plan {
  client::ServerEndpoint server;
  std::optional<protocol::Message> message;
};

Plan make_plan(const Arguments& arguments) {
  const auto& words = arguments.words;
  // "lazer:0 cmd ..." reads as a device, so explain it as one rather than as a bad host.
  if (words.size() >= 2 && (words[1] == "cmd" || words[1] == "req")) player_send::parse_device(words[0]);
  client::ToolTarget target;
  try {
    target = client::split_tool_target(words);
  } catch (const std::invalid_argument& e) {
    throw player_send::UsageError(e.what());
  }
  Plan plan{target.server, std::nullopt};
  if (arguments.from_stdin) {
    if (!target.rest.empty()) {
      throw player_send::UsageError("with --stdin, give only [HOST[:PORT]]: the messages come from stdin");
    }
    return plan;
  }
  if (arguments.rate_hz) throw player_send::UsageError("--rate paces --stdin lines; it needs --stdin");
  plan.message = player_send::message_from_arguments(target.rest);
  return plan;
}

ExitCode run(const Plan& plan, const Arguments& arguments) {
  const auto timeout = to_timeout(arguments.timeout_seconds);
  auto connection = client::Client::connect(plan.server.host, plan.server.port, timeout);
  connection.set_timeout(timeout);
  if (arguments.key) connection.authenticate(*arguments.key);
  player_send::Sender sender(connection, std::cout, std::cerr);
  const auto code = plan.message ? sender.send(*plan.message)
                                 : player_send::send_lines(std::cin, sender, arguments.rate_hz, std::cerr);
  // A feed stopped by a lost connection has said so; there is nothing left to confirm.
  if (code != ExitCode::kConnection) sender.confirm_commands();
  return code;
}

}  // namespace

int main(int argc, char** argv) {
  CLI::App app{"player-send: send a command or a request to a device of a Player 1.5 server.\n"
               "  player-send [HOST[:PORT]] DEVICE cmd FIELD=VALUE...\n"
               "  player-send [HOST[:PORT]] DEVICE req NAME [FIELD=VALUE...]\n"
               "  player-send [HOST[:PORT]] --stdin [--rate HZ]\n"
               "HOST defaults to localhost, PORT to 6665."};
  // Written only when --help asks for it.
  app.footer([] { return std::string(kGuide) + player_send::catalog_help(); });

  Arguments arguments;
  app.name("player-send");
  app.set_version_flag("--version", std::string("player-send (playerkit) ") + PLAYERKIT_VERSION);
  app.add_option("ARGS", arguments.words, "[HOST[:PORT]] DEVICE cmd FIELD=VALUE... | DEVICE req NAME [FIELD=VALUE...]");
  app.add_flag("--stdin", arguments.from_stdin, "send the JSON lines read from stdin (format below)");
  app.add_option("--rate", arguments.rate_hz, "with --stdin: at most HZ messages per second")
      ->check(CLI::PositiveNumber);
  app.add_option("--timeout", arguments.timeout_seconds, "seconds to wait for the connection and each reply")
      ->check(CLI::PositiveNumber)
      ->capture_default_str();
  app.add_option("--key", arguments.key, "authenticate with this key (servers started with -k)");
  app.add_option("--list", arguments.list, "print what INTERFACE takes ('all': every interface) and exit")
      ->type_name("INTERFACE");

  try {
    app.parse(argc, argv);
  } catch (const CLI::ParseError& e) {
    return playerkit::tools::report_parse_error(app, e, std::cerr);
  }
  if (arguments.list) return print_catalog(*arguments.list);

  Plan plan;
  try {
    plan = make_plan(arguments);
  } catch (const player_send::UsageError& e) {
    std::cerr << "player-send: " << e.what() << "\n";
    return player_send::to_int(ExitCode::kUsage);
  }
  try {
    return player_send::to_int(run(plan, arguments));
  } catch (const client::ClientError& e) {
    std::cerr << "player-send: " << e.what() << "\n";
    return player_send::to_int(ExitCode::kConnection);
  } catch (const player_send::UsageError& e) {
    std::cerr << "player-send: " << e.what() << "\n";
    return player_send::to_int(ExitCode::kUsage);
  }
}
