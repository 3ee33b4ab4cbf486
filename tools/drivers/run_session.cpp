#include "run_session.hpp"

#include <algorithm>
#include <atomic>
#include <chrono>
#include <memory>
#include <mutex>
#include <optional>
#include <set>
#include <thread>

#include "cat.hpp"
#include "client/client.hpp"
#include "daemon/daemon.hpp"
#include "device_monitor.hpp"
#include "driver_lookup.hpp"
#include "input_lines.hpp"
#include "line_feed.hpp"
#include "line_streams.hpp"
#include "outgoing_message.hpp"
#include "sender.hpp"
#include "known_drivers.hpp"
#include "telegram_trace.hpp"
#include "usage_error.hpp"

namespace playerkit::player_drivers {

namespace {

using Clock = std::chrono::steady_clock;

bool readable(protocol::Access access) { return access == protocol::Access::kRead || access == protocol::Access::kAll; }

std::string device_list(const RunPlan& plan) {
  std::string text;
  for (const auto& device : plan.devices) {
    text += (text.empty() ? "" : ", ") + protocol::to_string(device.address) + " (" + device.spec->name + ")";
  }
  return text;
}

// The daemon's log, with locations in the generated configuration told back
// as what the user typed, and the options no driver read set aside: they are
// errors here (a typo), where a configuration file only warns.
class DaemonLog {
 public:
  DaemonLog(const RunPlan& plan, SharedLines& err) : plan_(plan), err_(err) {}

  // Once known: "laser:0@41234" is then shown as "laser:0" (there is one port).
  void set_port(std::uint16_t port) { port_ = port; }
  // A device's set-up failed (and this log said why).
  [[nodiscard]] const std::atomic<bool>& setup_failed() const { return setup_failed_; }

  core::Logger::Sink sink() {
    return [this](core::LogLevel level, std::string_view message) {
      if (message.find("setup failed") != std::string_view::npos) setup_failed_ = true;
      const auto located = split_config_message(kGeneratedConfigName, message);
      if (located && located->text.find("is defined but not used") != std::string::npos) {
        const auto option = plan_.option_lines.find(located->line);
        if (option != plan_.option_lines.end()) {
          const std::lock_guard lock(mutex_);
          unused_.push_back(option->second);
          return;
        }
      }
      std::string text = explain_config_message(plan_, kGeneratedConfigName, message);
      if (const std::uint16_t port = port_; port != 0) {
        const std::string suffix = "@" + std::to_string(port);
        for (std::size_t at = text.find(suffix); at != std::string::npos; at = text.find(suffix, at)) {
          text.erase(at, suffix.size());
        }
      }
      err_.write_line("player-drivers: " + std::string(core::to_string(level)) + ": " + text);
    };
  }

  std::vector<OptionAssignment> unused() const {
    const std::lock_guard lock(mutex_);
    return unused_;
  }

 private:
  const RunPlan& plan_;
  SharedLines& err_;
  std::atomic<std::uint16_t> port_{0};
  std::atomic<bool> setup_failed_{false};
  mutable std::mutex mutex_;
  std::vector<OptionAssignment> unused_;
};

// player-cat's and player-send's messages as player-drivers': their names
// replaced, and their "could not be opened ... the server's log says why"
// (with the device list after it) left out once the daemon's own line has
// said why.
SharedLines::LineFilter client_diagnostics(const std::atomic<bool>& setup_failed) {
  auto dropping = std::make_shared<bool>(false);
  return [&setup_failed, dropping](std::string_view line) -> std::optional<std::string> {
    if (*dropping && (line == "the server has:" || line.starts_with("  "))) return std::nullopt;
    *dropping = false;
    const bool redundant = line.find("could not be opened") != std::string_view::npos ||
                           line.find("sending the request anyway") != std::string_view::npos;
    if (setup_failed && redundant) {
      *dropping = true;
      return std::nullopt;
    }
    for (const std::string_view program : {"player-cat: ", "player-send: "}) {
      if (line.starts_with(program)) return "player-drivers: " + std::string(line.substr(program.size()));
    }
    return std::string(line);
  };
}

// "null reads no option 'foo'; its options: a, b" (or where to look).
std::string unused_option_text(const RunPlan& plan, const OptionAssignment& option) {
  const PlannedDevice* owner = nullptr;
  for (const auto& device : plan.devices) {
    for (const auto& given : device.options) {
      if (given == option) owner = &device;
    }
  }
  const core::DriverSpec& spec = owner ? *owner->spec : *plan.devices.front().spec;
  std::string text = "option " + option.name + "=" + option.value + ": " + spec.name + " does not read '" +
                     option.name + "'";
  const std::vector<core::OptionDoc> rows = spec.doc.option_rows();
  if (rows.empty()) return text + " (player-drivers info " + spec.name + ")";
  std::string names;
  for (const auto& documented : rows) names += (names.empty() ? "" : ", ") + documented.name;
  return text + "; its options: " + names;
}

// daemon.run() on a thread of its own, stopped and joined on destruction.
class ServingThread {
 public:
  explicit ServingThread(daemon::Daemon& daemon) : daemon_(daemon), thread_([this] { daemon_.run(); }) {}
  ~ServingThread() {
    daemon_.stop();
    thread_.join();
  }
  ServingThread(const ServingThread&) = delete;
  ServingThread& operator=(const ServingThread&) = delete;

