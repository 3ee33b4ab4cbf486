#pragma once
// `writelog` (manual §7.48): records the data of other devices of this server
// into a Player 1.5 text log, e.g.
//
//   null:0 ( driver "writelog" filename "run.log" devices ["position:0" "laser:0"] alwayson 1 )
//
// While subscribed it holds a subscription on every listed device and writes
// one line per sample each of them publishes (every sample, not a 10 Hz poll
// as in 1.5), plus a `sync` line at most every 100 ms of server time. Every
// line is flushed as it is written; shutdown (the last unsubscription, or the
// server stopping on SIGINT/SIGTERM) writes whatever was received before the
// file is closed. The file is truncated at each set-up, as in 1.5, and
// written in place (files::OutputFile's streaming mode) so that it can be
// watched as it grows. A filename ending in ".gz" is written gzip-compressed,
// flushed at most once a second (each flush costs compression). Requests
// are answered NACK; no data, no commands.

#include <condition_variable>
#include <cstdint>
#include <deque>
#include <chrono>
#include <map>
#include <memory>
#include <mutex>
#include <optional>
#include <stop_token>
#include <string>
#include <vector>

#include "core/device.hpp"
#include "core/device_table.hpp"
#include "core/driver.hpp"
#include "core/driver_registry.hpp"
#include "core/source_subscription.hpp"
#include "files/output_file.hpp"

namespace playerkit::drivers {

class WritelogDriver final : public core::ThreadedDriver, private core::DeviceListener {
 public:
  // `sources` are looked up in `devices` at each set-up (they may be declared
  // after this device). `host` goes into every line.
  WritelogDriver(std::string filename, std::vector<core::DeviceKey> sources,
                 core::DeviceTable& devices, std::string host);
  ~WritelogDriver() override;

  // Every device to record exists (they are looked up again at set-up).
  void check() override;
  [[nodiscard]] std::vector<core::DeviceKey> source_devices() const override { return source_keys_; }

 protected:
  void open() override;
  void close() override;
  void run(std::stop_token stop) override;

 private:
  // A line to write: a sample, or a sync line when `sample` is null. Its time
  // is the clock's when it was queued, not when the thread gets to it, so a
  // simulation records the same bytes at any speedup.
  struct Pending {
    protocol::Timestamp recorded;
    protocol::DeviceAddress address;
    std::shared_ptr<const core::DataSample> sample;
  };

  void data_published(const core::Device& device) override;
  void replies_ready(const core::Device&) override {}

  // Queues the samples of `source` not queued yet, recorded at `now`. Holds
  // pending_mutex_.
  void collect_new_samples(const core::Device& source, protocol::Timestamp now);
  // Queues a sync line if one is due at `now`. Holds pending_mutex_.
  void queue_sync_if_due(protocol::Timestamp now);
  void write_pending();
  void write_line(const std::string& line);
  // Plain files: after every line. Gzip: at most once a second, from the
  // thread's loop (`periodic`).
  void flush_written(bool periodic);
  void report_write_failure();

  const std::string filename_;
  const std::vector<core::DeviceKey> source_keys_;
  core::DeviceTable& devices_;
  const std::string host_;

  std::optional<files::OutputFile> out_;  // between open() and close()
  bool write_failed_ = false;
  bool unflushed_ = false;
  std::chrono::steady_clock::time_point last_flush_{};
  std::uint64_t last_sync_us_ = 0;  // under pending_mutex_

  std::mutex pending_mutex_;
  std::condition_variable_any pending_ready_;
  std::deque<Pending> pending_;
  std::map<const core::Device*, std::uint64_t> last_sequence_;  // under pending_mutex_
  // Under pending_mutex_. A callback may still arrive after remove_listener()
  // (Device calls listeners outside its lock); close() clears this first.
  bool accepting_ = false;

  // Subscribed between open() and close(). Last, so they go first on
  // destruction: no notification can reach members already destroyed.
  std::vector<core::SourceSubscription> sources_;
};

// The host name written in log lines: this machine's, or "localhost" when it
// has none usable (the format separates fields by spaces).
std::string log_host_name();

core::DriverSpec writelog_driver_spec();

}  // namespace playerkit::drivers
