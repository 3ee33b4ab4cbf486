#pragma once
// Reads Player 1.5 text log lines (logfile-format.md) back into messages: the
// inverse of text_log_writer.hpp.
//
//   std::ifstream in(path);
//   log::TextLogReader reader(in, path);
//   while (auto line = reader.next()) {
//     if (auto* data = std::get_if<log::DataLine>(&*line)) deliver(data->message);
//     else pace();  // a SyncLine
//   }
//
// The file holds SI units with few decimals; reading converts them to wire
// units by rounding to the nearest unit (1.5's readlog truncated, so 4.35 m came
// back as 4349 mm; here it is 4350). What the text does not hold cannot come back:
//   * times are in milliseconds (usec comes back as a multiple of 1000);
//   * laser: range_res is not written, ranges come back in mm with range_res 1
//     (10 or 100 only when mm would not fit 16 bits); angles come back exactly,
//     because 4 decimals of a radian are finer than 0.005 deg;
//   * position3d: angles have 4 decimals of a radian, about 10 arc-seconds;
//   * gps: time_usec is not written (comes back 0); the time is written as
//     time_sec * (1 + 1e-6) (1.5's quirk), which is undone here (1.5's readlog
//     kept the integer part, so its times came back off by time_sec * 1e-6 s);
//   * fiducial: the uncertainties are not written (come back 0);
//   * the extension interfaces (wifi, sonar, ir, power, bumper, localize, ptz,
//     blobfinder; lib/log/README.md) come back as written;
//   * every other interface: no fields at all (empty payload).
// Times with 3 or 6 (or any number of) decimals are read; 6 keep microseconds.
// Files of version 0.0.0 (Player 1.5) and 0.2.0 (1.6.5, spec §6) are read; a
// file without a version line is read as 0.0.0.
//
// By default a malformed line is skipped and counted (its "file:line:col:
// message" kept for the first few); TextLogReaderOptions{.strict = true}
// makes it throw instead.

#include <cstdint>
#include <istream>
#include <memory>
#include <optional>
#include <string>
#include <string_view>
#include <variant>
#include <vector>

#include "log/log_clock.hpp"
#include "log/log_parse_error.hpp"
#include "log/text_log_format.hpp"
#include "protocol/device_address.hpp"
#include "protocol/message.hpp"

namespace playerkit::log {

// A blank line, or a comment (first token exactly "#", as 1.5's readlog has it).
struct SkippedLine {};

// "## File version 0.0.0 " gives {"File version", "0.0.0"}.
struct HeaderLine {
  std::string name;
  std::string value;
  int value_column = 0;  // 1-based, for errors about the value
};

// "<time> <host> <port> sync 00 <time> "
struct SyncLine {
  protocol::Timestamp server_time;  // token 0
  std::string host;
  std::uint16_t port = 0;
  protocol::Timestamp data_time;  // token 5; 1.5 writes the same time as token 0
};

struct DataLine {
  protocol::Timestamp server_time;  // token 0
  std::string host;
  std::uint16_t port = 0;  // the logging server's port, not a device's
  std::string interface_name;  // token 3 as written
  std::uint16_t index = 0;
  // nullopt when interface_name is not a Player 1.5 interface (1.5's readlog
  // warned and skipped such lines); the message then has interface code 0.
  std::optional<protocol::DeviceAddress> device;
  protocol::Timestamp data_time;  // token 5
  // A data message: header time = server_time, timestamp = data_time, size =
  // payload size; payload = the interface's wire struct, or empty when the line
  // has no fields (other interfaces, unknown names, prefix-only lines).
  protocol::Message message;
};

using LogLine = std::variant<SkippedLine, HeaderLine, SyncLine, DataLine>;

// Parses one line (a trailing "\n" or "\r\n" is allowed). `file` and
// `line_number` only go into errors. Throws LogParseError naming the column of
// the offending field.
LogLine parse_log_line(std::string_view text, std::string_view file, int line_number);
// The same for a file of the given version (the form above reads 0.0.0).
LogLine parse_log_line(std::string_view text, std::string_view file, int line_number,
                       LogFormatVersion version);

struct TextLogReaderOptions {
  // true: a malformed line throws LogParseError. false: it is skipped and counted.
  bool strict = false;
  // How many skipped lines keep their error text (the count goes on past it).
  std::size_t kept_errors = 10;
  // The log's clock (log_clock_reader.hpp: audit_log_times): lines whose time
  // it replaces get the replacement as token 0 and data time (and in the
  // message's header).
  std::shared_ptr<const LogClock> clock = nullptr;
};

// A whole log, line by line, in constant memory. The header's file version
// chooses how lines are read; an unknown version throws LogParseError (strict
// or not: every line after it would be misread).
class TextLogReader {
 public:
  TextLogReader(std::istream& in, std::string file, TextLogReaderOptions options = {});

  // The next sync or data line, past blank, comment and header lines (and,
  // unless strict, malformed lines); nullopt at the end. When strict, throws
  // LogParseError and keeps its place: the next call reads on.
  std::optional<std::variant<SyncLine, DataLine>> next();

  // Lines skipped as malformed so far (always 0 when strict).
  std::size_t malformed_count() const { return malformed_count_; }
  // "file:line:col: message" of the first kept_errors of them.
  const std::vector<std::string>& malformed_lines() const { return malformed_lines_; }
  // From the header's file version line; 0.0.0 until one is read.
  LogFormatVersion format_version() const { return format_version_; }

  // From the header lines, once read; nullopt when the file has none.
  const std::optional<std::string>& player_version() const { return player_version_; }
  const std::optional<std::string>& file_version() const { return file_version_; }
  // The number of the line read last (1-based; 0 before the first).
  int line_number() const { return line_number_; }
  // Sync and data lines returned so far (the LogClock's ordinals).
  std::size_t timed_lines() const { return timed_lines_; }

 private:
  void take_header(const HeaderLine& header);
  void retime(std::variant<SyncLine, DataLine>& line, std::size_t ordinal) const;

  std::istream& in_;
  std::string file_;
  TextLogReaderOptions options_;
  int line_number_ = 0;
  std::size_t timed_lines_ = 0;
  LogFormatVersion format_version_ = LogFormatVersion::k0_0_0;
  std::size_t malformed_count_ = 0;
  std::vector<std::string> malformed_lines_;
  std::optional<std::string> player_version_;
  std::optional<std::string> file_version_;
};

}  // namespace playerkit::log
