#include "input_lines.hpp"

#include <poll.h>
#include <unistd.h>

#include <array>
#include <cerrno>
#include <streambuf>

namespace playerkit::player_drivers {

class InterruptibleInput::Buffer final : public std::streambuf {
 public:
  Buffer(int fd, const std::atomic<bool>& stopped) : fd_(fd), stopped_(stopped) {}

 protected:
  int_type underflow() override {
    if (gptr() < egptr()) return traits_type::to_int_type(*gptr());
    while (!stopped_) {
      pollfd waiting{fd_, POLLIN, 0};
      const int ready = ::poll(&waiting, 1, 100);
      if (ready < 0 && errno != EINTR) return traits_type::eof();
      if (ready <= 0) continue;
      const ssize_t got = ::read(fd_, data_.data(), data_.size());
      if (got < 0 && (errno == EINTR || errno == EAGAIN)) continue;
      if (got <= 0) return traits_type::eof();
      setg(data_.data(), data_.data(), data_.data() + got);
      return traits_type::to_int_type(*gptr());
    }
    return traits_type::eof();
  }

 private:
  int fd_;
  const std::atomic<bool>& stopped_;
  std::array<char, 4096> data_{};
};

InterruptibleInput::InterruptibleInput(int fd)
    : buffer_(std::make_unique<Buffer>(fd, stopped_)), stream_(std::make_unique<std::istream>(buffer_.get())) {}

InterruptibleInput::~InterruptibleInput() = default;

std::istream& InterruptibleInput::stream() { return *stream_; }

}  // namespace playerkit::player_drivers
