#pragma once
// std::getline with a cap. A text reader that takes lines of any length lets
// a small input cost unbounded memory and time: 815 KB of gzip unpack to one
// 800 MB line. Every reader of line-oriented input (logs, CSV, JSON lines)
// reads through here; a line over the cap is an error that names the file and
// line and quotes none of it. Lenient readers may skip it and read on.
//
//   std::string line;
//   for (int number = 1; text::read_line(in, line, "run.log", number); ++number) { ... }

#include <cstddef>
#include <istream>
#include <stdexcept>
#include <string>
#include <string_view>

namespace playerkit::text {

// The longest line a line reader takes, in bytes, its '\n' not counted. The
// longest lines of real input are a few KB: 2.2 KB in the Radish CARMEN logs
// (a 361-beam scan with its poses), about 10 KB for a Player laser line with
// 361 ranges and intensities, some 25 KB for the largest messages the Player
// log writer can produce (localize with 100 hypotheses). 1 MiB is 40 times
// that, and small enough that a hostile line costs little.
inline constexpr std::size_t kMaxLineBytes = std::size_t{1} << 20;

// what(): "name:number: line longer than N bytes".
class LineTooLongError : public std::runtime_error {
 public:
  LineTooLongError(std::string_view name, long long number, std::size_t max_bytes);
  [[nodiscard]] long long line_number() const { return line_number_; }

 private:
  long long line_number_;
};

// Reads the next line of `in` into `line` without its '\n', as std::getline
// does (the same stream flags: eof when the last line has no '\n', fail when
// there was no line). Throws LineTooLongError, naming `name` and `number`
// (the number of the line being read), when the line has more than max_bytes
// bytes: the rest of that line is read and dropped first (memory stays at the
// cap), so the next call reads the line after it. `line` holds its start.
bool read_line(std::istream& in, std::string& line, std::string_view name, long long number,
               std::size_t max_bytes = kMaxLineBytes);

}  // namespace playerkit::text
