#pragma once
// A driver's subscription to another device it is built on (amcl's laser and
// odometry, writelog's sources), undone by destruction: the listener goes
// first, then the subscription. Taking several in turn and failing halfway
// undoes the ones already taken, because they are plain members or vector
// elements that go out of scope.

#include <cstdint>
#include <string_view>

#include "core/device.hpp"
#include "core/device_table.hpp"

namespace playerkit::core {

// The device a driver is built on: `interface`:`index` on the port of the
// driver's own device `self`, as 1.5's `*_index` options named it. Throws
// DriverError saying it is `self` itself ("<option> N is this device
// itself") or missing ("no laser:2 on port 6665 to <purpose>").
Device& source_device(const DeviceTable& devices, const Device& self, std::uint16_t interface, int index,
                      std::string_view option, std::string_view purpose);

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
