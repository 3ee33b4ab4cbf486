#include "core/reader_progress.hpp"

#include <algorithm>

namespace playerkit::core {

void ReaderProgress::taken(ClientId reader, std::uint64_t sequence) {
  {
    std::lock_guard lock(mutex_);
    taken_[reader] = sequence;
  }
  changed_.notify_all();
}

void ReaderProgress::forget(ClientId reader) {
  {
    std::lock_guard lock(mutex_);
    taken_.erase(reader);
  }
  changed_.notify_all();
}

std::size_t ReaderProgress::count() const {
  std::lock_guard lock(mutex_);
  return taken_.size();
}

bool ReaderProgress::all_taken(std::uint64_t sequence) const {
  return std::all_of(taken_.begin(), taken_.end(),
                     [sequence](const auto& entry) { return entry.second >= sequence; });
}

bool ReaderProgress::wait_until_taken(std::uint64_t sequence, const std::stop_token& stop) {
  std::unique_lock lock(mutex_);
  return changed_.wait(lock, stop, [&] { return all_taken(sequence); });
}

bool ReaderProgress::wait_for_reader(const std::stop_token& stop) {
  std::unique_lock lock(mutex_);
  return changed_.wait(lock, stop, [&] { return !taken_.empty(); });
}

}  // namespace playerkit::core
