#include "log_convert.hpp"

#include <algorithm>
#include <fstream>
#include <map>
#include <stdexcept>
#include <variant>

#include "formatters.hpp"
#include "log/carmen_log_writer.hpp"
#include "log/log_clock_reader.hpp"
#include "log/log_conversion.hpp"
#include "log/log_input.hpp"
#include "log/log_line.hpp"
#include "log/text_log_reader.hpp"
#include "log/text_log_writer.hpp"
#include "message_decoder.hpp"
#include "message_source.hpp"
#include "text/printable.hpp"

namespace playerkit::plog {
namespace {

bool wanted(const std::vector<protocol::DeviceAddress>& devices, protocol::DeviceAddress device) {
  return devices.empty() || std::find(devices.begin(), devices.end(), device) != devices.end();
}

void report_malformed(const SourceStats& stats, std::ostream& err) {
  if (stats.malformed == 0) return;
  for (const auto& text : stats.malformed_texts) err << text << "\n";
  err << "player-log: " << stats.malformed << " malformed line(s) skipped\n";
}

ConvertTarget default_target(const ConvertOptions& options, LogFormat input_format) {
  if (options.output.ends_with(".jsonl")) return ConvertTarget::kJsonl;
  if (options.output.ends_with(".csv")) return ConvertTarget::kCsv;
  return input_format == LogFormat::kPlayer ? ConvertTarget::kCarmen : ConvertTarget::kPlayer;
}

}  // namespace

ConvertTarget parse_convert_target(const std::string& text) {
  if (text == "player") return ConvertTarget::kPlayer;
  if (text == "carmen") return ConvertTarget::kCarmen;
  if (text == "jsonl") return ConvertTarget::kJsonl;
  if (text == "csv") return ConvertTarget::kCsv;
  throw UsageError("--to: '" + text + "' is not player, carmen, jsonl or csv");
}

void run_convert(const ConvertOptions& options, std::ostream& out, std::ostream& err, Progress& progress) {
  const auto target = options.to.value_or(default_target(options, detect_log_format(options.input)));
  OutputFile output(options.output, out, {options.input});
  auto& stream = output.stream();

  log::PlayerToCarmen to_carmen;
  tools::MessageDecoder decoder("player-log", options.si, err);
  std::unique_ptr<tools::Formatter> formatter;
  std::optional<protocol::DeviceAddress> csv_device;
  if (target == ConvertTarget::kPlayer) stream << log::log_file_header();
  if (target == ConvertTarget::kCarmen) stream << log::carmen_log_header();
  if (target == ConvertTarget::kJsonl) formatter = tools::make_json_formatter(stream, {});
  std::size_t not_carmen = 0;

  const auto write_records = [&] {
    for (const auto& record : to_carmen.take_records()) {
      if (const auto* odometry = std::get_if<log::CarmenOdometry>(&record)) stream << log::format_odom(*odometry);
      else stream << log::format_flaser(std::get<log::CarmenLaser>(record));
    }
  };

  const auto stats = for_each_message(options.input, options.strict, [&](const SourceMessage& source) {
    const auto& message = source.message;
    if (!wanted(options.devices, message.device())) return;
    progress.tick();
    switch (target) {
      case ConvertTarget::kPlayer:
        stream << log::format_data_line(message, source.host, source.port);
        break;
      case ConvertTarget::kCarmen:
        if (!to_carmen.feed(message, source.host)) ++not_carmen;
        write_records();
        break;
      case ConvertTarget::kJsonl:
      case ConvertTarget::kCsv: {
        if (target == ConvertTarget::kCsv) {
          if (!csv_device) {
            csv_device = message.device();
            formatter = tools::make_csv_formatter({{*csv_device, &stream}}, {});
          } else if (*csv_device != message.device()) {
            throw UsageError("csv holds one device's table, and the log has " + protocol::to_string(*csv_device) +
                             " and " + protocol::to_string(message.device()) +
                             ": choose one with --devices, or use --to jsonl");
          }
        }
        const auto json = decoder.to_json(message);
        formatter->data({message, json, message.time().seconds()});
        break;
      }
    }
    output.check();
  });
  to_carmen.finish();
  write_records();
  output.commit();
  report_malformed(stats, err);
  if (target == ConvertTarget::kCarmen) {
    if (not_carmen > 0) {
      err << "player-log: " << not_carmen
          << " message(s) of devices other than laser:0, position:0 and truth:0 have no CARMEN record; not written\n";
    }
    if (to_carmen.layout_mismatches() > 0) {
      err << "player-log: warning: " << to_carmen.layout_mismatches()
          << " scan(s) have a beam layout FLASER readers will not guess from the beam count; their angles are lost\n";
    }
  }
}

void run_cut(const CutOptions& options, std::ostream& out, std::ostream& err, Progress& progress) {
  if (detect_log_format(options.input) != LogFormat::kPlayer) {
    throw std::runtime_error(options.input + " is a CARMEN log; cut reads Player logs (convert it first)");
  }
  // The window is measured on the log's clock: file order on a synthetic
  // clock when its times are unusable (warned once on stderr), as every
  // reader sees it. Lines are still copied as they are.
  const auto clock = log::audit_log_times(options.input);
  std::size_t ordinal = 0;  // sync and data lines so far: the clock's ordinals
  auto in = log::open_log_input(options.input);
  OutputFile output(options.output, out, {options.input});
  auto& stream = output.stream();
  auto version = log::LogFormatVersion::k0_0_0;
  std::optional<double> first_time;
  std::size_t malformed = 0;
  std::vector<std::string> kept;
  std::string text;
  bool too_long = false;
  for (int number = 1; log::read_log_line(*in, text, too_long); ++number) {
    log::LogLine line;
    try {
      if (too_long) throw log::too_long_line_error(options.input, number);
      line = log::parse_log_line(text, options.input, number, version);
    } catch (const log::LogParseError& e) {
      if (options.strict) throw;
      if (kept.size() < 10) kept.emplace_back(e.what());
      ++malformed;
      continue;
    }
    if (const auto* header = std::get_if<log::HeaderLine>(&line)) {
      if (header->name == "File version") {
        const auto parsed = log::parse_format_version(header->value);
        if (!parsed) {
          throw log::LogParseError(options.input, number, header->value_column,
                                   "unknown file version '" + text::excerpt(header->value) + "'");
        }
        version = *parsed;
      }
      stream << text << "\n";
      continue;
    }
    double time = 0;
    if (const auto* data = std::get_if<log::DataLine>(&line)) {
      time = clock->time_of(ordinal++, data->server_time.seconds());
      if (!first_time) first_time = time;
      if (!options.devices.empty() && (!data->device || !wanted(options.devices, *data->device))) continue;
    } else if (const auto* sync = std::get_if<log::SyncLine>(&line)) {
      time = clock->time_of(ordinal++, sync->server_time.seconds());
      if (!first_time) first_time = time;
    } else {
      continue;  // blank and comment lines
    }
    progress.tick();
    const double relative = time - *first_time;
    if (options.start && relative < *options.start) continue;
    if (options.end && relative > *options.end) continue;
    stream << text << "\n";
    output.check();
  }
  if (const auto error = in->error()) throw std::runtime_error(options.input + ": " + *error);
  output.commit();
  for (const auto& message : kept) err << message << "\n";
  if (malformed > 0) err << "player-log: " << malformed << " malformed line(s) skipped\n";
}

}  // namespace playerkit::plog
