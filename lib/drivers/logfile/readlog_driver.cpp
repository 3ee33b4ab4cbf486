#include "drivers/logfile/readlog_driver.hpp"

#include <cmath>
#include <map>
#include <mutex>
#include <stdexcept>
#include <string>
#include <tuple>
#include <utility>

#include "config/errors.hpp"
#include "core/device.hpp"
#include "protocol/interfaces.hpp"

namespace playerkit::drivers {

ReadlogDriver::ReadlogDriver(std::shared_ptr<ReplaySession> session, protocol::DeviceAddress logged)
    : session_(std::move(session)), logged_(logged) {}

void ReadlogDriver::setup() { session_->attach(device(), logged_); }

void ReadlogDriver::shutdown() { session_->detach(device()); }

namespace {

// The readers shared between the devices of one registry: one per file and
// options, as long as some device holds it.
class ReplaySessions {
 public:
  explicit ReplaySessions(ReadlogSettings settings) : settings_(std::move(settings)) {}

  std::shared_ptr<ReplaySession> get(const ReplayOptions& options, core::Logger& logger) {
    std::lock_guard lock(mutex_);
    const Key key{options.path.string(), options.speed, options.autorewind, options.start_offset};
    // duration and burst come from the settings: the same for every device.
    if (auto existing = sessions_[key].lock()) return existing;
    // Only one reader keeps the server's time: the first one on the -r file.
    std::shared_ptr<core::ManualClock> clock;
    if (!clock_taken_ && settings_.log && options.path == *settings_.log) {
      clock = std::make_shared<core::ManualClock>();
      clock_taken_ = true;
    }
    auto session = std::make_shared<ReplaySession>(options, clock, settings_.timer, logger);
    sessions_[key] = session;
    return session;
  }

  const ReadlogSettings& settings() const { return settings_; }

 private:
  using Key = std::tuple<std::string, double, bool, double>;
  const ReadlogSettings settings_;
  std::mutex mutex_;
  std::map<Key, std::weak_ptr<ReplaySession>> sessions_;
  bool clock_taken_ = false;
};

// Enough that a client's round carries many lines, few enough to bound memory.
constexpr std::size_t kBurstDataQueue = 64;

config::SourceLocation where_of(const config::Section& section, std::string_view option) {
  const config::Property* property = section.property(option);
  return property != nullptr ? property->where : section.where();
}

ReplayOptions read_replay_options(const config::Section& section, const ReadlogSettings& settings) {
  ReplayOptions options;
  const std::string fallback = settings.log ? settings.log->string() : std::string();
  options.path = section.read_filename("filename", fallback);
  if (options.path.empty()) {
    throw config::ConfigError(section.where(),
                              "readlog: no log file: start player-serve with -r LOG or give a filename option");
  }
  options.speed = section.read_float("speed", settings.speed);
  if (!std::isfinite(options.speed) || options.speed <= 0) {
    throw config::ConfigError(where_of(section, "speed"),
                              "readlog: speed " + std::to_string(options.speed) + " must be above 0");
  }
  const int autorewind = section.read_int("autorewind", 0);
  if (autorewind != 0 && autorewind != 1) {
    throw config::ConfigError(where_of(section, "autorewind"), "readlog: autorewind must be 0 or 1");
  }
  options.autorewind = autorewind == 1;
  options.start_offset = section.read_float("start", 0.0);
  if (!std::isfinite(options.start_offset) || options.start_offset < 0) {
    throw config::ConfigError(where_of(section, "start"),
                              "readlog: start must be 0 or more seconds into the log");
  }
  options.duration = settings.duration;
  options.burst = settings.burst;
  return options;
}

}  // namespace

core::DriverSpec readlog_driver_spec(ReadlogSettings settings) {
  auto sessions = std::make_shared<ReplaySessions>(std::move(settings));
  core::DriverSpec spec;
  spec.name = "readlog";
  // What lib/log reads back with data fields; other interfaces' lines carry none.
  spec.interfaces = {protocol::kPowerCode,      protocol::kPositionCode,   protocol::kSonarCode,
                     protocol::kLaserCode,      protocol::kBlobfinderCode, protocol::kPtzCode,
                     protocol::kFiducialCode,   protocol::kGpsCode,        protocol::kBumperCode,
                     protocol::kTruthCode,      protocol::kIrCode,         protocol::kWifiCode,
                     protocol::kLocalizeCode,   protocol::kPosition3dCode};
  spec.access = protocol::Access::kRead;
  spec.limits.data_queue = sessions->settings().data_queue;
  if (sessions->settings().burst && spec.limits.data_queue == 0) spec.limits.data_queue = kBurstDataQueue;
  spec.factory = [sessions](const core::DriverContext& context) -> std::unique_ptr<core::Driver> {
    const ReplayOptions options = read_replay_options(context.section, sessions->settings());
    const int index = context.section.read_int("index", context.key.address.index);
    if (index < 0 || index > 65535) {
      throw config::ConfigError(where_of(context.section, "index"),
                                "readlog: index " + std::to_string(index) + " is not 0-65535");
    }
    const protocol::DeviceAddress logged{context.key.address.interface, static_cast<std::uint16_t>(index)};
    auto session = sessions->get(options, context.logger);
    // With -r every header time the server writes is log time
    // (logfile-format.md §5).
    if (auto log_clock = session->clock()) context.clock.claim(log_clock, core::to_string(context.key) + " (readlog)");
    return std::make_unique<ReadlogDriver>(std::move(session), logged);
  };
  spec.summary = "replays the data of a Player text log (player-serve -r LOG)";
  spec.doc.manual_section = "7.36";
  spec.doc.options = {
      {"filename", "filename", "the -r file", "", "the log to replay (relative to the config file); required without -r"},
      {"index", "int", "the device's index", "", "which logged device of this interface to replay"},
      {"speed", "float", "1 (-f)", "", "replay speed factor, above 0"},
      {"autorewind", "int", "0", "", "1: start again at the end of the file"},
      {"start", "float", "0", "s", "skip the log's first seconds"}};
  spec.doc.requests = {"every request: NACK"};
  spec.doc.example = "position:0 ( driver \"readlog\" filename \"run.log\" )";
  return spec;
}

}  // namespace playerkit::drivers
