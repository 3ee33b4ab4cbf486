#pragma once
// Reads a CARMEN log record by record, in constant memory (one line at a time;
// pass open_log_input(path) for plain or gzip files).
//
//   auto in = log::open_log_input(path);
//   log::CarmenLogReader reader(*in, path.string());
//   while (auto record = reader.next()) {
//     if (auto* laser = std::get_if<log::CarmenLaser>(&*record)) ...
//   }
//   for (auto& message : reader.malformed_messages()) std::cerr << message << '\n';
//
// Lines of unknown records (NEFF, VERTEX2, SYNC, ...) are skipped and counted
// by keyword. A malformed line of a known record is skipped and counted, its
// "file:line:col: message" kept (the first few); with strict it throws
// LogParseError instead (the reader keeps its place: the next call reads on).

#include <cstddef>
#include <istream>
#include <map>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "log/carmen_log.hpp"
#include "log/log_clock.hpp"
#include "log/log_parse_error.hpp"

namespace playerkit::log {

struct CarmenReadOptions {
  bool strict = false;  // a malformed line throws instead of being skipped
  std::size_t kept_messages = 10;  // how many malformed-line messages to keep
  // The log's clock (log_clock_reader.hpp: audit_log_times): records whose
  // time it replaces get the replacement as ipc and logger timestamp.
  std::shared_ptr<const LogClock> clock = nullptr;
};

class CarmenLogReader {
 public:
  CarmenLogReader(std::istream& in, std::string file, CarmenReadOptions options = {});

  // The next record, or nullopt at the end of the stream.
  std::optional<CarmenRecord> next();

  // The number of the line read last (1-based; 0 before the first).
  int line_number() const { return line_number_; }
  // Blank and '#' lines.
  std::size_t comment_lines() const { return comment_lines_; }
  // Unknown lines by keyword. At most kMaxKeywords different keywords are
  // named (memory stays bounded on garbage input); the rest count under "...".
  const std::map<std::string, std::size_t>& unknown_keywords() const { return unknown_keywords_; }
  std::size_t unknown_lines() const { return unknown_lines_; }
  std::size_t malformed_lines() const { return malformed_lines_; }
  // Records but PARAM returned so far (the LogClock's ordinals).
  std::size_t timed_records() const { return timed_records_; }
  // The first kept_messages "file:line:col: message" texts of malformed lines.
  const std::vector<std::string>& malformed_messages() const { return malformed_messages_; }

  static constexpr std::size_t kMaxKeywords = 64;

 private:
  void count_unknown(const std::string& keyword);
  void retime(CarmenRecord& record, std::size_t ordinal) const;

  std::istream& in_;
  std::string file_;
  CarmenReadOptions options_;
  std::string line_;
  int line_number_ = 0;
  std::size_t comment_lines_ = 0;
  std::size_t unknown_lines_ = 0;
  std::size_t malformed_lines_ = 0;
  std::size_t timed_records_ = 0;
  std::map<std::string, std::size_t> unknown_keywords_;
  std::vector<std::string> malformed_messages_;
};

}  // namespace playerkit::log
