#pragma once
// A bidirectional byte stream to one device, whatever carries it (a serial
// port, a TCP bridge). Drivers talk to this interface only, so the same
// driver runs on /dev/ttyUSB0, on ser2net and against an emulator.
//
// Every wait ends at a deadline (poll(2), never sleeping in a loop). Every
// read and write is counted and, when a trace hook is set, reported with its
// bytes and time so `--trace` can hex-dump both directions.
//
// Threads: one thread may read while another writes. close() and reopen()
// must not race with either (call them from the thread that owns the link).

#include <cstddef>
#include <cstdint>
#include <functional>
#include <memory>
#include <mutex>
#include <span>
#include <string>

#include "links/deadline.hpp"
#include "links/link_counters.hpp"

namespace playerkit::links {

enum class Direction {
  in,   // device -> host (read)
  out,  // host -> device (written)
};

// Called after every read and write that moved bytes, on the thread that did it.
using TraceHook = std::function<void(Direction, std::span<const std::uint8_t> bytes, LinkClock::time_point when)>;

class ByteLink {
 public:
  ByteLink(const ByteLink&) = delete;
  ByteLink& operator=(const ByteLink&) = delete;
  virtual ~ByteLink() = default;

  // Waits until at least one byte is available or the deadline passes; reads
  // what is there, up to buffer.size(). Returns the count, 0 on timeout only
  // (an empty buffer reads nothing and returns 0 at once).
  // Throws LinkError: disconnected (device unplugged, peer gone), closed, io_error.
  std::size_t read_some(std::span<std::uint8_t> buffer, Deadline deadline);

  // Writes every byte, or throws LinkError(timed_out) saying how many went
  // out before the deadline (and counts a timeout), or disconnected/io_error.
  void write_all(std::span<const std::uint8_t> bytes, Deadline deadline);

  // Discards bytes received but not yet read (before a request whose reply
  // must not be confused with stale data).
  virtual void flush_input() = 0;
  // Returns once written bytes have left the host (a serial port's UART);
  // on TCP the kernel sends on its own and this returns at once.
  virtual void drain() = 0;
  // Releases the device. Idempotent; reads and writes afterwards throw `closed`.
  virtual void close() noexcept = 0;
  [[nodiscard]] virtual bool is_open() const = 0;
  // Opens the same device again with the same settings (after a disconnect),
  // keeping counters and trace hook; counts a reconnect. Throws like the first open.
  virtual void reopen(Deadline deadline) = 0;

  // Changes the line speed while open (the SICK baud negotiation). Returns
  // false when the link has no line speed of its own (TCP: a bridge's speed
  // is configured on the bridge). Throws LinkError(bad_settings) when the
  // port refuses the rate.
  virtual bool set_baud(int baud);
  // The line speed, 0 when the link has none.
  [[nodiscard]] virtual int baud() const { return 0; }

  // "/dev/ttyUSB0 at 38400 8N1", "tcp:127.0.0.1:4001".
  [[nodiscard]] virtual std::string describe() const = 0;
  // The file descriptor, for a caller that polls it together with others;
  // -1 when closed. Reading it directly bypasses counters and traces.
  [[nodiscard]] virtual int native_handle() const = 0;

  LinkCounters& counters() { return counters_; }
  [[nodiscard]] const LinkCounters& counters() const { return counters_; }

  // Replaces the trace hook (an empty function removes it). Safe to call
  // while another thread reads or writes.
  void set_trace_hook(TraceHook hook);

 protected:
  ByteLink() = default;

  // One wait-and-read: the count read, 0 when the deadline passed first.
  virtual std::size_t read_available(std::span<std::uint8_t> buffer, Deadline deadline) = 0;
  // Writes as much as the deadline allows; returns the count written.
  virtual std::size_t write_available(std::span<const std::uint8_t> bytes, Deadline deadline) = 0;

  // For subclasses that read or discard bytes outside read_some.
  void report(Direction direction, std::span<const std::uint8_t> bytes);

 private:
  LinkCounters counters_;
  std::mutex trace_mutex_;
  std::shared_ptr<const TraceHook> trace_hook_;
};

}  // namespace playerkit::links
