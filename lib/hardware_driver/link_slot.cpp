#include "hardware_driver/link_slot.hpp"

#include <utility>

#include "links/link_error.hpp"
#include "links/open_link.hpp"

namespace playerkit::hardware_driver {

namespace {

links::LinkCounterSnapshot sum_of(const links::LinkCounterSnapshot& a, const links::LinkCounterSnapshot& b) {
  links::LinkCounterSnapshot total = a;
  total.bytes_in += b.bytes_in;
  total.bytes_out += b.bytes_out;
  total.telegrams += b.telegrams;
  total.checksum_errors += b.checksum_errors;
  total.resyncs += b.resyncs;
  total.bytes_dropped += b.bytes_dropped;
  total.timeouts += b.timeouts;
  total.reconnects += b.reconnects;
  total.retries += b.retries;
  return total;
}

}  // namespace

LinkSlot::LinkSlot(std::string port, links::SerialSettings settings)
    : port_(std::move(port)), settings_(settings) {}

links::ByteLink& LinkSlot::open() {
  std::shared_ptr<links::ByteLink> link;
  try {
    link = links::open_link(port_, settings_);
  } catch (const links::LinkError& e) {
    throw core::DriverError(e.what());
  }
  std::lock_guard lock(mutex_);
  if (link_) released_ = sum_of(released_, link_->counters().snapshot());
  link_ = std::move(link);
  install_trace();
  return *link_;
}

void LinkSlot::close() noexcept {
  if (link_) link_->close();
}

void LinkSlot::reopen(links::Deadline deadline) {
  if (!link_) throw links::LinkError(links::LinkErrorKind::closed, port_, port_ + ": never opened");
  link_->reopen(deadline);
}

void LinkSlot::release() noexcept {
  std::shared_ptr<links::ByteLink> gone;
  {
    std::lock_guard lock(mutex_);
    if (!link_) return;
    released_ = sum_of(released_, link_->counters().snapshot());
    gone = std::exchange(link_, nullptr);
  }
  gone->close();
}

links::LinkCounterSnapshot LinkSlot::totals() const {
  std::lock_guard lock(mutex_);
  return link_ ? sum_of(released_, link_->counters().snapshot()) : released_;
}

std::vector<core::DriverCounter> LinkSlot::counters(std::uint64_t reconnects, std::vector<core::DriverCounter> extra,
                                                    std::uint64_t own_timeouts) const {
  const links::LinkCounterSnapshot total = totals();
  std::vector<core::DriverCounter> figures{
      {"bytes_in", total.bytes_in},
      {"bytes_out", total.bytes_out},
      {"telegrams", total.telegrams},
      {"checksum_errors", total.checksum_errors},
      {"resyncs", total.resyncs},
      {"bytes_dropped", total.bytes_dropped},
      // A driver's own looks at the line that found no whole telegram are
      // not timeouts: unanswered requests and stuck writes are.
      {"timeouts", total.timeouts > own_timeouts ? total.timeouts - own_timeouts : 0},
      {"reconnects", reconnects},
      {"retries", total.retries}};
  figures.insert(figures.end(), std::make_move_iterator(extra.begin()), std::make_move_iterator(extra.end()));
  return figures;
}

void LinkSlot::set_trace(core::ByteTrace trace) {
  std::lock_guard lock(mutex_);
  trace_ = std::move(trace);
  install_trace();
}

void LinkSlot::install_trace() {
  if (!link_) return;
  if (!trace_) {
    link_->set_trace_hook({});
    return;
  }
  link_->set_trace_hook([trace = trace_](links::Direction direction, std::span<const std::uint8_t> bytes,
                                         links::LinkClock::time_point when) {
    trace(direction == links::Direction::out, bytes, when);
  });
}

}  // namespace playerkit::hardware_driver
