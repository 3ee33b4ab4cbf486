#include "log_record.hpp"

#include <algorithm>
#include <chrono>
#include <set>
#include <stdexcept>
#include <variant>

#include "client/client.hpp"
#include "log/log_line.hpp"
#include "log/text_log_reader.hpp"
#include "log/text_log_writer.hpp"
#include "log_tool.hpp"
#include "protocol/errors.hpp"
#include "text/printable.hpp"

namespace playerkit::plog {
namespace {

using Clock = std::chrono::steady_clock;

// What stops a recording: --count, --duration, a signal.
class Limits {
 public:
  Limits(const RecordOptions& options, const std::function<bool()>& stop_requested)
      : options_(options), stop_requested_(stop_requested) {
    if (options.duration) {
      has_deadline_ = true;
      deadline_ = Clock::now() + std::chrono::duration_cast<Clock::duration>(
                                     std::chrono::duration<double>(*options.duration));
    }
  }
  [[nodiscard]] bool done() const {
    if (stop_requested_()) return true;
    if (options_.count && recorded >= *options_.count) return true;
    return has_deadline_ && Clock::now() >= deadline_;
  }
  std::chrono::milliseconds wait() const {
    auto wait = std::chrono::milliseconds(100);
    if (has_deadline_) {
      const auto left = std::chrono::ceil<std::chrono::milliseconds>(deadline_ - Clock::now());
      wait = std::clamp(left, std::chrono::milliseconds(1), wait);
    }
    return wait;
  }
  std::uint64_t recorded = 0;

 private:
  const RecordOptions& options_;
  const std::function<bool()>& stop_requested_;
  // Not an optional: GCC 12 warns (falsely) that one may be used uninitialized.
  bool has_deadline_ = false;
  Clock::time_point deadline_{};
};

// The output, opened (truncating an older file of that name) only once the
// recording starts, so that a recording that cannot start leaves it alone.
// It streams to its final name (tail -f, player-log info while it runs); what
// was recorded reaches the file at every line, for gzip at most once a
// second (each flush costs compression), and is kept whatever ends the run.
class Recording {
 public:
  Recording(const RecordOptions& options, std::ostream& out, std::vector<std::string> inputs)
      : options_(options), out_(out), inputs_(std::move(inputs)) {}

  std::ostream& stream() { return open().stream(); }
  [[nodiscard]] bool started() const { return output_.has_value(); }

  // After each line.
  void flush() {
    OutputFile& output = open();
    const auto now = Clock::now();
    if (output.compressed() && now - last_flush_ < std::chrono::seconds(1)) {
      held_back_ = true;
      output.check();
      return;
    }
    last_flush_ = now;
    held_back_ = false;
    output.flush();
  }
  // When the input pauses: what flush() held back goes out.
  void flush_held_back() {
    if (!held_back_) return;
    held_back_ = false;
    last_flush_ = Clock::now();
    open().flush();
  }
  void finish() { open().commit(); }

 private:
  OutputFile& open() {
    if (!output_) output_.emplace(options_.output, out_, inputs_, files::WriteMode::kStreaming);
    return *output_;
  }

