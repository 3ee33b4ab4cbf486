#pragma once
// One driver class for both SICK lasers (sicklms200 and sickpls differ in
// model, defaults and the steps of sick_laser_control.hpp):
//
//  * setup (open): the port opened at 9600 (8N1, the PLS 8E1), `delay`,
//    the laser found at 38400 then 9600 (then `rate`), switched to `rate`,
//    configured, streaming. A laser that does not answer refuses the
//    subscription with a message naming the port and the speeds tried.
//  * run: each B0/B7 telegram becomes one player_laser_data_t, stamped when
//    it arrived; requests are answered between telegrams (and every 100 ms
//    when none come).
//  * a laser silent for 4 scan periods (at least 1 s), or a port that goes
//    away: one log line, the device unavailable, and every retry_interval
//    the whole bring-up again (the port reopened if it had gone); when it
//    succeeds the device is available again and data resumes.
//  * shutdown (close): the stream stopped (T1), a laser run at 500000 put
//    back to 38400, the port closed.

#include <atomic>
#include <chrono>
#include <memory>
#include <mutex>
#include <stop_token>
#include <string>
#include <vector>

#include "core/driver.hpp"
#include "families/sick/driver/sick_driver_settings.hpp"
#include "families/sick/driver/sick_laser_control.hpp"
#include "families/sick/driver/sick_session.hpp"
#include "links/byte_link.hpp"
#include "links/link_counters.hpp"

namespace playerkit::drivers::sick_laser {

class SickLaserDriver final : public core::ThreadedDriver {
 public:
  explicit SickLaserDriver(SickDriverSettings settings);
  ~SickLaserDriver() override;

  [[nodiscard]] const SickDriverSettings& settings() const { return settings_; }
  // open() probes baud rates and brings the laser up: seconds.
  [[nodiscard]] bool setup_may_block() const override { return true; }

  // bytes_in, bytes_out, telegrams, checksum_errors, resyncs, bytes_dropped,
  // timeouts, reconnects (lost lasers found again), scans (published).
  [[nodiscard]] std::vector<core::DriverCounter> counters() const override;
  bool set_byte_trace(core::ByteTrace trace) override;

 protected:
  void open() override;
  void close() override;
  void run(std::stop_token stop) override;
  core::RequestResult handle_request(const core::Request& request) override;

 private:
  SickLaserControl control();
  // The whole bring-up to streaming `scan_`; SickSetupError or LinkError.
  void bring_up(const std::vector<int>& probe_rates);
  [[nodiscard]] std::vector<int> probe_rates(bool recovering) const;
  void take_telegram(const hardware::sick::Reply& reply);
  void lose_laser(const std::string& reason, bool port_gone);
  void try_to_recover(const std::stop_token& stop);
  [[nodiscard]] std::chrono::steady_clock::duration data_timeout() const;
  void stop_laser() noexcept;
  void release_link() noexcept;
  void install_trace();  // link_mutex_ held

  core::RequestResult set_config(const core::Request& request);
  [[nodiscard]] core::RequestResult geometry() const;
  [[nodiscard]] std::string where() const;  // "laser:0@6665 (sicklms200)"

  const SickDriverSettings settings_;
  ScanConfig scan_;    // in force on the laser
  LaserState state_;   // speed, type, unit
  std::stop_token stop_token_;  // the thread's, while it runs

  mutable std::mutex link_mutex_;  // link_ as a pointer, trace_, retired_
  std::unique_ptr<links::ByteLink> link_;
  core::ByteTrace trace_;
  links::LinkCounterSnapshot retired_;  // counters of links closed before

  std::unique_ptr<SickSession> session_;
  bool lost_ = false;
  bool port_gone_ = false;  // the link itself failed: reopen before trying again
  std::chrono::steady_clock::time_point last_scan_{};
  std::chrono::steady_clock::time_point next_attempt_{};
  std::atomic<std::uint64_t> reconnects_{0};
  std::atomic<std::uint64_t> scans_{0};
};

}  // namespace playerkit::drivers::sick_laser
