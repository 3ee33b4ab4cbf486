#include "line_streams.hpp"

#include <streambuf>
#include <string>

namespace playerkit::player_drivers {

// Collects characters until a newline (or an explicit flush), then hands the
// whole text to SharedLines.
class SharedLines::LineBuffer final : public std::streambuf {
 public:
  LineBuffer(SharedLines& lines, LineFilter filter) : lines_(lines), filter_(std::move(filter)) {}

 protected:
  int_type overflow(int_type character) override {
    if (traits_type::eq_int_type(character, traits_type::eof())) return traits_type::not_eof(character);
    pending_ += traits_type::to_char_type(character);
    if (pending_.back() == '\n' && !hand_over()) return traits_type::eof();
    return character;
  }
  std::streamsize xsputn(const char* text, std::streamsize count) override {
    pending_.append(text, static_cast<std::size_t>(count));
    if (pending_.find('\n') != std::string::npos) {
      // Everything up to the last newline goes now; a partial line waits.
      const std::size_t end = pending_.rfind('\n') + 1;
      const std::string whole = pending_.substr(0, end);
      pending_.erase(0, end);
      if (!lines_.write_text(filtered(whole))) return 0;
    }
    return count;
  }
  int sync() override { return hand_over() ? 0 : -1; }

 private:
  bool hand_over() {
    if (pending_.empty()) return true;
    const bool written = lines_.write_text(filtered(pending_));
    pending_.clear();
    return written;
  }

  // Each whole line through the filter; a partial last line (a flush
  // before its newline) goes through as it is.
  std::string filtered(const std::string& text) const {
    if (!filter_) return text;
    std::string result;
    std::size_t start = 0;
    while (start < text.size()) {
      const std::size_t end = text.find('\n', start);
      if (end == std::string::npos) {
        result += text.substr(start);
        break;
      }
      if (auto line = filter_(std::string_view(text).substr(start, end - start))) result += *line + "\n";
      start = end + 1;
    }
    return result;
  }

  SharedLines& lines_;
  LineFilter filter_;
  std::string pending_;
};

namespace {

// An ostream that owns its buffer.
class OwningStream final : public std::ostream {
 public:
  explicit OwningStream(std::unique_ptr<std::streambuf> buffer) : std::ostream(buffer.get()), buffer_(std::move(buffer)) {}
  ~OwningStream() override { flush(); }

 private:
  std::unique_ptr<std::streambuf> buffer_;
};

}  // namespace

bool SharedLines::write_text(std::string_view text) {
  if (text.empty()) return true;
  const std::lock_guard lock(mutex_);
  target_.write(text.data(), static_cast<std::streamsize>(text.size()));
  target_.flush();
  return static_cast<bool>(target_);
}

bool SharedLines::write_line(std::string_view line) {
  std::string text(line);
  text += '\n';
  return write_text(text);
}

std::unique_ptr<std::ostream> SharedLines::open(LineFilter filter) {
  return std::make_unique<OwningStream>(std::make_unique<LineBuffer>(*this, std::move(filter)));
}

}  // namespace playerkit::player_drivers
