#include "files/fd_write_buffer.hpp"

#include <unistd.h>

#include <cerrno>
#include <cstring>

namespace playerkit::files {

FdWriteBuffer::FdWriteBuffer(int fd) : fd_(fd) { setp(block_.data(), block_.data() + block_.size()); }

bool FdWriteBuffer::write_all(const char* data, std::size_t count) {
  if (error_) return false;
  while (count > 0) {
    const ssize_t written = ::write(fd_, data, count);
    if (written < 0) {
      if (errno == EINTR) continue;
      error_ = std::strerror(errno);
      return false;
    }
    data += written;
    count -= static_cast<std::size_t>(written);
  }
  return true;
}

bool FdWriteBuffer::drain() {
  const auto pending = static_cast<std::size_t>(pptr() - pbase());
  const bool written = write_all(pbase(), pending);
  setp(block_.data(), block_.data() + block_.size());
  return written;
}

FdWriteBuffer::int_type FdWriteBuffer::overflow(int_type c) {
  if (!drain()) return traits_type::eof();
  if (traits_type::eq_int_type(c, traits_type::eof())) return traits_type::not_eof(c);
  *pptr() = traits_type::to_char_type(c);
  pbump(1);
  return c;
}

std::streamsize FdWriteBuffer::xsputn(const char* data, std::streamsize count) {
  // Small pieces go through the block; a large one goes straight out after it.
  if (count <= epptr() - pptr()) {
    std::memcpy(pptr(), data, static_cast<std::size_t>(count));
    pbump(static_cast<int>(count));
    return count;
  }
  if (!drain() || !write_all(data, static_cast<std::size_t>(count))) return 0;
  return count;
}

int FdWriteBuffer::sync() { return drain() ? 0 : -1; }

}  // namespace playerkit::files
