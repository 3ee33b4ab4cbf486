#include "server/push_schedule.hpp"

namespace playerkit::server {

PushSchedule::PushSchedule(const boost::asio::any_io_executor& executor) : timer_(executor) {}

void PushSchedule::add(Clock::time_point when, const std::weak_ptr<PushTarget>& target,
                       std::uint64_t generation) {
  due_.push(Entry{when, next_order_++, target, generation});
  if (!waiting_ || when < waiting_for_) wait_until(when);
}

void PushSchedule::clear() {
  due_ = {};
  waiting_ = false;
  timer_.cancel();
}

void PushSchedule::wait_until(Clock::time_point when) {
  waiting_ = true;
  waiting_for_ = when;
  // expires_at cancels a wait already pending; its handler then sees
  // operation_aborted and leaves the schedule to this newer wait.
  timer_.expires_at(when);
  timer_.async_wait([this](const boost::system::error_code& ec) {
    if (ec) return;
    waiting_ = false;
    hand_out_due();
  });
}

void PushSchedule::hand_out_due() {
  const Clock::time_point now = Clock::now();
  // Targets add their next round while we go; it lies after `now`, so this
  // loop ends even if a target's period is shorter than the time it takes.
  while (!due_.empty() && due_.top().when <= now) {
    Entry entry = due_.top();
    due_.pop();
    if (auto target = entry.target.lock()) target->push_due(entry.generation);
  }
  if (!due_.empty() && (!waiting_ || due_.top().when < waiting_for_)) wait_until(due_.top().when);
}

}  // namespace playerkit::server
