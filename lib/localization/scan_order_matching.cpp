#include "localization/scan_order_matching.hpp"

#include <stdexcept>
#include <string>

namespace playerkit::localization {

Trajectory retimed_by_scan_order(const Trajectory& estimate, const Trajectory& truth) {
  if (estimate.size() != truth.size()) {
    throw std::invalid_argument("cannot match by scan order: " + std::to_string(estimate.size()) +
                                " estimates for " + std::to_string(truth.size()) + " scans with a true pose");
  }
  Trajectory retimed = estimate;
  for (std::size_t k = 0; k < retimed.size(); ++k) retimed[k].time = truth[k].time;
  return retimed;
}

}  // namespace playerkit::localization
