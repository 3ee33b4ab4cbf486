#pragma once
// What the fuzz targets share: reading control bytes off the front of an
// input, and one scratch directory per process for parsers that resolve
// file names (includes, bitmaps, images), so that no input can make them
// read a file of the machine.

#include <cstddef>
#include <cstdint>
#include <filesystem>
#include <span>
#include <string>
#include <string_view>
#include <system_error>
#include <unistd.h>

namespace playerkit::fuzz {

// Bytes taken from the front of an input; past its end, zeros. A target
// takes its choices (chunk sizes, which codec) first and hands the rest on,
// so a seed is a few choice bytes followed by a real file or stream.
class ByteSource {
 public:
  ByteSource(const std::uint8_t* data, std::size_t size) : bytes_(data, size) {}

  std::uint8_t byte() {
    if (bytes_.empty()) return 0;
    const std::uint8_t b = bytes_.front();
    bytes_ = bytes_.subspan(1);
    return b;
  }
  std::span<const std::uint8_t> take(std::size_t count) {
    const std::size_t n = count < bytes_.size() ? count : bytes_.size();
    const auto taken = bytes_.first(n);
    bytes_ = bytes_.subspan(n);
    return taken;
  }
  std::span<const std::uint8_t> rest() const { return bytes_; }
  bool empty() const { return bytes_.empty(); }

 private:
  std::span<const std::uint8_t> bytes_;
};

inline std::string_view as_text(std::span<const std::uint8_t> bytes) {
  return {reinterpret_cast<const char*>(bytes.data()), bytes.size()};
}

// An empty directory of this process under $TMPDIR (scripts/fuzz points
// TMPDIR into build-fuzz), removed when the process ends normally.
class ScratchDirectory {
 public:
  ScratchDirectory() {
    path_ = std::filesystem::temp_directory_path() / ("playerkit-fuzz-" + std::to_string(::getpid()));
    std::filesystem::create_directories(path_);
  }
  ~ScratchDirectory() {
    std::error_code ignored;
    std::filesystem::remove_all(path_, ignored);
  }
  ScratchDirectory(const ScratchDirectory&) = delete;
  ScratchDirectory& operator=(const ScratchDirectory&) = delete;
  const std::filesystem::path& path() const { return path_; }

 private:
  std::filesystem::path path_;
};

inline const std::filesystem::path& scratch_directory() {
  static const ScratchDirectory directory;
  return directory.path();
}

// The text with every '/' made '_': a name in it can then only be a file of
// the scratch directory (or the directory itself, or its parent, which the
// readers refuse as directories), never one elsewhere on the machine.
inline std::string without_slashes(std::string_view text) {
  std::string out(text);
  for (char& c : out) {
    if (c == '/') c = '_';
  }
  return out;
}

}  // namespace playerkit::fuzz
