#include "live.hpp"

#include <algorithm>
#include <chrono>
#include <optional>

#include "page_server.hpp"
#include "session.hpp"
#include "view/frame_json.hpp"
#include "view/scene.hpp"

namespace playerkit::player_view {
namespace {

using LiveClock = std::chrono::steady_clock;

// Only the default addresses go without a warning: whether another address
// reaches beyond this machine depends on its network, which the tool cannot see.
bool default_loopback(const std::string& address) { return address == "127.0.0.1" || address == "::1"; }

std::string url_host(const std::string& address) {
  return address.find(':') == std::string::npos ? address : "[" + address + "]";
}

}  // namespace

int run_live(const ViewOptions& options, std::ostream& err, const std::function<bool()>& stop_requested) {
  return report_failures(options, err, [&] {
    const auto map = load_view_map(options);
    // The port before the robot: a port in use is found without connecting.
    PageServer pages(options.bind, options.http_port, page_assets());
    auto session = open_session(options, err);
    view::Scene scene;
    ask_geometry(session, scene, geometry_timeout(options));
    if (map) pages.set_greeting(view::map_json(*map));
    pages.start();
    err << "player-view: serving http://" << url_host(options.bind) << ":" << pages.port() << "/\n";
    if (!default_loopback(options.bind)) {
      err << "player-view: warning: the page listens on " << options.bind
          << ", not 127.0.0.1: whoever reaches that address sees the robot's data (no password, no encryption)\n";
    }
    err << std::flush;

    const auto start = LiveClock::now();
    const auto period = std::chrono::duration_cast<LiveClock::duration>(std::chrono::duration<double>(1.0 / kPagesPerSecond));
    auto next = start + period;
    const auto elapsed = [&] { return std::chrono::duration<double>(LiveClock::now() - start).count(); };
    while (!stop_requested()) {
      const auto now = LiveClock::now();
      if (now >= next) {
        pages.publish(view::frame_json(scene.frame(elapsed())));
        next += period;
        // After a stall, keep the pace rather than catching up in a burst.
        if (next <= now) next = now + period;
      }
      const auto wait = std::clamp(std::chrono::ceil<std::chrono::milliseconds>(next - LiveClock::now()),
                                   std::chrono::milliseconds(1), std::chrono::milliseconds(100));
      if (auto message = session.connection.read(wait)) scene.apply(*message, elapsed());
    }
  });
}

}  // namespace playerkit::player_view
