#include "live.hpp"

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <optional>
#include <thread>

#include <nlohmann/json.hpp>

#include "client/typed/position.hpp"
#include "drive.hpp"
#include "page_server.hpp"
#include "protocol/binary_codec.hpp"
#include "session.hpp"
#include "view/frame_json.hpp"
#include "view/scene.hpp"

namespace playerkit::player_view {
namespace {

using LiveClock = std::chrono::steady_clock;

// Only the default addresses go without a warning: whether another address
// reaches beyond this machine depends on its network, which the tool cannot see.
bool default_loopback(const std::string& address) { return address == "127.0.0.1" || address == "::1"; }

std::string hello(const ViewOptions& options) {
  char text[128];
  std::snprintf(text, sizeof text, R"({"type":"hello","drive":%s,"speed":%.3f,"turn":%.4f})",
                options.drive ? "true" : "false", options.speed, options.turn_rate);
  return text;
}

// The base obeys the pages through a DriveControl, the one place the
// dead-man rule lives.
class Driver {
 public:
  Driver(client::Client& connection, protocol::DeviceAddress base, const ViewOptions& options)
      : connection_(connection), base_(base), control_(options.speed, options.turn_rate) {}

  void take(const std::vector<PageEvent>& events, double now) {
    for (const auto& event : events) {
      if (event.closed) {
        control_.closed(event.page);
      } else {
        control_.message(event.page, event.text, now);
      }
    }
  }

  void update(double now) {
    const auto motors = control_.take_motor_request();
    const bool starting = control_.starting();
    const auto command = control_.update(now);
    // Off before the stop it implies is sent; on when driving starts, as
    // playerjoy did (a base without the request still takes the command's
    // own motor state).
    if (motors && !*motors) power(false);
    if (command) {
      if (starting || (motors && *motors)) power(true);
      send(*command);
    } else if (motors && *motors) {
      power(true);
    }
  }

  void stop() { send({}); }

 private:
  void power(bool on) {
    const protocol::PositionPowerConfig request{protocol::kPositionMotorPowerReq, static_cast<std::uint8_t>(on ? 1 : 0)};
    try {
      (void)connection_.request(base_, protocol::encode(request));
    } catch (const client::TimeoutError&) {
      // No answer: the command that follows still carries the motor state.
    }
  }

  void send(const DriveCommand& command) {
    client::PositionCommand wanted;
    wanted.velocity = {command.forward, 0.0, command.turn};
    wanted.motors_on = true;
    connection_.write_command(base_, protocol::encode(client::to_wire(wanted)));
  }

  client::Client& connection_;
  protocol::DeviceAddress base_;
  DriveControl control_;
};

std::string url_host(const std::string& address) {
  return address.find(':') == std::string::npos ? address : "[" + address + "]";
}


// One connection's life: feeds the pages until a stop request, or throws
// client::ClientError when the connection is lost.
void feed_pages(Session& session, PageServer& pages, const ViewOptions& options,
                const std::function<bool()>& stop_requested) {
  view::Scene scene;
  ask_geometry(session, scene, geometry_timeout(options));
  std::optional<Driver> driver;
  if (options.drive) driver.emplace(session.connection, open_base_for_driving(session, options), options);
  (void)pages.take_events();  // what pages asked while there was no robot is stale

  const auto start = LiveClock::now();
  const auto period =
      std::chrono::duration_cast<LiveClock::duration>(std::chrono::duration<double>(1.0 / kPagesPerSecond));
  auto next = start;
  const auto elapsed = [&] { return std::chrono::duration<double>(LiveClock::now() - start).count(); };
  while (!stop_requested()) {
    const auto now = LiveClock::now();
    if (now >= next) {
      pages.publish(view::frame_json(scene.frame(elapsed())));
      next += period;
      // After a stall, keep the pace rather than catching up in a burst.
      if (next <= now) next = now + period;
    }
    const auto events = pages.take_events();
    if (driver) {
      driver->take(events, elapsed());
      driver->update(elapsed());
    }
    // A key released on a page reaches the robot within 50 ms.
    const auto longest = std::chrono::milliseconds(driver ? 50 : 100);
    const auto wait = std::clamp(std::chrono::ceil<std::chrono::milliseconds>(next - LiveClock::now()),
                                 std::chrono::milliseconds(1), longest);
    if (auto message = session.connection.read(wait)) scene.apply(*message, elapsed());
  }
  if (driver) driver->stop();
}

std::string lost_json(const std::string& why) {
  const auto since = std::chrono::duration<double>(std::chrono::system_clock::now().time_since_epoch()).count();
  return nlohmann::json{{"type", "lost"}, {"since", since}, {"why", why}}.dump();
}

// Sleeps up to `seconds`, waking for a stop request.
void wait_a_while(double seconds, const std::function<bool()>& stop_requested) {
  const auto until = LiveClock::now() + std::chrono::duration_cast<LiveClock::duration>(std::chrono::duration<double>(seconds));
  while (!stop_requested() && LiveClock::now() < until) std::this_thread::sleep_for(std::chrono::milliseconds(50));
}

}  // namespace

int run_live(const ViewOptions& options, std::ostream& err, const std::function<bool()>& stop_requested) {
  return report_failures(options, err, [&] {
    const auto map = load_view_map(options);
    // The port before the robot: a port in use is found without connecting.
    PageServer pages(options.bind, options.http_port, page_assets());
    // The first connection must work: an unreachable server or a refused
    // device is an error, as for pictures.
    auto session = std::make_optional(open_session(options, err));
    if (options.drive) (void)open_base_for_driving(*session, options);
    pages.add_greeting(hello(options));
    if (map) pages.add_greeting(view::map_json(*map));
    pages.start();
    err << "player-view: serving http://" << url_host(options.bind) << ":" << pages.port() << "/\n";
    if (!default_loopback(options.bind)) {
      err << "player-view: warning: the page listens on " << options.bind
          << ", not 127.0.0.1: whoever reaches that address sees the robot's data (no password, no encryption)\n";
    }
    err << std::flush;

    const std::string where = client::to_string(options.server);
    while (true) {
      try {
        if (!session) session.emplace(open_session(options, err));
        feed_pages(*session, pages, options, stop_requested);
        return;
      } catch (const client::ClientError& e) {
        // Lost (or not back yet): the pages say so, and the tool tries again
        // every second until the server returns.
        if (session) {
          err << "player-view: lost " << where << " (" << e.what() << "); reconnecting every second\n" << std::flush;
          pages.publish(lost_json(e.what()));
        }
      } catch (const ViewFailure& e) {
        if (session) {
          err << "player-view: " << e.what() << "; trying again every second\n" << std::flush;
          pages.publish(lost_json(e.what()));
        }
      }
      session.reset();
      wait_a_while(1.0, stop_requested);
      if (stop_requested()) return;
    }
  });
}

}  // namespace playerkit::player_view
