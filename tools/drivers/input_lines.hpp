#pragma once
// `run --stdin`: an istream over a file descriptor whose reads give up (end
// of input) when asked to stop, so the thread feeding commands from it ends
// with the run even while nobody types.

#include <atomic>
#include <istream>
#include <memory>

namespace playerkit::player_drivers {

class InterruptibleInput {
 public:
  // Reads `fd` (not owned, not closed).
  explicit InterruptibleInput(int fd);
  ~InterruptibleInput();
  InterruptibleInput(const InterruptibleInput&) = delete;
  InterruptibleInput& operator=(const InterruptibleInput&) = delete;

  std::istream& stream();
  // From any thread: the stream reads as ended within 100 ms.
  void stop() { stopped_ = true; }

 private:
  class Buffer;
  std::atomic<bool> stopped_{false};
  std::unique_ptr<Buffer> buffer_;
  std::unique_ptr<std::istream> stream_;
};

}  // namespace playerkit::player_drivers
