#include "drivers/logfile/replay_session.hpp"

#include <algorithm>
#include <chrono>
#include <stdexcept>
#include <string>
#include <utility>
#include <variant>

#include "log/log_clock_reader.hpp"
#include "log/log_format_detection.hpp"
#include "log/log_input.hpp"
#include "text/printable.hpp"

namespace playerkit::drivers {

namespace {

using std::chrono::nanoseconds;

// After the end of the file the clock moves in steps of this much real time,
// as 1.5's did (100 ms).
constexpr nanoseconds kClockStepAfterEnd = std::chrono::milliseconds(100);

// Enough warnings to see what is wrong without flooding the log on a bad file.
constexpr std::uint64_t kMaxMalformedWarnings = 10;

protocol::Timestamp logged_time(const std::variant<log::SyncLine, log::DataLine>& line) {
  return std::visit([](const auto& entry) { return entry.server_time; }, line);
}

nanoseconds scaled(std::uint64_t log_microseconds, double speed) {
  return nanoseconds(static_cast<std::int64_t>(static_cast<double>(log_microseconds) * 1000.0 / speed));
}

}  // namespace

protocol::Timestamp first_replay_time(const std::filesystem::path& path) {
  bool carmen = false;
  try {
    carmen = log::detect_log_format(path) == log::LogFormat::kCarmen;
  } catch (const std::runtime_error&) {
    // Not told apart (unreadable, or no deciding line near the start): the
    // reader below says what is wrong in a Player log's terms.
  }
  if (carmen) {
    const std::string name = text::printable(path.string());
    throw std::runtime_error(name + " is a CARMEN log; readlog replays Player text logs: serve it with `player-log replay " +
                             name + "`, or convert it first with `player-log convert " + name + " -o run.log`");
  }
  const auto in = log::open_log_input(path);
  log::TextLogReader reader(*in, path.string());
  const auto first = reader.next();
  if (!first) {
    if (const auto error = in->error()) throw std::runtime_error(path.string() + ": " + *error);
    throw std::runtime_error(path.string() + ": no sync or data lines to replay");
  }
  return logged_time(*first);
}

ReplaySession::ReplaySession(ReplayOptions options, std::shared_ptr<core::ManualClock> clock,
                             std::shared_ptr<ReplayTimer> timer, core::Logger& logger)
    : options_(std::move(options)),
      clock_(std::move(clock)),
      timer_(timer ? std::move(timer) : std::make_shared<SteadyReplayTimer>()),
      logger_(logger) {
  first_log_time_ = first_replay_time(options_.path);
  // A log without usable times is paced by its LogClock (warned once on stderr).
  log_clock_ = log::audit_log_times(options_.path);
  if (const auto first = log_clock_->replacement(0)) first_log_time_ = protocol::Timestamp::from_seconds(*first);
  last_log_time_ = first_log_time_;
  // Before anyone subscribes the server already speaks log time.
  if (clock_ != nullptr) clock_->set(first_log_time_);
}

ReplaySession::~ReplaySession() {
  thread_.request_stop();
  if (thread_.joinable()) thread_.join();
}

void ReplaySession::attach(core::Device& device, protocol::DeviceAddress logged) {
  std::lock_guard lock(targets_mutex_);
  targets_.push_back({&device, logged});
  last_attach_ = timer_->now();
  if (!started_) {
    started_ = true;
    thread_ = std::jthread([this](std::stop_token stop) { run(stop); });
  }
}

void ReplaySession::detach(core::Device& device) {
  std::lock_guard lock(targets_mutex_);
  std::erase_if(targets_, [&device](const Target& target) { return target.device == &device; });
}

void ReplaySession::run(const std::stop_token& stop) {
  // Each pass either serves a line or ends; a pass that serves nothing (every
  // line before the start offset) would spin, so rewinding stops there.
  for (;;) {
    std::uint64_t served = 0;
    if (!replay_file(stop, served)) return;
    if (!options_.autorewind) break;
    if (served == 0) {
      logger_.warning(options_.path.string() + ": nothing to replay after the start offset; not rewinding");
      break;
    }
  }
  follow_clock_after_end(stop);
}

bool ReplaySession::replay_file(const std::stop_token& stop, std::uint64_t& served) {
  std::unique_ptr<log::LogInput> in;
  try {
    in = log::open_log_input(options_.path);
  } catch (const std::exception& e) {
    logger_.error(std::string("readlog: ") + e.what());
    return !stop.stop_requested();
  }
  log::TextLogReader reader(*in, options_.path.string(), {.clock = log_clock_});
  const std::uint64_t skip_before =
      core::to_microseconds(first_log_time_) +
      static_cast<std::uint64_t>(options_.start_offset * 1e6);
  std::uint64_t pass_start_log = 0;
  nanoseconds pass_start_wall{0};

  while (!stop.stop_requested()) {
    std::optional<std::variant<log::SyncLine, log::DataLine>> line;
    try {
      line = reader.next();
    } catch (const log::LogParseError& e) {
      if (++malformed_lines_ <= kMaxMalformedWarnings) logger_.warning(std::string("readlog: skipped ") + e.what());
      continue;
    }
    if (!line) break;
    const protocol::Timestamp time = logged_time(*line);
    const std::uint64_t log_us = core::to_microseconds(time);
    if (log_us < skip_before) continue;
    if (served == 0) {
      pass_start_log = log_us;
      pass_start_wall = timer_->now();
    }
    if (options_.duration && log_us > pass_start_log &&
        static_cast<double>(log_us - pass_start_log) > *options_.duration * 1e6) {
      // A pass lasts its whole window, not until its last line: the next one
      // starts `duration` after this one did, however sparse the log is there.
      const auto window = static_cast<std::uint64_t>(*options_.duration * 1e6);
      if (!options_.burst && !timer_->wait_until(pass_start_wall + scaled(window, options_.speed), stop)) {
        return false;
      }
      break;
    }
    ++served;
    if (options_.burst) {
      if (!settled_) {
        if (!wait_for_attachments_to_settle(stop)) return false;
        settled_ = true;
      }
      if (!wait_for_any_reader(stop)) return false;
    } else {
      // A line logged earlier than the pass start (time went back) goes at once.
      const nanoseconds offset = log_us > pass_start_log ? scaled(log_us - pass_start_log, options_.speed)
                                                          : nanoseconds{0};
      if (!timer_->wait_until(pass_start_wall + offset, stop)) return false;
    }
    last_log_time_ = time;
    if (clock_ != nullptr) clock_->set(time);
    if (const auto* data = std::get_if<log::DataLine>(&*line)) deliver(*data, stop);
  }
  if (const auto error = in->error()) logger_.error("readlog: " + options_.path.string() + ": " + *error);
  return !stop.stop_requested();
}

void ReplaySession::follow_clock_after_end(const std::stop_token& stop) {
  if (clock_ == nullptr) return;
  const nanoseconds end_wall = timer_->now();
  const std::uint64_t end_log = core::to_microseconds(last_log_time_);
  for (nanoseconds next = end_wall + kClockStepAfterEnd; timer_->wait_until(next, stop);
       next += kClockStepAfterEnd) {
    const auto elapsed = std::chrono::duration_cast<std::chrono::microseconds>(timer_->now() - end_wall);
    clock_->set(core::from_microseconds(
        end_log + static_cast<std::uint64_t>(static_cast<double>(elapsed.count()) * options_.speed)));
  }
}

void ReplaySession::deliver(const log::DataLine& line, const std::stop_token& stop) {
  // Interfaces the log format holds no fields for come back empty: nothing to serve.
  if (!line.device || line.message.payload.empty()) return;
  struct Owed {
    std::shared_ptr<core::ReaderProgress> readers;
    std::uint64_t sequence;
  };
  std::vector<Owed> owed;
  {
    std::lock_guard lock(targets_mutex_);
    for (const Target& target : targets_) {
      if (target.logged != *line.device) continue;
      target.device->publish(line.message.payload, line.data_time);
      const std::size_t queue = target.device->info().limits.data_queue;
      if (!options_.burst || queue == 0) continue;
      // Room for the next line: every reader is at most queue - 1 behind.
      const std::uint64_t sequence = target.device->latest_data()->sequence;
      if (sequence + 1 > queue) owed.push_back({target.device->shared_readers(), sequence + 1 - queue});
    }
  }
  // Outside the lock, so that a client leaving (which detaches) is not held up;
  // a reader that leaves is forgotten before its device detaches.
  for (const Owed& entry : owed) {
    if (!entry.readers->wait_until_taken(entry.sequence, stop)) return;
  }
}

bool ReplaySession::wait_for_attachments_to_settle(const std::stop_token& stop) {
  // Measured from the last subscription, not the first: on a loaded machine a
  // client's second subscription can come long after its first.
  for (;;) {
    nanoseconds quiet_until;
    {
      std::lock_guard lock(targets_mutex_);
      quiet_until = last_attach_ + options_.burst_settle;
    }
    if (timer_->now() >= quiet_until) return true;
    if (!timer_->wait_until(quiet_until, stop)) return false;
  }
}

bool ReplaySession::wait_for_any_reader(const std::stop_token& stop) {
  constexpr nanoseconds kPoll = std::chrono::milliseconds(20);
  for (;;) {
    {
      std::lock_guard lock(targets_mutex_);
      for (const Target& target : targets_) {
        if (target.device->readers().count() > 0) return true;
      }
    }
    if (!timer_->wait_until(timer_->now() + kPoll, stop)) return false;
  }
}

}  // namespace playerkit::drivers
