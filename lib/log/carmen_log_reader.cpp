#include "log/carmen_log_reader.hpp"

#include <utility>
#include <variant>

#include "log/carmen_log_parser.hpp"
#include "log/log_line.hpp"

namespace playerkit::log {

CarmenLogReader::CarmenLogReader(std::istream& in, std::string file, CarmenReadOptions options)
    : in_(in), file_(std::move(file)), options_(options) {}

void CarmenLogReader::count_unknown(const std::string& keyword) {
  ++unknown_lines_;
  if (auto found = unknown_keywords_.find(keyword); found != unknown_keywords_.end()) {
    ++found->second;
  } else if (unknown_keywords_.size() < kMaxKeywords) {
    unknown_keywords_.emplace(keyword, 1);
  } else {
    ++unknown_keywords_["..."];
  }
}

void CarmenLogReader::retime(CarmenRecord& record, std::size_t ordinal) const {
  if (!options_.clock) return;
  const auto time = options_.clock->replacement(ordinal);
  if (!time) return;
  std::visit(
      [&](auto& r) {
        r.stamp.ipc_timestamp = *time;
        r.stamp.logger_timestamp = *time;
      },
      record);
}

std::optional<CarmenRecord> CarmenLogReader::next() {
  bool too_long = false;
  while (read_log_line(in_, line_, too_long)) {
    ++line_number_;
    CarmenLine parsed;
    try {
      if (too_long) throw too_long_line_error(file_, line_number_);
      parsed = parse_carmen_line(line_, file_, line_number_);
    } catch (const LogParseError& error) {
      ++malformed_lines_;
      if (malformed_messages_.size() < options_.kept_messages) {
        malformed_messages_.emplace_back(error.what());
      }
      if (options_.strict) throw;
      continue;
    }
    if (auto* record = std::get_if<CarmenRecord>(&parsed)) {
      if (!std::holds_alternative<CarmenParam>(*record)) retime(*record, timed_records_++);
      return std::move(*record);
    }
    if (auto* unknown = std::get_if<CarmenUnknownLine>(&parsed)) {
      count_unknown(unknown->keyword);
    } else {
      ++comment_lines_;
    }
  }
  return std::nullopt;
}

}  // namespace playerkit::log
