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
  const Clock::time_point until = Clock::now() + kGatherWithin;
  // Targets add their next round while we go, a period after the one handed
  // out, so this loop ends whatever the periods (at most kGatherWithin / period
  // rounds of one target, which then finds its round still pending).
  while (!due_.empty() && due_.top().when <= until) {
    Entry entry = due_.top();
    due_.pop();
    if (auto target = entry.target.lock()) target->push_due(entry.generation);
  }
  if (!due_.empty() && (!waiting_ || due_.top().when < waiting_for_)) wait_until(due_.top().when);
}

}  // namespace playerkit::server
