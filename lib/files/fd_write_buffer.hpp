#pragma once
// A std::streambuf writing to a POSIX file descriptor it does not own, in
// 64 KiB blocks, EINTR retried. A failed write is kept (error()) and makes
// every later write fail, so a stream over it goes bad and stays bad.

#include <array>
#include <optional>
#include <streambuf>
#include <string>

namespace playerkit::files {

class FdWriteBuffer : public std::streambuf {
 public:
  explicit FdWriteBuffer(int fd);
  FdWriteBuffer(const FdWriteBuffer&) = delete;
  FdWriteBuffer& operator=(const FdWriteBuffer&) = delete;

  // Why the first failed write failed (strerror), if one did.
  [[nodiscard]] const std::optional<std::string>& error() const { return error_; }

 protected:
  int_type overflow(int_type c) override;
  std::streamsize xsputn(const char* data, std::streamsize count) override;
  int sync() override;

 private:
  bool write_all(const char* data, std::size_t count);
  bool drain();

  int fd_;
  std::array<char, 64 * 1024> block_{};
  std::optional<std::string> error_;
};

}  // namespace playerkit::files
