#include "log/text_log_writer.hpp"

#include <cstdarg>
#include <cstdio>
#include <numbers>
#include <stdexcept>

#include "protocol/binary_codec.hpp"
#include "protocol/interfaces.hpp"
#include "protocol/messages/fiducial.hpp"
#include "protocol/messages/gps.hpp"
#include "protocol/messages/laser.hpp"
#include "protocol/messages/position.hpp"
#include "protocol/messages/position3d.hpp"
#include "protocol/messages/truth.hpp"

namespace playerkit::log {
namespace {

// printf into a string, so every field keeps the exact pattern writelog used;
// the attribute keeps the compiler checking each pattern against its arguments.
__attribute__((format(printf, 2, 3))) void append_printf(std::string& out, const char* pattern, ...) {
  char buffer[128];
  std::va_list args;
  va_start(args, pattern);
  const int length = std::vsnprintf(buffer, sizeof buffer, pattern, args);
  va_end(args);
  if (length < 0) throw std::runtime_error("text log: cannot format a field");
  if (static_cast<std::size_t>(length) < sizeof buffer) {
    out.append(buffer, static_cast<std::size_t>(length));
    return;
  }
  // Only a huge number gets here; format again with room for it.
  std::string wide(static_cast<std::size_t>(length) + 1, '\0');
  va_start(args, pattern);
  std::vsnprintf(wide.data(), wide.size(), pattern, args);
  va_end(args);
  wide.resize(static_cast<std::size_t>(length));
  out += wide;
}

// The unit conversions of 1.5's writelog, with its order of operations, so the
// last printed digit rounds the same way it did there.
double mm_to_m(double mm) { return mm / 1000.0; }
double cm_to_m(double cm) { return cm / 100.0; }
double deg_to_rad(double deg) { return deg * std::numbers::pi / 180.0; }

double seconds(std::uint32_t sec, std::uint32_t usec) {
  return static_cast<double>(sec) + static_cast<double>(usec) * 1e-6;
}

void check_host(std::string_view host) {
  if (host.empty()) throw std::invalid_argument("text log: the host name is empty");
  for (char c : host) {
    if (c == ' ' || c == '\t' || c == '\n' || c == '\r' || c == '\v' || c == '\f') {
      throw std::invalid_argument("text log: host name '" + std::string(host) +
                                  "' holds whitespace, which would split it into two fields");
    }
  }
}

// "%014.3f %s %d %s %02d %014.3f "
std::string common_prefix(double server_time, std::string_view host, std::uint16_t port,
                          std::string_view interface, std::uint16_t index, double data_time) {
  std::string line;
  append_printf(line, "%014.3f ", server_time);
  line += host;
  append_printf(line, " %d ", static_cast<int>(port));
  line += interface;
  append_printf(line, " %02d %014.3f ", static_cast<int>(index), data_time);
  return line;
}

void append_laser(std::string& line, const protocol::LaserData& scan) {
  append_printf(line, "%+07.4f %+07.4f %+07.4f %04d ", deg_to_rad(scan.min_angle * 0.01),
                deg_to_rad(scan.max_angle * 0.01), deg_to_rad(scan.resolution * 0.01),
                static_cast<int>(scan.range_count));
  for (std::size_t i = 0; i < scan.range_count; ++i) {
    const auto scaled_mm = static_cast<std::uint32_t>(scan.ranges[i]) * scan.range_res;
    append_printf(line, "%.3f %2d ", mm_to_m(scaled_mm), static_cast<int>(scan.intensity[i]));
  }
}

void append_position(std::string& line, const protocol::PositionData& pose) {
  append_printf(line, "%+07.3f %+07.3f %+04.3f %+07.3f %+07.3f %+07.3f %d", mm_to_m(pose.xpos),
                mm_to_m(pose.ypos), deg_to_rad(pose.yaw), mm_to_m(pose.xspeed),
                mm_to_m(pose.yspeed), deg_to_rad(pose.yawspeed), static_cast<int>(pose.stall));
}

double arcsec_to_rad(std::int32_t arcsec) { return deg_to_rad(arcsec / 3600.0); }

void append_position3d(std::string& line, const protocol::Position3dData& pose) {
  append_printf(line, "%+.4f %+.4f %+.4f %+.4f %+.4f %+.4f ", mm_to_m(pose.xpos),
                mm_to_m(pose.ypos), mm_to_m(pose.zpos), arcsec_to_rad(pose.roll),
                arcsec_to_rad(pose.pitch), arcsec_to_rad(pose.yaw));
  append_printf(line, "%+.4f %+.4f %+.4f %+.4f %+.4f %+.4f %d", mm_to_m(pose.xspeed),
                mm_to_m(pose.yspeed), mm_to_m(pose.zspeed), arcsec_to_rad(pose.rollspeed),
                arcsec_to_rad(pose.pitchspeed), arcsec_to_rad(pose.yawspeed),
                static_cast<int>(pose.stall));
}

void append_gps(std::string& line, const protocol::GpsData& fix) {
  // 1.5's quirk, kept: the time is time_sec plus time_sec (not time_usec) * 1e-6.
  const double quirky_time =
      static_cast<double>(fix.time_sec) + static_cast<double>(fix.time_sec) * 1e-6;
  constexpr double kUnitsPerDegree = 60 * 60 * 60;
  append_printf(line, "%.3f %.6f %.6f %.6f ", quirky_time, fix.latitude / kUnitsPerDegree,
                fix.longitude / kUnitsPerDegree, mm_to_m(fix.altitude));
  append_printf(line, "%.3f %.3f %.3f %.3f %.3f %d %d", cm_to_m(fix.utm_e), cm_to_m(fix.utm_n),
                fix.hdop / 10.0, mm_to_m(fix.err_horz), mm_to_m(fix.err_vert),
                static_cast<int>(fix.quality), static_cast<int>(fix.num_sats));
}

void append_truth(std::string& line, const protocol::TruthData& pose) {
  append_printf(line, "%+07.3f %+07.3f %+04.3f", mm_to_m(pose.px), mm_to_m(pose.py),
                deg_to_rad(pose.pa));
}

void append_fiducial(std::string& line, const protocol::FiducialData& seen) {
  append_printf(line, "%d", static_cast<int>(seen.count));
  for (std::size_t i = 0; i < seen.count; ++i) {
    const auto& item = seen.fiducials[i];
    append_printf(line, " %d %+07.3f %+07.3f %+04.3f", static_cast<int>(item.id),
                  mm_to_m(item.pose[0]), deg_to_rad(item.pose[1]), deg_to_rad(item.pose[2]));
  }
}

void append_fields(std::string& line, std::uint16_t interface, std::span<const std::uint8_t> payload) {
  using namespace protocol;
  switch (interface) {
    case kLaserCode: append_laser(line, decode<LaserData>(payload)); break;
    case kPositionCode: append_position(line, decode<PositionData>(payload)); break;
    case kPosition3dCode: append_position3d(line, decode<Position3dData>(payload)); break;
    case kGpsCode: append_gps(line, decode<GpsData>(payload)); break;
    case kTruthCode: append_truth(line, decode<TruthData>(payload)); break;
    case kFiducialCode: append_fiducial(line, decode<FiducialData>(payload)); break;
    default: break;  // 1.5 writes no fields for the other interfaces
  }
}

}  // namespace

std::string log_file_header() { return "## Player version 1.5 \n## File version 0.0.0 \n"; }

std::string format_data_line(const protocol::Message& message, std::string_view host,
                             std::uint16_t port) {
  if (message.type() != protocol::MessageType::kData) {
    throw std::invalid_argument(std::string("text log: only data messages have log lines, not '") +
                                std::string(protocol::to_string(message.type())) + "'");
  }
  check_host(host);
  const auto device = message.device();
  const auto* interface = protocol::find_interface(device.interface);
  if (interface == nullptr) {
    throw std::invalid_argument("text log: interface code " + std::to_string(device.interface) +
                                " is not a Player 1.5 interface, and log lines name interfaces");
  }
  const auto& header = message.header;
  std::string line =
      common_prefix(seconds(header.time_sec, header.time_usec), host, port, interface->name,
                    device.index, seconds(header.timestamp_sec, header.timestamp_usec));
  if (!message.payload.empty()) append_fields(line, device.interface, message.payload);
  line += '\n';
  return line;
}

std::string format_sync_line(double time, std::string_view host, std::uint16_t port) {
  check_host(host);
  return common_prefix(time, host, port, "sync", 0, time) + '\n';
}

}  // namespace playerkit::log
