#pragma once
// `run --stats`: listens to the served devices and says, once a second on
// stderr, how regularly each publishes (rate_meter.hpp) and what its
// driver's link counted (core::Driver::counters):
//
//   stats laser:0 sicklms200: 5.0 Hz (5 in 1.0 s), interval 199.1-201.0 ms, jitter 0.7 ms;
//         link: bytes_in 3660, bytes_out 28, telegrams 6, checksum_errors 0, ...
//
// The devices of one family share a link, so its counters are shown once,
// on the first device that has them.

#include <memory>
#include <string>
#include <vector>

#include "core/device.hpp"
#include "rate_meter.hpp"

namespace playerkit::player_drivers {

struct MonitoredDevice {
  core::Device* device = nullptr;
  // Devices with the same non-empty group share a link (a driver family
  // run together); their counters are shown once.
  std::string link_group;
};

class DeviceMonitor {
 public:
  // Starts listening; the devices must outlive the monitor.
  explicit DeviceMonitor(const std::vector<MonitoredDevice>& devices);
  ~DeviceMonitor();
  DeviceMonitor(const DeviceMonitor&) = delete;
  DeviceMonitor& operator=(const DeviceMonitor&) = delete;

  // One line per device for the window since the previous report.
  std::vector<std::string> report(StatsClock::time_point now);

 private:
  class Listener;
  std::vector<std::unique_ptr<Listener>> listeners_;
};

// "bytes_in 3660, bytes_out 28" (empty for no counters).
std::string counters_text(const std::vector<core::DriverCounter>& counters);

}  // namespace playerkit::player_drivers
