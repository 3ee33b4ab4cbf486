#include "text/line_reader.hpp"

#include <limits>
#include <streambuf>

#include "text/printable.hpp"

namespace playerkit::text {

LineTooLongError::LineTooLongError(std::string_view name, long long number, std::size_t max_bytes)
    : std::runtime_error(printable(name) + ":" + std::to_string(number) + ": line longer than " +
                         std::to_string(max_bytes) + " bytes"),
      line_number_(number) {}

// Chunk by chunk through istream::getline, which finds the '\n' in the
// stream's buffer with a memchr rather than a call per character.
bool read_line(std::istream& in, std::string& line, std::string_view name, long long number,
               std::size_t max_bytes) {
  constexpr std::streamsize kChunk = 4096;
  line.clear();
  bool extracted = false;
  for (;;) {
    char chunk[kChunk];
    in.getline(chunk, kChunk);
    const std::streamsize got = in.gcount();
    extracted = extracted || got > 0;
    // Filled without reaching the end of the line: getline says fail.
    const bool filled = in.fail() && !in.eof() && got == kChunk - 1;
    const bool newline = !in.fail() && !in.eof();  // the '\n' was counted, not stored
    const std::size_t stored = static_cast<std::size_t>(got) - (newline ? 1 : 0);
    if (line.size() + stored > max_bytes) {
      line.append(chunk, max_bytes - line.size());
      if (filled) {
        in.clear(in.rdstate() & ~std::ios::failbit);
        in.ignore(std::numeric_limits<std::streamsize>::max(), '\n');
      }
      throw LineTooLongError(name, number, max_bytes);
    }
    line.append(chunk, stored);
    if (!filled) break;
    in.clear(in.rdstate() & ~std::ios::failbit);
  }
  // As std::getline: fail only when there was no line at all.
  if (extracted) in.clear(in.rdstate() & ~std::ios::failbit);
  return extracted;
}

}  // namespace playerkit::text
