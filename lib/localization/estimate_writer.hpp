#pragma once
// The rows `amcl-offline localize` prints: one per scan, in metres and
// radians. CSV with the header `time,x,y,yaw,std_x,std_y,std_yaw,particles`,
// or JSON lines with the same keys.

#include <ostream>

#include "localization/offline_localizer.hpp"

namespace playerkit::localization {

enum class EstimateFormat { csv, json };

class EstimateWriter {
 public:
  // CSV writes its header at once.
  EstimateWriter(std::ostream& out, EstimateFormat format);
  void write(const LocalizedScan& row);

 private:
  std::ostream& out_;
  EstimateFormat format_;
};

}  // namespace playerkit::localization