  const RecordOptions& options_;
  std::ostream& out_;
  std::vector<std::string> inputs_;
  std::optional<OutputFile> output_;
  Clock::time_point last_flush_{};
  bool held_back_ = false;
};

void record_from_server(const RecordOptions& options, Recording& output, std::ostream& err, Limits& limits) {
  auto connection = client::Client::connect(options.server.host, options.server.port,
                                            std::chrono::milliseconds(static_cast<long>(options.timeout * 1000)));
  for (const auto device : options.devices) {
    const auto grant = connection.request_access(device, protocol::Access::kRead);
    if (grant.access != protocol::Access::kRead && grant.access != protocol::Access::kAll) {
      throw std::runtime_error(client::to_string(options.server) +
                               (grant.driver_name.empty() ? " has no device " : " could not open ") +
                               protocol::to_string(device));
    }
  }
  if (options.frequency) connection.set_frequency(*options.frequency);
  auto& stream = output.stream();
  stream << log::log_file_header();
  output.flush();
  const std::string& host = options.server.host;
  const std::set<protocol::DeviceAddress> wanted(options.devices.begin(), options.devices.end());
  bool data_since_sync = false;
  while (!limits.done()) {
    const auto message = connection.read(limits.wait());
    if (!message) {
      output.flush_held_back();
      continue;
    }
    if (message->type() == protocol::MessageType::kSynch) {
      if (!data_since_sync) continue;
      stream << log::format_sync_line(message->time(), host, options.server.port);
      data_since_sync = false;
    } else if (message->type() == protocol::MessageType::kData && wanted.contains(message->device())) {
      try {
        stream << log::format_data_line(*message, host, options.server.port);
      } catch (const protocol::DecodeError& e) {
        err << "player-log: " << protocol::to_string(message->device()) << ": data does not decode (" << e.what()
            << "); no log line for it\n";
        continue;
      }
      data_since_sync = true;
      ++limits.recorded;
    } else {
      continue;
    }
    output.flush();
  }
}

void record_from_stdin(const RecordOptions& options, std::istream& in, Recording& output, std::ostream& err,
                       Limits& limits) {
  auto version = log::LogFormatVersion::k0_0_0;
  bool header_written = false;
  std::size_t malformed = 0;
  std::string text;
  // A blocking getline: a signal ends the run at the next line or at the end of input.
  bool too_long = false;
  for (int number = 1; !limits.done() && log::read_log_line(in, text, too_long); ++number) {
    log::LogLine line;
    try {
      if (too_long) throw log::too_long_line_error("stdin", number);
      line = log::parse_log_line(text, "stdin", number, version);
    } catch (const log::LogParseError& e) {
      if (options.strict) throw;
      if (malformed++ < 10) err << e.what() << "\n";
      continue;
    }
    if (const auto* header = std::get_if<log::HeaderLine>(&line)) {
      if (header->name == "File version") {
        const auto parsed = log::parse_format_version(header->value);
        if (!parsed) throw std::runtime_error("stdin: unknown file version '" + text::excerpt(header->value) + "'");
        version = *parsed;
      }
      output.stream() << text << "\n";
      header_written = true;
    } else if (std::holds_alternative<log::SkippedLine>(line)) {
      continue;
    } else {
      if (!header_written) {
        output.stream() << log::log_file_header();
        header_written = true;
      }
      output.stream() << text << "\n";
      if (std::holds_alternative<log::DataLine>(line)) ++limits.recorded;
    }
    output.flush();
  }
  if (!header_written) output.stream() << log::log_file_header();
  if (malformed > 0) err << "player-log: " << malformed << " malformed line(s) skipped\n";
}

}  // namespace

void parse_record_targets(const std::vector<std::string>& targets, RecordOptions& options) {
  if (targets.size() == 1 && targets[0] == "-") {
    options.from_stdin = true;
    return;
  }
  client::ToolTarget split;
  try {
    split = client::split_tool_target(targets);
  } catch (const std::invalid_argument& e) {
    throw UsageError(e.what());
  }
  options.server = split.server;
  if (split.rest.empty()) throw UsageError("record: name at least one device (laser:0), or - for stdin");
  for (const auto& name : split.rest) {
    const auto device = protocol::parse_device_address(name);
    if (!device) throw UsageError("record: '" + name + "' is not a device (laser:0, position, 6:1)");
    options.devices.push_back(*device);
  }
}

int run_record(const RecordOptions& options, std::istream& in, std::ostream& out, std::ostream& err,
               const std::function<bool()>& stop_requested) {
  const std::vector<std::string> inputs = options.from_stdin ? std::vector<std::string>{"-"}
                                                             : std::vector<std::string>{};
  // Before connecting: writing over the input is a usage error (exit 2).
  tools::refuse_output_over_inputs(options.output, inputs);
  Recording output(options, out, inputs);
  try {
    Limits limits(options, stop_requested);
    if (options.from_stdin) record_from_stdin(options, in, output, err, limits);
    else record_from_server(options, output, err, limits);
    output.finish();
    return kExitOk;
  } catch (const std::exception& e) {
    err << "player-log: " << e.what() << "\n";
    // What was recorded before the failure stays in the file (the Recording's
    // OutputFile ends it as written).
    return kExitFailure;
  }
}

}  // namespace playerkit::plog
