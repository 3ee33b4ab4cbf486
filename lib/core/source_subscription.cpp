#include "core/source_subscription.hpp"

#include <string>
#include <utility>

namespace playerkit::core {

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
