#pragma once
// The pose from the RMP's fore/aft and yaw displacement counters
// (segwayrmp.md §3): the first set after a start or a reset only records
// the counters; each later one moves the pose by the counters' change, the
// shorter way round their 32-bit wrap.

#include <cstdint>
#include <optional>

namespace playerkit::hardware::segwayrmp {

struct OdometryPose {
  double x = 0;      // m
  double y = 0;      // m
  double theta = 0;  // rad, [0, 2π)
};

class RmpOdometry {
 public:
  // The pose after this set of counters.
  const OdometryPose& update(std::uint32_t fore_aft, std::uint32_t yaw);
  // Back to (0, 0, 0); the next counters are the new origin.
  void reset();
  // The pose kept, the next counters taken as the origin (a robot found
  // again may have restarted them).
  void forget_counters() { last_.reset(); }
  [[nodiscard]] const OdometryPose& pose() const { return pose_; }

 private:
  struct Counters {
    std::uint32_t fore_aft;
    std::uint32_t yaw;
  };
  OdometryPose pose_;
  std::optional<Counters> last_;
};

// b - a taken the shorter way round a 32-bit counter.
[[nodiscard]] std::int64_t counter_change(std::uint32_t from, std::uint32_t to);

}  // namespace playerkit::hardware::segwayrmp
