#include "log/text_log_writer.hpp"
#include "log/text_log_units.hpp"

#include <charconv>
#include <cmath>
#include <cstdint>
#include <numbers>
#include <stdexcept>

#include "log/text_log_extensions.hpp"
#include "log/text_log_printf.hpp"
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

using namespace text_log_units;

// The unit conversions of 1.5's writelog, with its order of operations, so the
// last printed digit rounds the same way it did there.
double cm_to_m(double cm) { return cm / 100.0; }

double seconds(std::uint32_t sec, std::uint32_t usec) {
  return static_cast<double>(sec) + static_cast<double>(usec) * 1e-6;
}

// What "%.3f" prints for mm / 1000.0: a whole number of millimetres has
// exactly three decimals in metres, and a double holds it closely enough
// (below 2^53 / 1000 m) that printf's rounding cannot change a digit.
void append_millimetres_as_metres(std::string& line, std::uint64_t mm) {
  char digits[24];
  const auto end = std::to_chars(digits, digits + sizeof digits, mm / 1000).ptr;
  line.append(digits, end);
  const auto fraction = static_cast<unsigned>(mm % 1000);
  line += '.';
  line += static_cast<char>('0' + fraction / 100);
  line += static_cast<char>('0' + fraction / 10 % 10);
  line += static_cast<char>('0' + fraction % 10);
}

