#include "core/source_subscription.hpp"

#include <string>
#include <utility>

#include "protocol/interfaces.hpp"

namespace playerkit::core {

Device& source_device(const DeviceTable& devices, const Device& self, std::uint16_t interface, int index,
                      std::string_view option, std::string_view purpose) {
  const DeviceKey key{self.key().port, {interface, static_cast<std::uint16_t>(index)}};
  const std::string what = protocol::interface_name(interface);
  if (key == self.key()) {
    throw DriverError(self.name() + ": " + std::string(option) + " " + std::to_string(index) +
                      " is this device itself; name the " + what + " to " + std::string(purpose));
  }
  Device* found = devices.find(key);
  if (found == nullptr) {
    throw DriverError(self.name() + ": no " + what + ":" + std::to_string(index) + " on port " +
                      std::to_string(key.port) + " to " + std::string(purpose));
  }
  return *found;
}

SourceSubscription::SourceSubscription(Device& source, DeviceListener* listener,
                                       std::string_view owner) {
  if (listener != nullptr) source.add_listener(listener);
  if (!source.subscribe()) {
    if (listener != nullptr) source.remove_listener(listener);
    throw DriverError(std::string(owner) + ": " + source.name() + " could not be set up");
  }
  source_ = &source;
  listener_ = listener;
}

SourceSubscription::SourceSubscription(SourceSubscription&& other) noexcept
    : source_(std::exchange(other.source_, nullptr)),
      listener_(std::exchange(other.listener_, nullptr)) {}

SourceSubscription& SourceSubscription::operator=(SourceSubscription&& other) noexcept {
  if (this != &other) {
    reset();
    source_ = std::exchange(other.source_, nullptr);
    listener_ = std::exchange(other.listener_, nullptr);
  }
  return *this;
}

SourceSubscription::~SourceSubscription() { reset(); }

void SourceSubscription::stop_listening() {
  if (source_ != nullptr && listener_ != nullptr) source_->remove_listener(listener_);
  listener_ = nullptr;
}

void SourceSubscription::reset() {
  if (source_ == nullptr) return;
  stop_listening();
  std::exchange(source_, nullptr)->unsubscribe();
}

}  // namespace playerkit::core
