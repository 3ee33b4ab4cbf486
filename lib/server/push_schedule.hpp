#pragma once
// When each client's next data round falls due, for every client at once.
//
// A thousand clients at 100 Hz are 100 000 rounds a second. One timer per
// client costs a timer-queue insertion, a handler and often a reprogramming of
// the kernel timer for each of them; here one heap holds every due time and
// one timer waits for the earliest, and a wake-up hands out, in due order,
// every round due by then or within kGatherWithin after. Runs on the
// event-loop thread.

#include <chrono>
#include <cstdint>
#include <memory>
#include <queue>
#include <vector>

#include <boost/asio/any_io_executor.hpp>
#include <boost/asio/steady_timer.hpp>

namespace playerkit::server {

// What the schedule calls back: a client session.
class PushTarget {
 public:
  // `generation` is the one given to PushSchedule::add; a target that has
  // rescheduled since then ignores the call.
  virtual void push_due(std::uint64_t generation) = 0;

 protected:
  ~PushTarget() = default;
};

class PushSchedule {
 public:
  using Clock = std::chrono::steady_clock;
  // A wake-up also hands out the rounds due this soon after it: clients'
  // rounds spread over a period then go out in small batches, not one wake-up
  // each (at 100 Hz that is 2 % of a period early, and the cadence keeps).
  static constexpr std::chrono::microseconds kGatherWithin{200};

  explicit PushSchedule(const boost::asio::any_io_executor& executor);

  // Calls target->push_due(generation) once, at `when` or as soon after as
  // the event loop gets to it; not at all if the target is gone by then.
  // Nothing is removed early: a target that changes its schedule adds a new
  // entry under a new generation and ignores the old one when it comes.
  void add(Clock::time_point when, const std::weak_ptr<PushTarget>& target, std::uint64_t generation);
  // Drops every entry and stops waiting (the server is stopping).
  void clear();

  [[nodiscard]] std::size_t pending() const { return due_.size(); }

 private:
  struct Entry {
    Clock::time_point when;
    std::uint64_t order;  // ties in `when` keep the order of add()
    std::weak_ptr<PushTarget> target;
    std::uint64_t generation;
  };
  struct Later {
    bool operator()(const Entry& a, const Entry& b) const {
      return a.when != b.when ? a.when > b.when : a.order > b.order;
    }
  };

  void wait_until(Clock::time_point when);
  void hand_out_due();

  boost::asio::steady_timer timer_;
  std::priority_queue<Entry, std::vector<Entry>, Later> due_;
  std::uint64_t next_order_ = 0;
  bool waiting_ = false;
  Clock::time_point waiting_for_{};
};

}  // namespace playerkit::server
