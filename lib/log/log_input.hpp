#pragma once
// Opens a log for reading, gzip-compressed or plain (told by its first bytes,
// not its name), as a std::istream read in 64 KiB blocks: constant memory
// whatever the file's size. Concatenated gzip members are read in turn.
//
//   auto in = log::open_log_input("intel.log.gz");
//   log::TextLogReader reader(*in, "intel.log.gz");
//   ...
//   if (const auto error = in->error()) throw std::runtime_error(path + ": " + *error);
//
// Damaged gzip data ends the stream early with error() set, saying where,
// without the file's name (callers add it): "gzip data cut short: the file
// ends at byte 30000, in line 413" or "corrupt gzip data at byte 1234, in
// line 97: invalid block type". What comes before is delivered in whole lines
// only: the line the damage is in is left out, so readers see no torn line.

#include <filesystem>
#include <istream>
#include <memory>
#include <optional>
#include <string>

namespace playerkit::log {

class LogInput : public std::istream {
 public:
  // The decompression (or read) error that ended the stream early, if any
  // (a truncated .gz file reads up to the damage, then ends with this set).
  [[nodiscard]] virtual std::optional<std::string> error() const = 0;

 protected:
  using std::istream::istream;
};

// Throws std::runtime_error "cannot open FILE: reason".
std::unique_ptr<LogInput> open_log_input(const std::filesystem::path& path);

}  // namespace playerkit::log
