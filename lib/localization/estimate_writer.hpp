#pragma once
// The rows `amcl-offline localize` prints: one per scan, in metres and
// radians. CSV with the header `time,x,y,yaw,std_x,std_y,std_yaw,particles,cov_xy`
// (cov_xy in m^2, last so that scripts reading the first eight by position
// still work), JSON lines with the same keys, or a Player 1.5 text log of localize:0 data
// (one hypothesis per line, wire units) that player-log and readlog read.

#include <ostream>

#include "localization/offline_localizer.hpp"

namespace playerkit::localization {

enum class EstimateFormat { csv, json, player_log };

class EstimateWriter {
 public:
  // CSV and the Player log write their headers at once.
  EstimateWriter(std::ostream& out, EstimateFormat format);
  void write(const LocalizedScan& row);

 private:
  std::ostream& out_;
  EstimateFormat format_;
};

}  // namespace playerkit::localization
