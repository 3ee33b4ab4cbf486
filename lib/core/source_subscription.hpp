#pragma once
// A driver's subscription to another device it is built on (amcl's laser and
// odometry, writelog's sources), undone by destruction: the listener goes
// first, then the subscription. Taking several in turn and failing halfway
// undoes the ones already taken, because they are plain members or vector
// elements that go out of scope.

#include <string_view>

#include "core/device.hpp"

namespace playerkit::core {

class SourceSubscription {
 public:
  SourceSubscription() = default;
  // Adds `listener` (may be null) before subscribing, since a source may
  // publish from its setup() on. Throws DriverError "<owner>: <source> could
  // not be set up" when the source refuses.
  SourceSubscription(Device& source, DeviceListener* listener, std::string_view owner);
  SourceSubscription(SourceSubscription&& other) noexcept;
  SourceSubscription& operator=(SourceSubscription&& other) noexcept;
  SourceSubscription(const SourceSubscription&) = delete;
  SourceSubscription& operator=(const SourceSubscription&) = delete;
  ~SourceSubscription();

  // Stops notifications but keeps the source subscribed (a recorder that
  // drains what arrived before letting go).
  void stop_listening();
  // Unsubscribes now; afterwards the object is empty.
  void reset();

  [[nodiscard]] Device* device() const { return source_; }
  [[nodiscard]] explicit operator bool() const { return source_ != nullptr; }

 private:
  Device* source_ = nullptr;
  DeviceListener* listener_ = nullptr;
};

}  // namespace playerkit::core
