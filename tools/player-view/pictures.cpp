#include "pictures.hpp"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <filesystem>
#include <optional>

#include "files/output_file.hpp"
#include "map/map_file.hpp"
#include "session.hpp"
#include "view/renderer.hpp"
#include "view/scene.hpp"

namespace playerkit::player_view {
namespace {

using Clock = std::chrono::steady_clock;

Clock::duration picture_seconds(double s) {
  return std::chrono::duration_cast<Clock::duration>(std::chrono::duration<double>(s));
}

class Pictures {
 public:
  Pictures(const ViewOptions& options, Session& session, std::optional<grid::OccupancyGrid> map)
      : options_(options), session_(session), map_(std::move(map)), start_(Clock::now()) {}

  view::Scene& scene() { return scene_; }

  // Feeds the scene until `until` or a stop request. Returns false when stopped.
  bool collect_until(Clock::time_point until, const std::function<bool()>& stop_requested) {
    while (!stop_requested()) {
      const auto now = Clock::now();
      if (now >= until) return true;
      const auto wait = std::clamp(std::chrono::ceil<std::chrono::milliseconds>(until - now),
                                   std::chrono::milliseconds(1), std::chrono::milliseconds(100));
      if (auto message = session_.connection.read(wait)) scene_.apply(*message, elapsed());
    }
    return false;
  }

  void write(const std::filesystem::path& path) {
    const auto frame = scene_.frame(elapsed());
    view::write_png(path, view::render(frame, map_ ? &*map_ : nullptr, options_.render));
  }

  [[nodiscard]] Clock::time_point start() const { return start_; }

 private:
  [[nodiscard]] double elapsed() const { return std::chrono::duration<double>(Clock::now() - start_).count(); }

  const ViewOptions& options_;
  Session& session_;
  std::optional<grid::OccupancyGrid> map_;
  view::Scene scene_;
  Clock::time_point start_;
};

void record(const ViewOptions& options, Pictures& pictures, std::ostream& out,
            const std::function<bool()>& stop_requested) {
  std::error_code error;
  std::filesystem::create_directories(options.record_dir, error);
  if (error) throw ViewFailure("cannot create " + options.record_dir.string() + ": " + error.message());
  auto next = pictures.start();
  for (std::uint64_t n = 1; !options.count || n <= *options.count; ++n) {
    next += picture_seconds(options.every);
    if (!pictures.collect_until(next, stop_requested)) return;
    const auto path = options.record_dir / record_file_name(n);
    pictures.write(path);
    // The names on stdout, a line each, so a script can follow the pictures.
    out << path.string() << '\n' << std::flush;
    // After a stall, keep the pace rather than catching up in a burst.
    if (next < Clock::now()) next = Clock::now();
  }
}

}  // namespace

int run_pictures(const ViewOptions& options, std::ostream& out, std::ostream& err,
                 const std::function<bool()>& stop_requested) {
  return report_failures(options, err, [&] {
    // The map first: a bad map file is found before connecting.
    auto map = load_view_map(options);
    auto session = open_session(options, err);
    Pictures pictures(options, session, std::move(map));
    ask_geometry(session, pictures.scene(), geometry_timeout(options));
    if (options.output == Output::kSnapshot) {
      pictures.collect_until(pictures.start() + picture_seconds(options.after), stop_requested);
      pictures.write(options.snapshot);
    } else {
      record(options, pictures, out, stop_requested);
    }
  });
}

}  // namespace playerkit::player_view
