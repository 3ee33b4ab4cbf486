#include "log_replay.hpp"

#include <algorithm>
#include <filesystem>
#include <sstream>
#include <system_error>
#include <unistd.h>

#include "daemon/serve.hpp"
#include "drivers/logfile/readlog_driver.hpp"
#include "log_convert.hpp"
#include "log_info.hpp"
#include "protocol/interfaces.hpp"
#include "serve_exit_status.hpp"

namespace playerkit::plog {

namespace {

// Enough for a client reading at 10 Hz to get every scan of a log played
// tens of times faster than logged; each kept sample is one message.
constexpr std::size_t kReplayDataQueue = 256;

// A converted CARMEN log, deleted when the replay ends.
class TemporaryFile {
 public:
  explicit TemporaryFile(std::filesystem::path path) : path_(std::move(path)) {}
  ~TemporaryFile() {
    std::error_code ignored;
    std::filesystem::remove(path_, ignored);
  }
  TemporaryFile(const TemporaryFile&) = delete;
  TemporaryFile& operator=(const TemporaryFile&) = delete;
  [[nodiscard]] const std::filesystem::path& path() const { return path_; }

 private:
  std::filesystem::path path_;
};

std::string join(const std::vector<protocol::DeviceAddress>& devices) {
  std::string text;
  for (const auto& device : devices) text += (text.empty() ? "" : ", ") + protocol::to_string(device);
  return text;
}

}  // namespace

std::string replay_configuration(const std::vector<protocol::DeviceAddress>& devices, double start,
                                 bool loop) {
  std::ostringstream config;
  config.precision(17);
  config << "# player-log replay: one readlog device per logged device\n";
  for (const auto& device : devices) {
    config << protocol::to_string(device) << " ( driver \"readlog\" start " << start << " autorewind "
           << (loop ? 1 : 0) << " )\n";
  }
  return config.str();
}

std::vector<protocol::DeviceAddress> replayable_devices(const std::string& player_log, Progress& progress) {
  const auto servable = drivers::readlog_driver_spec().interfaces;
  const LogSummary summary = summarize_log(player_log, false, progress);
  std::vector<protocol::DeviceAddress> devices;
  for (const auto& [name, stream] : summary.streams) {
    if (name == "sync") continue;
    std::vector<protocol::DeviceAddress> parsed;
    try {
      parsed = parse_device_list(name);
    } catch (const UsageError&) {
      continue;  // an interface this build has no name for
    }
    if (parsed.size() == 1 &&
        std::find(servable.begin(), servable.end(), parsed.front().interface) != servable.end()) {
      devices.push_back(parsed.front());
    }
  }
  std::sort(devices.begin(), devices.end());
  return devices;
}

int run_replay(const ReplayOptions& options, std::ostream& err, Progress& progress) {
  std::optional<TemporaryFile> converted;
  std::string player_log = options.input;
  if (detect_log_format(options.input) == LogFormat::kCarmen) {
    converted.emplace(std::filesystem::temp_directory_path() /
                      ("player-log-replay-" + std::to_string(::getpid()) + ".log"));
    ConvertOptions convert;
    convert.input = options.input;
    convert.output = converted->path().string();
    convert.to = ConvertTarget::kPlayer;
    std::ostringstream unused_stdout;
    run_convert(convert, unused_stdout, err, progress);
    player_log = converted->path().string();
  }

  const auto logged = replayable_devices(player_log, progress);
  std::vector<protocol::DeviceAddress> served = logged;
  if (!options.devices.empty()) {
    for (const auto& wanted : options.devices) {
      if (std::find(logged.begin(), logged.end(), wanted) == logged.end()) {
        throw UsageError(options.input + " has no " + protocol::to_string(wanted) + " to replay (it has " +
                         (logged.empty() ? std::string("none") : join(logged)) + ")");
      }
    }
    served = options.devices;
  }
  if (served.empty()) throw std::runtime_error(options.input + ": no devices that readlog can replay");
  if (options.log_level >= core::LogLevel::kInfo) {
    err << "player-log: replaying " << join(served) << " from " << options.input << "\n";
  }

  daemon::ServeOptions serve;
  serve.program_name = "player-log";
  serve.config_path = options.input + " (replay)";
  serve.config_text = replay_configuration(served, options.start, options.loop);
  serve.port = options.port;
  serve.bind_address = options.bind_address;
  serve.log_level = options.log_level;
  serve.readlog = player_log;
  serve.readlog_speed = options.rate;
  serve.readlog_data_queue = kReplayDataQueue;
  serve.readlog_duration = options.duration;
  serve.readlog_burst = options.burst;
  return tools::exit_status_for(daemon::serve(serve));
}

}  // namespace playerkit::plog
