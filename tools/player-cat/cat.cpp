#include "cat.hpp"

#include <algorithm>
#include <cerrno>
#include <chrono>
#include <cmath>
#include <cstring>
#include <filesystem>
#include <map>
#include <memory>
#include <set>
#include <stdexcept>
#include <string>
#include <vector>

#include "client/client.hpp"
#include "files/output_file.hpp"
#include "formatters.hpp"
#include "message_decoder.hpp"
#include "protocol/errors.hpp"

namespace playerkit::cat {
namespace {

using Clock = std::chrono::steady_clock;
using protocol::Message;
using protocol::MessageType;
using tools::Formatter;
using tools::MessageDecoder;
using tools::TimeColumn;
using tools::describe_fields;

// A problem to report as "player-cat: <what>" with an exit status.
class CatFailure : public std::runtime_error {
 public:
  explicit CatFailure(const std::string& what, int status = kExitFailure)
      : std::runtime_error(what), status_(status) {}
  [[nodiscard]] int status() const { return status_; }

 private:
  int status_;
};

// The reader of stdout went away (`player-cat ... | head`): stop quietly.
struct StdoutClosed {};

std::chrono::milliseconds to_milliseconds(double seconds) {
  return std::chrono::milliseconds(static_cast<std::int64_t>(std::ceil(seconds * 1000.0)));
}

std::string device_lines(const std::vector<client::DeviceEntry>& entries) {
  if (entries.empty()) return "  (no devices)\n";
  std::string text;
  for (const auto& entry : entries) {
    text += "  " + protocol::to_string(entry.address) + " " +
            (entry.driver_name.empty() ? std::string("(driver unknown)") : entry.driver_name) + "\n";
  }
  return text;
}

void subscribe(client::Client& connection, const CatOptions& options) {
  for (const auto device : options.devices) {
    const auto grant = connection.request_access(device, protocol::Access::kRead);
    if (grant.access == protocol::Access::kRead || grant.access == protocol::Access::kAll) continue;
    const std::string name = protocol::to_string(device);
    const std::string where = client::to_string(options.server);
    std::string problem;
    if (grant.driver_name.empty()) {
      problem = where + " has no device " + name;
    } else {
      problem = name + " (driver " + grant.driver_name + ") on " + where +
                " could not be opened for reading (access '" +
                std::string(1, static_cast<char>(grant.access)) +
                "'): its driver failed to set up; the server's log says why";
    }
    // Reading the device list before the message: the reply carries what the server has.
    throw CatFailure(problem + "\nthe server has:\n" + device_lines(connection.device_list()));
  }
}

// Where the lines go: stdout, or one CSV file per device with --csv-dir.
class Outputs {
 public:
  Outputs(const CatOptions& options, std::ostream& out) : out_(out) {
    if (options.csv_dir) open_csv_files(options);
    switch (options.format) {
      case OutputFormat::kText:
        formatter_ = tools::make_text_formatter(out, options.fields);
        break;
      case OutputFormat::kJson:
        formatter_ = tools::make_json_formatter(out, options.fields);
        break;
      case OutputFormat::kLog:
        formatter_ = tools::make_log_formatter(out, options.server);
        break;
      case OutputFormat::kCsv: {
        std::map<protocol::DeviceAddress, std::ostream*> sinks;
        for (std::size_t i = 0; i < options.devices.size(); ++i) {
          sinks[options.devices[i]] = files_.empty() ? &out : &files_[i].output->stream();
        }
        formatter_ = tools::make_csv_formatter(std::move(sinks), options.fields);
        break;
      }
    }
    check();
  }

  Formatter& formatter() { return *formatter_; }

  // After every write: stdout closed by its reader ends the run quietly;
  // any other failed write is an error.
  void check() const {
    if (!out_) {
      if (errno == EPIPE) throw StdoutClosed{};
      throw CatFailure(std::string("cannot write to stdout: ") + std::strerror(errno));
    }
    for (const auto& file : files_) {
      try {
        file.output->check();
      } catch (const files::OutputError& e) {
        throw CatFailure(e.what());
      }
    }
  }

 private:
  struct File {
    std::filesystem::path path;
    // Streaming: the CSV grows under its name while player-cat runs, and
    // keeps what was written whatever ends the run.
    std::unique_ptr<files::OutputFile> output;
  };

  void open_csv_files(const CatOptions& options) {
    std::error_code error;
    std::filesystem::create_directories(*options.csv_dir, error);
    if (error) throw CatFailure("cannot create " + options.csv_dir->string() + ": " + error.message());
    for (const auto device : options.devices) {
      File file{*options.csv_dir / csv_file_name(device), nullptr};
      try {
        file.output = std::make_unique<files::OutputFile>(
            file.path, files::OutputFileOptions{.compression = files::Compression::kNone,
                                                .mode = files::WriteMode::kStreaming});
      } catch (const files::OutputError& e) {
        throw CatFailure(e.what());
      }
      files_.push_back(std::move(file));
    }
  }

  std::ostream& out_;
  std::vector<File> files_;
  std::unique_ptr<Formatter> formatter_;
};

// Counts, --once, the --field check at each device's first message.
class Dump {
 public:
  Dump(const CatOptions& options, Outputs& outputs, std::ostream& err)
      : options_(options),
        outputs_(outputs),
        err_(err),
        decoder_("player-cat", options.si, err),
        time_column_(options.time_style) {}

