// A log file's bytes through log::open_log_input, as every tool opens a log:
// gzip (one member or several, then perhaps bytes that are no member) or
// plain, told by the first two bytes. Checked against zlib driven directly
// over the same bytes: when that decodes them, the reader must deliver
// exactly its text and report no error; when the reader reports no error,
// zlib must agree. A damaged file delivers whole lines only (a line longer
// than the reader's 64 KiB block may go out in parts before the damage).

#include <zlib.h>

#include <array>
#include <fstream>
#include <iterator>
#include <optional>
#include <stdexcept>
#include <string>

#include "fuzz_support.hpp"
#include "fuzz_targets.hpp"
#include "log/log_input.hpp"

namespace playerkit::fuzz {
namespace log_input_detail {

constexpr std::size_t kReaderBlock = 64 * 1024;

bool starts_gzip(std::span<const std::uint8_t> bytes) {
  return bytes.size() >= 2 && bytes[0] == 0x1f && bytes[1] == 0x8b;
}

// The text zlib decodes from every gzip member in a row; nullopt if a member
// is damaged or cut short.
std::optional<std::string> decoded_by_zlib(std::span<const std::uint8_t> bytes) {
  if (!starts_gzip(bytes)) return std::string(as_text(bytes));
  std::string text;
  std::array<char, 16384> out{};
  while (starts_gzip(bytes)) {
    z_stream z{};
    if (inflateInit2(&z, 15 + 16) != Z_OK) throw std::bad_alloc();
    z.next_in = const_cast<Bytef*>(bytes.data());
    z.avail_in = static_cast<uInt>(bytes.size());
    int result = Z_OK;
    while (result == Z_OK) {
      z.next_out = reinterpret_cast<Bytef*>(out.data());
      z.avail_out = static_cast<uInt>(out.size());
      result = inflate(&z, Z_NO_FLUSH);
      text.append(out.data(), out.size() - z.avail_out);
    }
    const std::size_t consumed = bytes.size() - z.avail_in;
    inflateEnd(&z);
    if (result != Z_STREAM_END) return std::nullopt;
    bytes = bytes.subspan(consumed);
  }
  return text;
}

}  // namespace log_input_detail

int log_input(const std::uint8_t* data, std::size_t size) {
  using namespace log_input_detail;
  const auto path = scratch_directory() / "input.log";
  {
    std::ofstream file(path, std::ios::binary | std::ios::trunc);
    file.write(reinterpret_cast<const char*>(data), static_cast<std::streamsize>(size));
  }
  std::unique_ptr<log::LogInput> in;
  try {
    in = log::open_log_input(path);
  } catch (const std::runtime_error& error) {
    invariant_failed("log_input", (std::string("a readable file was refused: ") + error.what()).c_str());
  }
  const std::string text((std::istreambuf_iterator<char>(*in)), std::istreambuf_iterator<char>());
  const auto error = in->error();
  const auto expected = decoded_by_zlib({data, size});

  if (expected && (error || text != *expected)) {
    invariant_failed("log_input", error ? "zlib decodes the file but the reader reports damage"
                                        : "the reader's text differs from zlib's");
  }
  if (!expected && !error) invariant_failed("log_input", "damaged gzip data read without an error");
  if (error && !text.empty() && text.back() != '\n') {
    const auto last_newline = text.rfind('\n');
    const std::size_t torn = last_newline == std::string::npos ? text.size() : text.size() - last_newline - 1;
    if (torn < kReaderBlock) invariant_failed("log_input", "a damaged file delivered a torn line");
  }
  return 0;
}

}  // namespace playerkit::fuzz
