#pragma once
// Several threads writing to one stdout or stderr (data dump, request
// replies, --stats, --trace, the daemon's log): each writes through a stream
// of its own, and whole lines reach the target one at a time, flushed, so
// lines never interleave mid-way and a pipe reader sees each at once.

#include <functional>
#include <memory>
#include <mutex>
#include <optional>
#include <ostream>
#include <string>
#include <string_view>

namespace playerkit::player_drivers {

class SharedLines {
 public:
  explicit SharedLines(std::ostream& target) : target_(target) {}
  SharedLines(const SharedLines&) = delete;
  SharedLines& operator=(const SharedLines&) = delete;

  // Writes `line` and a newline, flushed. False when the target failed
  // (its errno tells why, EPIPE for a closed pipe).
  bool write_line(std::string_view line);
  // Rewrites each line (without its newline) of a stream, or drops it (nullopt).
  using LineFilter = std::function<std::optional<std::string>(std::string_view line)>;

  // A stream of its own: what is written to it goes out a whole line at a
  // time, through `filter` when one is given. It goes bad when the target
  // fails. Must not outlive this object.
  std::unique_ptr<std::ostream> open(LineFilter filter = {});

 private:
  class LineBuffer;
  bool write_text(std::string_view text);

  std::ostream& target_;
  std::mutex mutex_;
};

}  // namespace playerkit::player_drivers
