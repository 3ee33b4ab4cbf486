#include "localization/estimate_writer.hpp"

#include <cmath>
#include <cstdio>

#include "localization/localize_wire.hpp"
#include "log/text_log_writer.hpp"
#include "protocol/binary_codec.hpp"
#include "protocol/interfaces.hpp"

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
                               "\"std_y\":%.4f,\"std_yaw\":%.5f,\"particles\":%zu,\"cov_xy\":%.8f}\n"
                             : "%.6f,%.4f,%.4f,%.5f,%.4f,%.4f,%.5f,%zu,%.8f\n";
  std::snprintf(line, sizeof line, pattern, row.time, mean.x, mean.y, mean.yaw, sd(0), sd(1), sd(2),
                row.particles, covariance(0, 1));
  out << line;
}

// The host field of the log lines: where the estimate came from.
constexpr const char* kLogHost = "amcl-offline";

}  // namespace

EstimateWriter::EstimateWriter(std::ostream& out, EstimateFormat format) : out_(out), format_(format) {
  if (format_ == EstimateFormat::csv) out_ << "time,x,y,yaw,std_x,std_y,std_yaw,particles,cov_xy\n";
  if (format_ == EstimateFormat::player_log) out_ << log::log_file_header();
}

void EstimateWriter::write(const LocalizedScan& row) {
  if (format_ != EstimateFormat::player_log) {
    write_row(out_, row, format_ == EstimateFormat::json);
    return;
  }
  const protocol::Timestamp time = protocol::Timestamp::from_seconds(row.time);
  protocol::Message message;
  message.header = protocol::make_header(protocol::MessageType::kData, {protocol::kLocalizeCode, 0}, time, time);
  message.payload = protocol::encode(localize_data({&row.estimate, 1}, 0, time));
  out_ << log::format_data_line(message, kLogHost, protocol::kDefaultPort);
}

}  // namespace playerkit::localization