  [[nodiscard]] bool done() const {
    if (options_.count && printed_ >= *options_.count) return true;
    return options_.once && devices_seen_.size() == options_.devices.size();
  }

  void handle(const Message& message) {
    if (message.type() == MessageType::kSynch) {
      outputs_.formatter().synch(message);
      outputs_.check();
      return;
    }
    if (message.type() != MessageType::kData) return;
    const auto device = message.device();
    if (std::find(options_.devices.begin(), options_.devices.end(), device) == options_.devices.end()) return;
    const bool first_of_device = !devices_seen_.contains(device);
    if (options_.once && !first_of_device) return;

    const nlohmann::json json =
        options_.format == OutputFormat::kLog ? nlohmann::json::object() : decoder_.to_json(message);
    if (first_of_device && !options_.fields.empty()) check_fields(device, json.at("data"));
    devices_seen_.insert(device);
    try {
      outputs_.formatter().data({message, json, time_column_.next(message.time())});
    } catch (const protocol::DecodeError& e) {
      // Only the log writer decodes on its own. A log line has no room for raw
      // bytes: say so, and go on with the next message.
      err_ << "player-cat: " << protocol::to_string(device) << ": data does not decode (" << e.what()
           << "); no log line for it\n";
      return;
    }
    outputs_.check();
    ++printed_;
  }

 private:
  void check_fields(protocol::DeviceAddress device, const nlohmann::json& data) const {
    const auto missing = missing_fields(data, options_.fields);
    if (missing.empty()) return;
    throw CatFailure(protocol::to_string(device) + " has no field '" + missing.front().text() +
                         "'; its data has: " + describe_fields(data),
                     kExitUsage);
  }

  const CatOptions& options_;
  Outputs& outputs_;
  std::ostream& err_;
  MessageDecoder decoder_;
  TimeColumn time_column_;
  std::set<protocol::DeviceAddress> devices_seen_;
  std::uint64_t printed_ = 0;
};

client::Client connect_and_prepare(const CatOptions& options) {
  auto connection =
      client::Client::connect(options.server.host, options.server.port, to_milliseconds(options.timeout));
  try {
    if (options.key) connection.authenticate(*options.key);
    if (options.list) return connection;
    connection.set_data_mode(options.mode);
    if (options.rate && !options.pull_mode())
      connection.set_frequency(static_cast<std::uint16_t>(*options.rate));
    subscribe(connection, options);
  } catch (const client::ClientError& e) {
    // A server started with -k hangs up on a first message that is not its key.
    if (options.key) throw;
    throw CatFailure(std::string(e.what()) + "; if the server was started with -k, pass --key");
  }
  return connection;
}

void stream(client::Client& connection, const CatOptions& options, Dump& dump,
            const std::function<bool()>& stop_requested) {
  const auto start = Clock::now();
  std::optional<Clock::time_point> deadline;
  if (options.duration) {
    deadline =
        start + std::chrono::duration_cast<Clock::duration>(std::chrono::duration<double>(*options.duration));
  }
  const auto pull_period = std::chrono::duration_cast<Clock::duration>(
      std::chrono::duration<double>(1.0 / options.rate.value_or(kDefaultPullRate)));
  auto next_pull = start;

  while (!dump.done() && !stop_requested()) {
    auto now = Clock::now();
    if (deadline && now >= *deadline) return;
    auto wake = now + std::chrono::milliseconds(100);
    if (options.pull_mode()) {
      if (now >= next_pull) {
        connection.request_data();
        next_pull += pull_period;
        // After a stall, keep the pace rather than catching up in a burst.
        if (next_pull <= now) next_pull = now + pull_period;
      }
      wake = std::min(wake, next_pull);
    }
    if (deadline) wake = std::min(wake, *deadline);
    now = Clock::now();
    const auto wait =
        std::max(std::chrono::milliseconds(1), std::chrono::ceil<std::chrono::milliseconds>(wake - now));
    if (auto message = connection.read(wait)) dump.handle(*message);
  }
}

}  // namespace

int run_cat(const CatOptions& options, std::ostream& out, std::ostream& err,
            const std::function<bool()>& stop_requested) {
  try {
    auto connection = connect_and_prepare(options);
    if (options.list) {
      for (const auto& entry : connection.device_list()) {
        out << protocol::to_string(entry.address) << ' ' << entry.driver_name << '\n' << std::flush;
      }
      if (!out && errno != EPIPE)
        throw CatFailure(std::string("cannot write to stdout: ") + std::strerror(errno));
      return kExitOk;
    }
    Outputs outputs(options, out);
    Dump dump(options, outputs, err);
    stream(connection, options, dump, stop_requested);
    return kExitOk;
  } catch (const StdoutClosed&) {
    return kExitOk;
  } catch (const CatFailure& e) {
    err << "player-cat: " << e.what() << (std::string_view(e.what()).ends_with('\n') ? "" : "\n");
    return e.status();
  } catch (const client::ClientError& e) {
    err << "player-cat: " << e.what() << "\n";
    return kExitFailure;
  } catch (const std::exception& e) {
    err << "player-cat: " << e.what() << "\n";
    return kExitFailure;
  }
}

}  // namespace playerkit::cat
