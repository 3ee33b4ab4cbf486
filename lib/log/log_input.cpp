#include "log/log_input.hpp"

#include <fcntl.h>
#include <unistd.h>

#include <algorithm>
#include <array>
#include <cerrno>
#include <cstring>
#include <stdexcept>
#include <streambuf>

#include <zlib.h>

namespace playerkit::log {

namespace {

constexpr std::size_t kBlockSize = 64 * 1024;
// inflateInit2's window bits: 15 (32 KiB) plus 16, gzip only (no zlib or raw deflate).
constexpr int kGzipWindowBits = 15 + 16;

bool starts_gzip(const char* bytes, std::size_t count) {
  return count >= 2 && static_cast<unsigned char>(bytes[0]) == 0x1f && static_cast<unsigned char>(bytes[1]) == 0x8b;
}

// A log's bytes, plain or gzip (told by the magic bytes), read from a file
// descriptor it owns. zlib's inflate is driven here rather than gzread so
// that damage is located: the byte of the file where decoding failed and
// the line of the text it was in. A gzip stream that fails delivers whole
// lines only (the broken line's start is held back), so readers see no torn
// line; concatenated gzip members are read in turn, and bytes after the last
// member that are not a gzip member are ignored, as gzip -d does.
class LogReadBuffer : public std::streambuf {
 public:
  explicit LogReadBuffer(int fd) : fd_(fd) {
    fill_raw();
    gzip_ = starts_gzip(raw_.data() + raw_begin_, raw_end_ - raw_begin_);
    if (gzip_ && inflateInit2(&z_, kGzipWindowBits) != Z_OK) {
      ::close(fd_);
      throw std::runtime_error("out of memory for gzip decoding");
    }
  }
  ~LogReadBuffer() override {
    if (gzip_) inflateEnd(&z_);
    ::close(fd_);
  }
  LogReadBuffer(const LogReadBuffer&) = delete;
  LogReadBuffer& operator=(const LogReadBuffer&) = delete;

  [[nodiscard]] const std::optional<std::string>& error() const { return error_; }

 protected:
  int_type underflow() override {
    if (gptr() < egptr()) return traits_type::to_int_type(*gptr());
    const bool more = gzip_ ? next_decoded_block() : next_plain_block();
    return more ? traits_type::to_int_type(*gptr()) : traits_type::eof();
  }

 private:
  // Reads more of the file behind what is still unread in raw_.
  void fill_raw() {
    if (raw_eof_ || error_) return;
    if (raw_begin_ > 0) {
      std::memmove(raw_.data(), raw_.data() + raw_begin_, raw_end_ - raw_begin_);
      raw_end_ -= raw_begin_;
      raw_begin_ = 0;
    }
    while (raw_end_ < raw_.size()) {
      const ssize_t count = ::read(fd_, raw_.data() + raw_end_, raw_.size() - raw_end_);
      if (count < 0 && errno == EINTR) continue;
      if (count < 0) {
        fail(std::string("read error at byte ") + std::to_string(file_offset_ + raw_end_) + ": " +
             std::strerror(errno));
        return;
      }
      if (count == 0) raw_eof_ = true;
      raw_end_ += static_cast<std::size_t>(count);
      break;
    }
  }

  bool next_plain_block() {
    if (raw_begin_ == raw_end_) fill_raw();
    if (raw_begin_ == raw_end_) return false;
    char* begin = raw_.data() + raw_begin_;
    char* end = raw_.data() + raw_end_;
    file_offset_ += raw_end_ - raw_begin_;
    raw_begin_ = raw_end_;
    setg(begin, begin, end);
    return true;
  }

