#include "log/log_input.hpp"

#include <array>
#include <cerrno>
#include <cstring>
#include <stdexcept>
#include <streambuf>

#include <zlib.h>

namespace playerkit::log {

namespace {

// zlib's gzread passes plain files through unchanged, so one buffer serves both.
class GzipReadBuffer : public std::streambuf {
 public:
  explicit GzipReadBuffer(gzFile file) : file_(file) {}
  ~GzipReadBuffer() override { gzclose(file_); }
  GzipReadBuffer(const GzipReadBuffer&) = delete;
  GzipReadBuffer& operator=(const GzipReadBuffer&) = delete;

  [[nodiscard]] const std::optional<std::string>& error() const { return error_; }

 protected:
  int_type underflow() override {
    if (gptr() < egptr()) return traits_type::to_int_type(*gptr());
    if (error_) return traits_type::eof();
    const int read = gzread(file_, block_.data(), static_cast<unsigned>(block_.size()));
    if (read < 0) {
      int code = 0;
      const char* message = gzerror(file_, &code);
      error_ = code == Z_ERRNO ? std::string(std::strerror(errno)) : std::string(message);
      return traits_type::eof();
    }
    if (read == 0) {
      // gzread reports a .gz file cut short as a clean end; gzerror knows better.
      int code = 0;
      const char* message = gzerror(file_, &code);
      if (code != Z_OK && code != Z_STREAM_END) error_ = message;
      return traits_type::eof();
    }
    setg(block_.data(), block_.data(), block_.data() + read);
    return traits_type::to_int_type(*gptr());
  }

 private:
  gzFile file_;
  std::array<char, 64 * 1024> block_{};
  std::optional<std::string> error_;
};

class GzipLogInput final : public LogInput {
 public:
  explicit GzipLogInput(gzFile file) : LogInput(nullptr), buffer_(file) { rdbuf(&buffer_); }
  [[nodiscard]] std::optional<std::string> error() const override { return buffer_.error(); }

 private:
  GzipReadBuffer buffer_;
};

}  // namespace

std::unique_ptr<LogInput> open_log_input(const std::filesystem::path& path) {
  if (std::filesystem::is_directory(path)) {
    throw std::runtime_error("cannot open " + path.string() + ": it is a directory");
  }
  errno = 0;
  gzFile file = gzopen(path.c_str(), "rb");
  if (file == nullptr) {
    const std::string reason = errno != 0 ? std::strerror(errno) : "out of memory";
    throw std::runtime_error("cannot open " + path.string() + ": " + reason);
  }
  gzbuffer(file, 128 * 1024);
  return std::make_unique<GzipLogInput>(file);
}

}  // namespace playerkit::log
