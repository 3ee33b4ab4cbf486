#include "text/line_reader.hpp"

#include <limits>
#include <streambuf>

#include "text/printable.hpp"

namespace playerkit::text {

LineTooLongError::LineTooLongError(std::string_view name, long long number, std::size_t max_bytes)
    : std::runtime_error(printable(name) + ":" + std::to_string(number) + ": line longer than " +
                         std::to_string(max_bytes) + " bytes"),
      line_number_(number) {}

bool read_line(std::istream& in, std::string& line, std::string_view name, long long number,
               std::size_t max_bytes) {
  line.clear();
  const std::istream::sentry sentry(in, true);
  if (!sentry) return false;
  std::streambuf& buffer = *in.rdbuf();
  using Traits = std::streambuf::traits_type;
  std::ios::iostate state = std::ios::goodbit;
  bool extracted = false;
  for (;;) {
    const Traits::int_type c = buffer.sbumpc();
    if (Traits::eq_int_type(c, Traits::eof())) {
      state |= std::ios::eofbit;
      if (!extracted) state |= std::ios::failbit;
      break;
    }
    extracted = true;
    if (Traits::to_char_type(c) == '\n') break;
    if (line.size() == max_bytes) {
      in.ignore(std::numeric_limits<std::streamsize>::max(), '\n');
      throw LineTooLongError(name, number, max_bytes);
    }
    line.push_back(Traits::to_char_type(c));
  }
  in.setstate(state);
  return extracted;
}

}  // namespace playerkit::text