  bool next_decoded_block() {
    // The start of a line held back from the last block comes first.
    std::memmove(block_.data(), block_.data() + held_begin_, held_end_ - held_begin_);
    std::size_t filled = held_end_ - held_begin_;
    held_begin_ = held_end_ = 0;
    while (filled < block_.size() && !error_ && !ended_) {
      if (raw_begin_ == raw_end_) fill_raw();
      if (error_) break;
      if (between_members_) {
        if (raw_end_ - raw_begin_ < 2 && !raw_eof_) {
          fill_raw();
          continue;
        }
        if (!starts_gzip(raw_.data() + raw_begin_, raw_end_ - raw_begin_)) {
          ended_ = true;  // the end, or trailing bytes that are no gzip member
          break;
        }
        inflateReset(&z_);
        between_members_ = false;
      }
      z_.next_in = reinterpret_cast<Bytef*>(raw_.data() + raw_begin_);
      z_.avail_in = static_cast<uInt>(raw_end_ - raw_begin_);
      z_.next_out = reinterpret_cast<Bytef*>(block_.data() + filled);
      z_.avail_out = static_cast<uInt>(block_.size() - filled);
      const int result = inflate(&z_, Z_NO_FLUSH);
      const std::size_t consumed = (raw_end_ - raw_begin_) - z_.avail_in;
      raw_begin_ += consumed;
      file_offset_ += consumed;
      filled = block_.size() - z_.avail_out;
      if (result == Z_STREAM_END) {
        between_members_ = true;
      } else if (result == Z_BUF_ERROR && raw_begin_ == raw_end_ && raw_eof_) {
        // No progress, and no more input: the file ends inside the stream.
        fail_decoding("gzip data cut short: the file ends at byte " + std::to_string(file_offset_), filled);
      } else if (result != Z_OK && result != Z_BUF_ERROR) {
        const char* why = z_.msg != nullptr ? z_.msg : "data error";
        fail_decoding("corrupt gzip data at byte " + std::to_string(file_offset_), filled, why);
        break;
      }
    }
    if (error_) filled = whole_lines(filled);
    else if (!ended_) hold_back_line_start(filled);
    else held_end_ = held_begin_ = 0;
    const std::size_t delivered = error_ || ended_ ? filled : held_begin_;
    for (std::size_t i = 0; i < delivered; ++i) lines_ += block_[i] == '\n' ? 1 : 0;
    setg(block_.data(), block_.data(), block_.data() + delivered);
    return delivered > 0;
  }

  // Keeps the part after the block's last newline for the next block (unless
  // the block holds no newline at all: a line longer than a block goes as is).
  void hold_back_line_start(std::size_t filled) {
    const auto* last = static_cast<const char*>(memrchr(block_.data(), '\n', filled));
    held_begin_ = last == nullptr ? filled : static_cast<std::size_t>(last - block_.data()) + 1;
    held_end_ = filled;
  }

  std::size_t whole_lines(std::size_t filled) const {
    const auto* last = static_cast<const char*>(memrchr(block_.data(), '\n', filled));
    return last == nullptr ? 0 : static_cast<std::size_t>(last - block_.data()) + 1;
  }

  // `decoded` bytes of this block are decoded: the broken line is the one
  // after the last newline in them.
  void fail_decoding(const std::string& where, std::size_t decoded, const std::string& why = "") {
    std::size_t line = lines_ + 1;
    for (std::size_t i = 0; i < decoded; ++i) line += block_[i] == '\n' ? 1 : 0;
    fail(where + ", in line " + std::to_string(line) + (why.empty() ? "" : ": " + why));
  }

  void fail(std::string message) {
    if (!error_) error_ = std::move(message);
  }

  int fd_;
  bool gzip_ = false;
  z_stream z_{};
  std::array<char, kBlockSize> raw_{};
  std::size_t raw_begin_ = 0, raw_end_ = 0;
  bool raw_eof_ = false;
  std::size_t file_offset_ = 0;  // bytes of the file consumed
  std::array<char, kBlockSize> block_{};
  std::size_t held_begin_ = 0, held_end_ = 0;
  bool between_members_ = false;
  bool ended_ = false;
  std::size_t lines_ = 0;  // newlines delivered
  std::optional<std::string> error_;
};

class FileLogInput final : public LogInput {
 public:
  explicit FileLogInput(int fd) : LogInput(nullptr), buffer_(fd) { rdbuf(&buffer_); }
  [[nodiscard]] std::optional<std::string> error() const override { return buffer_.error(); }

 private:
  LogReadBuffer buffer_;
};

}  // namespace

std::unique_ptr<LogInput> open_log_input(const std::filesystem::path& path) {
  if (std::filesystem::is_directory(path)) {
    throw std::runtime_error("cannot open " + path.string() + ": it is a directory");
  }
  const int fd = ::open(path.c_str(), O_RDONLY | O_CLOEXEC);
  if (fd < 0) throw std::runtime_error("cannot open " + path.string() + ": " + std::strerror(errno));
  return std::make_unique<FileLogInput>(fd);
}

}  // namespace playerkit::log
