#include "device_monitor.hpp"

#include <mutex>
#include <set>

#include "protocol/device_address.hpp"

namespace playerkit::player_drivers {

class DeviceMonitor::Listener final : public core::DeviceListener {
 public:
  Listener(core::Device& device, std::string link_group)
      : device_(device), link_group_(std::move(link_group)), meter_(StatsClock::now()) {
    device_.add_listener(this);
  }
  ~Listener() override { device_.remove_listener(this); }
  Listener(const Listener&) = delete;
  Listener& operator=(const Listener&) = delete;

  void data_published(const core::Device& /*device*/) override {
    const auto now = StatsClock::now();
    const std::lock_guard lock(mutex_);
    meter_.record(now);
  }
  void replies_ready(const core::Device& /*device*/) override {}

  RateSummary take(StatsClock::time_point now) {
    const std::lock_guard lock(mutex_);
    return meter_.take(now);
  }
  core::Device& device() { return device_; }
  const std::string& link_group() const { return link_group_; }

 private:
  core::Device& device_;
  std::string link_group_;
  std::mutex mutex_;
  RateMeter meter_;
};

DeviceMonitor::DeviceMonitor(const std::vector<MonitoredDevice>& devices) {
  for (const auto& monitored : devices) {
    listeners_.push_back(std::make_unique<Listener>(*monitored.device, monitored.link_group));
  }
}

DeviceMonitor::~DeviceMonitor() = default;

std::vector<std::string> DeviceMonitor::report(StatsClock::time_point now) {
  std::vector<std::string> lines;
  std::set<std::string> families_shown;
  for (const auto& listener : listeners_) {
    core::Device& device = listener->device();
    std::string line = "stats " + protocol::to_string(device.address()) + " " + device.info().driver_name + ": " +
                       to_string(listener->take(now));
    const auto counters = device.driver().counters();
    if (!counters.empty()) {
      // Devices of one robot share its link and report the same counters.
      const std::string& group = listener->link_group();
      if (group.empty() || families_shown.insert(group).second) line += "; link: " + counters_text(counters);
    }
    lines.push_back(std::move(line));
  }
  return lines;
}

std::string counters_text(const std::vector<core::DriverCounter>& counters) {
  std::string text;
  for (const auto& counter : counters) {
    text += (text.empty() ? "" : ", ") + counter.name + " " + std::to_string(counter.value);
  }
  return text;
}

}  // namespace playerkit::player_drivers
