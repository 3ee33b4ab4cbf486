#pragma once
// The link a hardware driver owns across its whole life: opened from the
// `port` option at setup, reopened when the device vanishes and comes back,
// closed at shutdown, opened again at the next setup. What outlives any one
// link is kept here: the byte trace (--trace) goes on every link as it is
// opened, and the counters (--stats) of links closed before are added to the
// current one's, so a reconnect never resets a figure.
//
// The I/O thread (or open()/close() while it is not running) opens, reopens
// and closes; counters() and set_trace() may be called from any thread.

#include <memory>
#include <mutex>
#include <string>
#include <vector>

#include "core/driver.hpp"
#include "links/byte_link.hpp"
#include "links/link_counters.hpp"
#include "links/serial_settings.hpp"

namespace playerkit::hardware_driver {

class LinkSlot {
 public:
  LinkSlot(std::string port, links::SerialSettings settings);
  LinkSlot(const LinkSlot&) = delete;
  LinkSlot& operator=(const LinkSlot&) = delete;

  // Opens `port` (a tty path or tcp:HOST:PORT) with the settings, replacing
  // any earlier link. Throws core::DriverError naming the port.
  links::ByteLink& open();
  // Closes the link, keeping it (and its counters) for reopen().
  void close() noexcept;
  // The link's own reopen (same device, same settings; counts a reconnect).
  // Throws links::LinkError.
  void reopen(links::Deadline deadline);
  // Closes the link and lets it go: the next start is open().
  void release() noexcept;

  // The open (or closed, not released) link; null before open(). I/O thread.
  [[nodiscard]] links::ByteLink* get() const { return link_.get(); }
  [[nodiscard]] const std::string& port() const { return port_; }
  [[nodiscard]] const links::SerialSettings& settings() const { return settings_; }

  // Every link's counters, this one's and those released before.
  [[nodiscard]] links::LinkCounterSnapshot totals() const;
  // The link's figures in --stats form, then `extra`. `reconnects` is the
  // caller's (devices found again), not the link's reopen count.
  [[nodiscard]] std::vector<core::DriverCounter> counters(std::uint64_t reconnects,
                                                          std::vector<core::DriverCounter> extra = {},
                                                          std::uint64_t own_timeouts = 0) const;
  // Every byte of every link from now on (an empty function stops it).
  void set_trace(core::ByteTrace trace);

 private:
  void install_trace();  // mutex_ held

  const std::string port_;
  const links::SerialSettings settings_;
  mutable std::mutex mutex_;  // link_ as a pointer, trace_, released_
  std::shared_ptr<links::ByteLink> link_;
  core::ByteTrace trace_;
  links::LinkCounterSnapshot released_;
};

}  // namespace playerkit::hardware_driver
