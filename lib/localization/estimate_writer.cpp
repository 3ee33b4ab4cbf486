#include "localization/estimate_writer.hpp"

#include <cmath>
#include <cstdio>

namespace playerkit::localization {

namespace {

// Enough digits for millimetres and milliradians after hours of log time,
// without printing float noise.
void write_row(std::ostream& out, const LocalizedScan& row, bool json) {
  const auto& mean = row.estimate.mean;
  const auto& covariance = row.estimate.covariance;
  const auto sd = [&](int i) { return std::sqrt(std::max(0.0, covariance(i, i))); };
  char line[256];
  const char* pattern = json ? "{\"time\":%.6f,\"x\":%.4f,\"y\":%.4f,\"yaw\":%.5f,\"std_x\":%.4f,"
                               "\"std_y\":%.4f,\"std_yaw\":%.5f,\"particles\":%zu}\n"
                             : "%.6f,%.4f,%.4f,%.5f,%.4f,%.4f,%.5f,%zu\n";
  std::snprintf(line, sizeof line, pattern, row.time, mean.x, mean.y, mean.yaw, sd(0), sd(1), sd(2),
                row.particles);
  out << line;
}

}  // namespace

EstimateWriter::EstimateWriter(std::ostream& out, EstimateFormat format) : out_(out), format_(format) {
  if (format_ == EstimateFormat::csv) out_ << "time,x,y,yaw,std_x,std_y,std_yaw,particles\n";
}

void EstimateWriter::write(const LocalizedScan& row) { write_row(out_, row, format_ == EstimateFormat::json); }

}  // namespace playerkit::localization