// "%2d" of a value in 0..255.
void append_width_two(std::string& line, unsigned value) {
  if (value < 10) line += ' ';
  char digits[4];
  const auto end = std::to_chars(digits, digits + sizeof digits, value).ptr;
  line.append(digits, end);
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

void check_options(const TextLogWriterOptions& options) {
  if (options.time_decimals != 3 && options.time_decimals != 6) {
    throw std::invalid_argument("text log: time_decimals is " + std::to_string(options.time_decimals) +
                                "; it must be 3 (Player 1.5's milliseconds) or 6 (microseconds)");
  }
}

// 3 decimals: "%014.3f" of sec + usec * 1e-6, rounding as 1.5 did. 6 decimals:
// from the integers, because a double of ~1e9 s has no digit to spare at 1e-6.
void append_time(std::string& line, protocol::Timestamp time, int decimals) {
  if (decimals == 3) {
    append_printf(line, "%014.3f", seconds(time.sec, time.usec));
  } else {
    append_printf(line, "%010u.%06u", time.sec, time.usec);
  }
}

// "%014.3f %s %d %s %02d %014.3f " (or the times with 6 decimals)
std::string common_prefix(protocol::Timestamp server_time, std::string_view host, std::uint16_t port,
                          std::string_view interface, std::uint16_t index, protocol::Timestamp data_time,
                          int decimals) {
  std::string line;
  append_time(line, server_time, decimals);
  line += ' ';
  line += host;
  append_printf(line, " %d ", static_cast<int>(port));
  line += interface;
  append_printf(line, " %02d ", static_cast<int>(index));
  append_time(line, data_time, decimals);
  line += ' ';
  return line;
}

void append_laser(std::string& line, const protocol::LaserData& scan, LogFormatVersion version) {
  append_printf(line, "%+07.4f %+07.4f ", deg_to_rad(scan.min_angle * 0.01), deg_to_rad(scan.max_angle * 0.01));
  // 1.6.5 fixed the resolution's precision with 8 decimals.
  if (version == LogFormatVersion::k0_2_0) {
    append_printf(line, "%+.8f ", deg_to_rad(scan.resolution * 0.01));
  } else {
    append_printf(line, "%+07.4f ", deg_to_rad(scan.resolution * 0.01));
  }
  append_printf(line, "%04d ", static_cast<int>(scan.range_count));
  // "%.3f %2d " per reading, without printf: a scan is most of a log's bytes,
  // and vsnprintf made writing five times slower than reading.
  for (std::size_t i = 0; i < scan.range_count; ++i) {
    const auto scaled_mm = static_cast<std::uint64_t>(scan.ranges[i]) * scan.range_res;
    append_millimetres_as_metres(line, scaled_mm);
    line += ' ';
    append_width_two(line, scan.intensity[i]);
    line += ' ';
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

void append_gps(std::string& line, const protocol::GpsData& fix, LogFormatVersion version) {
  // 1.5's quirk, kept: the time is time_sec plus time_sec (not time_usec) * 1e-6.
  const double quirky_time =
      static_cast<double>(fix.time_sec) + static_cast<double>(fix.time_sec) * 1e-6;
  constexpr double kUnitsPerDegree = 60 * 60 * 60;
  append_printf(line, "%.3f %.6f %.6f %.6f ", quirky_time, fix.latitude / kUnitsPerDegree,
                fix.longitude / kUnitsPerDegree, mm_to_m(fix.altitude));
  append_printf(line, "%.3f %.3f %.3f ", cm_to_m(fix.utm_e), cm_to_m(fix.utm_n), fix.hdop / 10.0);
  // 1.6.5 added vdop after hdop; 1.5's gps has none, so it is written as 0.
  if (version == LogFormatVersion::k0_2_0) append_printf(line, "%.3f ", 0.0);
  append_printf(line, "%.3f %.3f %d %d", mm_to_m(fix.err_horz), mm_to_m(fix.err_vert),
                static_cast<int>(fix.quality), static_cast<int>(fix.num_sats));
}

void append_truth(std::string& line, const protocol::TruthData& pose, LogFormatVersion version) {
  if (version == LogFormatVersion::k0_2_0) {
    // 1.6.5's 3-D pose: x y z roll pitch yaw; 1.5's truth is planar.
    append_printf(line, "%+07.3f %+07.3f %+07.3f %+04.3f %+04.3f %+04.3f", mm_to_m(pose.px), mm_to_m(pose.py),
                  0.0, 0.0, 0.0, deg_to_rad(pose.pa));
    return;
  }
  append_printf(line, "%+07.3f %+07.3f %+04.3f", mm_to_m(pose.px), mm_to_m(pose.py),
                deg_to_rad(pose.pa));
}

// 1.6.5's fiducial: id, 3-D pose x y z roll pitch yaw, then the six
// uncertainties. 1.5's (range, bearing) becomes (x, y); its three uncertainties
// (range m, bearing rad, orientation rad) go in the x, y and yaw slots.
void append_fiducial_3d(std::string& line, const protocol::FiducialData& seen) {
  append_printf(line, "%d", static_cast<int>(seen.count));
  for (std::size_t i = 0; i < seen.count; ++i) {
    const auto& item = seen.fiducials[i];
    const double range = mm_to_m(item.pose[0]);
    const double bearing = deg_to_rad(item.pose[1]);
    append_printf(line, " %d %+07.4f %+07.4f %+07.4f %+04.3f %+04.3f %+04.3f", static_cast<int>(item.id),
                  range * std::cos(bearing), range * std::sin(bearing), 0.0, 0.0, 0.0, deg_to_rad(item.pose[2]));
    append_printf(line, " %+07.3f %+04.3f %+07.3f %+04.3f %+04.3f %+04.3f", mm_to_m(item.upose[0]),
                  deg_to_rad(item.upose[1]), 0.0, 0.0, 0.0, deg_to_rad(item.upose[2]));
  }
}

void append_fiducial(std::string& line, const protocol::FiducialData& seen, LogFormatVersion version) {
  if (version == LogFormatVersion::k0_2_0) {
    append_fiducial_3d(line, seen);
    return;
  }
  append_printf(line, "%d", static_cast<int>(seen.count));
  for (std::size_t i = 0; i < seen.count; ++i) {
    const auto& item = seen.fiducials[i];
    append_printf(line, " %d %+07.3f %+07.3f %+04.3f", static_cast<int>(item.id),
                  mm_to_m(item.pose[0]), deg_to_rad(item.pose[1]), deg_to_rad(item.pose[2]));
  }
}

void append_fields(std::string& line, std::uint16_t interface, std::span<const std::uint8_t> payload,
                   LogFormatVersion version) {
  using namespace protocol;
  switch (interface) {
    case kLaserCode: append_laser(line, decode<LaserData>(payload), version); break;
    case kPositionCode: append_position(line, decode<PositionData>(payload)); break;
    case kPosition3dCode: append_position3d(line, decode<Position3dData>(payload)); break;
    case kGpsCode: append_gps(line, decode<GpsData>(payload), version); break;
    case kTruthCode: append_truth(line, decode<TruthData>(payload), version); break;
    case kFiducialCode: append_fiducial(line, decode<FiducialData>(payload), version); break;
    default: append_extension_fields(line, interface, payload); break;  // nothing for the rest
  }
}

}  // namespace

std::string log_file_header(const TextLogWriterOptions& options) {
  if (options.version == LogFormatVersion::k0_2_0) return "## Player version 1.6.5 \n## File version 0.2.0 \n";
  return "## Player version 1.5 \n## File version 0.0.0 \n";
}

std::string format_data_line(const protocol::Message& message, std::string_view host,
                             std::uint16_t port, const TextLogWriterOptions& options) {
  check_options(options);
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
  std::string line = common_prefix(message.time(), host, port, interface->name, device.index,
                                   message.timestamp(), options.time_decimals);
  if (!message.payload.empty()) append_fields(line, device.interface, message.payload, options.version);
  line += '\n';
  return line;
}

std::string format_sync_line(protocol::Timestamp time, std::string_view host, std::uint16_t port,
                             const TextLogWriterOptions& options) {
  check_options(options);
  check_host(host);
  return common_prefix(time, host, port, "sync", 0, time, options.time_decimals) + '\n';
}

std::string format_sync_line(double time, std::string_view host, std::uint16_t port,
                             const TextLogWriterOptions& options) {
  check_options(options);
  check_host(host);
  if (options.time_decimals == 3) {
    // 1.5 printed the double itself; keep its rounding byte for byte.
    std::string line;
    append_printf(line, "%014.3f ", time);
    line += host;
    append_printf(line, " %d sync 00 %014.3f \n", static_cast<int>(port), time);
    return line;
  }
  return format_sync_line(protocol::Timestamp::from_seconds(time), host, port, options);
}

}  // namespace playerkit::log