 private:
  daemon::Daemon& daemon_;
  std::thread thread_;
};

// --stats: a report on stderr every second until destroyed.
class StatsPrinter {
 public:
  StatsPrinter(const std::vector<MonitoredDevice>& devices, SharedLines& err)
      : monitor_(devices), thread_([this, &err](std::stop_token stop) { run(stop, err); }) {}

 private:
  void run(const std::stop_token& stop, SharedLines& err) {
    auto next = Clock::now() + std::chrono::seconds(1);
    while (!stop.stop_requested()) {
      if (Clock::now() < next) {
        std::this_thread::sleep_for(std::min<Clock::duration>(next - Clock::now(), std::chrono::milliseconds(50)));
        continue;
      }
      next += std::chrono::seconds(1);
      for (const auto& line : monitor_.report(Clock::now())) err.write_line(line);
    }
  }

  DeviceMonitor monitor_;
  std::jthread thread_;  // last: stopped and joined before the monitor goes
};

// What the client side needs once the daemon serves.
struct Served {
  std::string host;
  std::uint16_t port = 0;
  std::vector<protocol::DeviceAddress> read_devices;
  std::optional<cat::CatOptions> cat_options;
  std::optional<protocol::Message> request;
  const std::atomic<bool>* setup_failed = nullptr;  // DaemonLog's
};

// Waits for a stop or the --duration with nothing to read.
int serve_only(const cat::CommandLine& cat_line, const std::function<bool()>& stop) {
  const auto start = Clock::now();
  while (!stop()) {
    if (cat_line.duration && Clock::now() - start >= std::chrono::duration<double>(*cat_line.duration)) break;
    std::this_thread::sleep_for(std::chrono::milliseconds(50));
  }
  return kExitOk;
}

int dump(const Served& served, const cat::CommandLine& cat_line, SharedLines& out, SharedLines& err,
         const std::function<bool()>& stop) {
  if (!served.cat_options) return serve_only(cat_line, stop);
  cat::CatOptions options = *served.cat_options;
  options.server = {served.host, served.port};
  const auto out_stream = out.open();
  const auto err_stream = err.open(client_diagnostics(*served.setup_failed));
  return cat::run_cat(options, *out_stream, *err_stream, stop);
}

int send_request(const Served& served, double timeout_seconds, SharedLines& out, SharedLines& err) {
  const auto timeout = std::chrono::milliseconds(static_cast<long long>(timeout_seconds * 1000.0));
  const auto out_stream = out.open();
  const auto err_stream = err.open(client_diagnostics(*served.setup_failed));
  try {
    auto connection = client::Client::connect(served.host, served.port, timeout);
    connection.set_timeout(timeout);
    player_send::Sender sender(connection, *out_stream, *err_stream);
    return player_send::to_int(sender.send(*served.request));
  } catch (const client::ClientError& e) {
    err.write_line(std::string("player-drivers: ") + e.what());
    return kExitFailure;
  } catch (const player_send::UsageError& e) {
    err.write_line(std::string("player-drivers: --req: ") + e.what());
    return kExitUsage;
  }
}

// --stdin: the lines go out on a connection of their own while the data is
// dumped; without -n or --duration the run ends with the input.
int feed_and_dump(const Served& served, const RunOptions& options, const RunStreams& streams, SharedLines& out,
                  SharedLines& err, const std::function<bool()>& stop) {
  InterruptibleInput input(streams.input_fd);
  std::atomic<bool> feed_done{false};
  std::atomic<int> feed_status{kExitOk};
  std::thread feeder([&] {
    const auto out_stream = out.open();
    const auto err_stream = err.open(client_diagnostics(*served.setup_failed));
    const auto timeout = std::chrono::milliseconds(static_cast<long long>(options.cat_line.timeout * 1000.0));
    int status = kExitOk;
    try {
      auto connection = client::Client::connect(served.host, served.port, timeout);
      connection.set_timeout(timeout);
      player_send::Sender sender(connection, *out_stream, *err_stream);
      const auto code = player_send::send_lines(input.stream(), sender, std::nullopt, *err_stream);
      if (code != player_send::ExitCode::kConnection) sender.confirm_commands();
      status = player_send::to_int(code);
    } catch (const client::ClientError& e) {
      *err_stream << "player-drivers: --stdin: " << e.what() << "\n" << std::flush;
      status = kExitFailure;
    }
    feed_status = status;
    feed_done = true;
  });
  const bool limited = options.cat_line.count || options.cat_line.duration;
  const auto until = [&] { return stop() || (!limited && feed_done); };
  const int dump_status = dump(served, options.cat_line, out, err, until);
  input.stop();
  feeder.join();
  return feed_status != kExitOk ? feed_status.load() : dump_status;
}

// --trace on the first device of each link that has one.
void install_traces(const RunPlan& plan, const families::FamilyRegistry& families,
                    const std::vector<core::Device*>& devices, SharedLines& err) {
  bool any = false;
  for (std::size_t i = 0; i < devices.size(); ++i) {
    const core::DriverSpec& spec = *plan.devices[i].spec;
    // A family's devices share one link: it is traced under the family's name.
    const std::string label = plan.family ? plan.name : protocol::to_string(plan.devices[i].address);
    auto trace = telegram_trace(label, families.framing(spec.family),
                                [&err](std::string_view line) { err.write_line(line); });
    if (devices[i]->driver().set_byte_trace(std::move(trace))) {
      any = true;
      // The devices of a family share one link: traced once.
      if (plan.family) break;
    }
  }
  if (!any) {
    err.write_line("player-drivers: --trace: " + plan.name +
                   " has no link to trace (only drivers of hardware have one)");
  }
}

// Planning and checking, before anything starts. Throws UsageError.
RunPlan plan_run(const core::DriverRegistry& registry, const RunOptions& options, Served& served) {
  const DriverSelection selection = select_drivers(registry, options.plan.name);
  PlanRequest request = options.plan;
  if (!selection.family) request.serve_as = options.device;
  RunPlan plan = make_run_plan(registry, request);

  std::optional<protocol::DeviceAddress> target;
  for (const auto& device : plan.devices) {
    if (plan.family && options.device && device.address != *options.device) continue;
    if (!target) target = device.address;
    if (readable(device.spec->access)) served.read_devices.push_back(device.address);
  }
  if (!target) {
    throw UsageError("--device " + protocol::to_string(*options.device) + ": " + plan.name + " serves " +
                     device_list(plan));
  }
  if (!served.read_devices.empty()) {
    cat::CommandLine cat_line = options.cat_line;
    cat_line.targets = {"127.0.0.1:6665"};
    for (const auto address : served.read_devices) cat_line.targets.push_back(protocol::to_string(address));
    served.cat_options = cat::make_cat_options(cat_line);
  } else if (options.cat_line.count || !options.cat_line.fields.empty()) {
    throw UsageError(plan.name + " has no device to read data from (" + device_list(plan) +
                     "): -n and --field do not apply");
  }
  if (!options.request.empty()) {
    std::vector<std::string> words = {protocol::to_string(*target), "req"};
    words.insert(words.end(), options.request.begin(), options.request.end());
    try {
      served.request = player_send::message_from_arguments(words);
    } catch (const player_send::UsageError& e) {
      throw UsageError(std::string("--req: ") + e.what());
    }
  }
  return plan;
}

}  // namespace

int run_driver(const RunOptions& options, const families::FamilyRegistry& families, const RunStreams& streams,
               const std::function<bool()>& stop_requested) {
  SharedLines out(streams.out);
  SharedLines err(streams.err);

  core::Logger loader_log("player-drivers");
  loader_log.set_level(core::LogLevel::kWarning);
  loader_log.set_sink([&err](core::LogLevel level, std::string_view message) {
    err.write_line("player-drivers: " + std::string(core::to_string(level)) + ": " + std::string(message));
  });
  core::DriverRegistry registry;
  try {
    registry = known_drivers(options.plugins, families, loader_log);
  } catch (const std::exception& e) {
    err.write_line(std::string("player-drivers: ") + e.what());
    return kExitFailure;
  }

  Served served;
  RunPlan plan;
  try {
    plan = plan_run(registry, options, served);
  } catch (const UsageError& e) {
    err.write_line(std::string("player-drivers: run: ") + e.what());
    return kExitUsage;
  }

  daemon::ServeOptions serve;
  serve.program_name = "player-drivers";
  serve.config_path = kGeneratedConfigName;
  serve.config_text = plan.config_text;
  serve.port = options.serve_port.value_or(0);
  serve.bind_address = options.bind_address;
  serve.plugins = options.plugins;
  serve.extra_drivers = drivers_brought_by(families);
  serve.log_level = options.verbose ? core::LogLevel::kInfo : core::LogLevel::kWarning;

  DaemonLog log(plan, err);
  std::unique_ptr<daemon::Daemon> daemon;
  try {
    daemon = std::make_unique<daemon::Daemon>(serve);
    daemon->logger().set_sink(log.sink());
    daemon->load();
  } catch (const daemon::DaemonError& e) {
    return e.result() == daemon::ServeResult::bad_configuration ? kExitUsage : kExitFailure;
  }
  const auto unused = log.unused();
  if (!unused.empty()) {
    for (const auto& option : unused) err.write_line("player-drivers: run: " + unused_option_text(plan, option));
    return kExitUsage;
  }

  served.port = daemon->default_port();
  served.setup_failed = &log.setup_failed();
  log.set_port(served.port);
  served.host = options.bind_address == "0.0.0.0" ? "127.0.0.1" : options.bind_address;
  std::vector<core::Device*> devices;
  std::vector<MonitoredDevice> monitored;
  for (const auto& planned : plan.devices) {
    core::Device* device = daemon->devices().find(served.port, planned.address);
    if (!device) {
      err.write_line("player-drivers: " + protocol::to_string(planned.address) + " was not created");
      return kExitFailure;
    }
    devices.push_back(device);
    // --stats watches what is read (all of them when nothing is).
    const bool read = std::find(served.read_devices.begin(), served.read_devices.end(), planned.address) !=
                      served.read_devices.end();
    if (read || served.read_devices.empty()) monitored.push_back({device, plan.family ? plan.name : std::string()});
  }
  if (options.trace) install_traces(plan, families, devices, err);
  try {
    daemon->start();
  } catch (const daemon::DaemonError&) {
    return kExitFailure;  // logged
  }
  if (options.serve_port) {
    err.write_line("player-drivers: listening on port " + std::to_string(served.port) + " (" + options.bind_address +
                   "): " + device_list(plan));
  } else if (options.verbose) {
    err.write_line("player-drivers: serving " + device_list(plan) + " on " + served.host + ":" +
                   std::to_string(served.port));
  }

  const ServingThread serving(*daemon);
  std::optional<StatsPrinter> stats;
  if (options.stats) stats.emplace(monitored, err);

  if (served.request) return send_request(served, options.cat_line.timeout, out, err);
  if (options.from_stdin) return feed_and_dump(served, options, streams, out, err, stop_requested);
  if (!served.cat_options) {
    err.write_line("player-drivers: " + plan.name + " has no device to read data from; serving until " +
                   (options.cat_line.duration ? std::string("--duration ends") : std::string("Ctrl-C")));
  }
  return dump(served, options.cat_line, out, err, stop_requested);
}

}  // namespace playerkit::player_drivers
