#pragma once
// One driver class for both SICK lasers (sicklms200 and sickpls differ in
// model, defaults and the steps of sick_laser_control.hpp), on
// hardware_driver::SerialDeviceDriver (the port, its loss and recovery, the
// counters and the trace); what stays here is the laser's own:
//
//  * start: the port opened at 9600 (8N1, the PLS 8E1), `delay`, the laser
//    found at 38400 then 9600 (then `rate`), switched to `rate`, configured,
//    streaming. A laser that does not answer refuses the subscription with a
//    message naming the port and the speeds tried.
//  * serve: each B0/B7 telegram becomes one player_laser_data_t, stamped
//    when it arrived; requests are answered as they arrive (the thread
//    sleeps on the line and wakes for them).
//  * a laser silent for 4 scan periods (at least 1 s), or a port that goes
//    away: the laser is lost (the base logs it, makes the device
//    unavailable and every retry_interval starts it again, the port
//    reopened if it had gone, the last good speed tried first).
//  * stop: the stream stopped (T1), a laser run at 500000 put back to
//    38400, then the port closed.

#include <atomic>
#include <chrono>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "families/sick/driver/sick_driver_settings.hpp"
#include "families/sick/driver/sick_laser_control.hpp"
#include "families/sick/driver/sick_session.hpp"
#include "hardware_driver/serial_device_driver.hpp"
#include "links/byte_link.hpp"

namespace playerkit::drivers::sick_laser {

class SickLaserDriver final : public hardware_driver::SerialDeviceDriver {
 public:
  explicit SickLaserDriver(SickDriverSettings settings);
  ~SickLaserDriver() override;

  [[nodiscard]] const SickDriverSettings& settings() const { return settings_; }

 protected:
  void start_device(links::ByteLink& link, bool recovering) override;
  void serve(links::ByteLink& link, const core::Wakeup::Woken& woke) override;
  [[nodiscard]] Clock::time_point next_deadline() const override;
  void stop_device(links::ByteLink& link) noexcept override;
  void link_closing() noexcept override;
  [[nodiscard]] std::string subject() const override;
  [[nodiscard]] std::string recovery_detail() const override;
  // scans (published), after the link's figures.
  [[nodiscard]] std::vector<core::DriverCounter> protocol_counters() const override;
  core::RequestResult handle_request(const core::Request& request) override;

 private:
  SickLaserControl control();
  // The whole bring-up to streaming `scan_`; SickSetupError or LinkError.
  void bring_up(const std::vector<int>& probe_rates);
  [[nodiscard]] std::vector<int> probe_rates(bool recovering) const;
  void take_telegram(const hardware::sick::Reply& reply);
  [[nodiscard]] Clock::duration data_timeout() const;

  core::RequestResult set_config(const core::Request& request);
  [[nodiscard]] core::RequestResult geometry() const;
  [[nodiscard]] std::string where() const;  // "laser:0@6665 (sicklms200)"

  const SickDriverSettings settings_;
  ScanConfig scan_;    // in force on the laser
  LaserState state_;   // speed, type, unit

  std::unique_ptr<SickSession> session_;
  // A telegram was just taken: more may wait in the session's buffer,
  // where a wait on the line would not see them.
  bool more_buffered_ = false;
  // A request found the laser gone (a reconfiguration it could not undo,
  // the port failing): the next serve() reports it.
  std::optional<std::string> lost_in_request_;
  bool port_gone_in_request_ = false;
  Clock::time_point last_scan_{};
  std::atomic<std::uint64_t> scans_{0};
};

}  // namespace playerkit::drivers::sick_laser
