#include "log/text_log_reader.hpp"
#include "log/text_log_units.hpp"

#include <array>
#include <cmath>
#include <limits>
#include <numbers>
#include <utility>
#include <vector>

#include "log/log_line.hpp"
#include "log/text_log_extensions.hpp"
#include "log/text_log_fields.hpp"
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

using protocol::kLaserMaxSamples;

// File units to wire units.
constexpr double kCmPerM = 100.0;
constexpr double kHundredthDegPerRad = 100.0 * kDegPerRad;
constexpr double kGpsUnitsPerDeg = 60.0 * 60.0 * 60.0;
constexpr double kHdopWirePerHdop = 10.0;
// 1.5 wrote the gps time as time_sec + time_sec * 1e-6; dividing undoes it.
constexpr double kGpsTimePerWrittenTime = 1.0 / (1.0 + 1e-6);

constexpr std::size_t kPrefixFields = 6;

std::vector<std::uint8_t> laser_payload(const LineFields& fields) {
  protocol::LaserData scan;
  scan.min_angle = fields.wire<std::int16_t>(6, "min_angle", kHundredthDegPerRad, "0.01 deg");
  scan.max_angle = fields.wire<std::int16_t>(7, "max_angle", kHundredthDegPerRad, "0.01 deg");
  scan.resolution = fields.wire<std::uint16_t>(8, "resolution", kHundredthDegPerRad, "0.01 deg");
  const auto count = fields.integer<std::uint16_t>(9, "range_count");
  if (count > kLaserMaxSamples) {
    fields.fail(9, "range_count " + std::to_string(count) + " exceeds the " +
                       std::to_string(kLaserMaxSamples) + " readings a laser scan holds");
  }
  scan.range_count = count;
  const std::size_t end = 10 + 2 * std::size_t{count};
  if (fields.size() < end) {
    const std::size_t complete = (fields.size() - 10) / 2;
    fields.fail_at_end("laser line ends after " + std::to_string(complete) + " of its " +
                       std::to_string(count) + " readings (each is a range and an intensity)");
  }
  fields.expect_end(end, "the last of the " + std::to_string(count) + " readings of range_count");

  std::array<double, kLaserMaxSamples> metres{};
  double longest = 0.0;
  std::size_t longest_field = 10;
  for (std::size_t i = 0; i < count; ++i) {
    const std::size_t field = 10 + 2 * i;
    metres[i] = fields.real(field, "range");
    if (metres[i] < 0) fields.fail(field, "range " + fields.text(field) + " m is negative");
    if (metres[i] > longest) {
      longest = metres[i];
      longest_field = field;
    }
    scan.intensity[i] = fields.integer<std::uint8_t>(field + 1, "intensity");
  }
  // The file has no range_res; take the finest that still fits 16 bits.
  constexpr std::uint16_t kRangeResolutions[] = {1, 10, 100};
  for (std::uint16_t range_res : kRangeResolutions) {
    const double units_per_m = kMmPerM / range_res;
    if (std::round(longest * units_per_m) > std::numeric_limits<std::uint16_t>::max()) continue;
    scan.range_res = range_res;
    for (std::size_t i = 0; i < count; ++i) {
      scan.ranges[i] = static_cast<std::uint16_t>(std::round(metres[i] * units_per_m));
    }
    return protocol::encode(scan);
  }
  fields.fail(longest_field, "range " + fields.text(longest_field) +
                                 " m is beyond what a laser scan carries (6553.5 m at range_res 100)");
}

std::vector<std::uint8_t> position_payload(const LineFields& fields) {
  protocol::PositionData pose;
  pose.xpos = fields.wire<std::int32_t>(6, "x", kMmPerM, "mm");
  pose.ypos = fields.wire<std::int32_t>(7, "y", kMmPerM, "mm");
  pose.yaw = fields.wire<std::int32_t>(8, "yaw", kDegPerRad, "deg");
  pose.xspeed = fields.wire<std::int32_t>(9, "xspeed", kMmPerM, "mm/s");
  pose.yspeed = fields.wire<std::int32_t>(10, "yspeed", kMmPerM, "mm/s");
  pose.yawspeed = fields.wire<std::int32_t>(11, "yawspeed", kDegPerRad, "deg/s");
  pose.stall = fields.integer<std::uint8_t>(12, "stall");
  fields.expect_end(13, "stall");
  return protocol::encode(pose);
}

std::vector<std::uint8_t> position3d_payload(const LineFields& fields) {
  protocol::Position3dData pose;
  pose.xpos = fields.wire<std::int32_t>(6, "x", kMmPerM, "mm");
  pose.ypos = fields.wire<std::int32_t>(7, "y", kMmPerM, "mm");
  pose.zpos = fields.wire<std::int32_t>(8, "z", kMmPerM, "mm");
  pose.roll = fields.wire<std::int32_t>(9, "roll", kArcsecPerRad, "arcsec");
  pose.pitch = fields.wire<std::int32_t>(10, "pitch", kArcsecPerRad, "arcsec");
  pose.yaw = fields.wire<std::int32_t>(11, "yaw", kArcsecPerRad, "arcsec");
  pose.xspeed = fields.wire<std::int32_t>(12, "xspeed", kMmPerM, "mm/s");
  pose.yspeed = fields.wire<std::int32_t>(13, "yspeed", kMmPerM, "mm/s");
  pose.zspeed = fields.wire<std::int32_t>(14, "zspeed", kMmPerM, "mm/s");
  pose.rollspeed = fields.wire<std::int32_t>(15, "rollspeed", kArcsecPerRad, "arcsec/s");
  pose.pitchspeed = fields.wire<std::int32_t>(16, "pitchspeed", kArcsecPerRad, "arcsec/s");
  pose.yawspeed = fields.wire<std::int32_t>(17, "yawspeed", kArcsecPerRad, "arcsec/s");
  pose.stall = fields.integer<std::uint8_t>(18, "stall");
  fields.expect_end(19, "stall");
  return protocol::encode(pose);
}

std::vector<std::uint8_t> gps_payload(const LineFields& fields, LogFormatVersion version) {
  protocol::GpsData fix;
  fix.time_sec = fields.wire<std::uint32_t>(6, "time", kGpsTimePerWrittenTime, "s");
  fix.latitude = fields.wire<std::int32_t>(7, "latitude", kGpsUnitsPerDeg, "1/216000 deg");
  fix.longitude = fields.wire<std::int32_t>(8, "longitude", kGpsUnitsPerDeg, "1/216000 deg");
  fix.altitude = fields.wire<std::int32_t>(9, "altitude", kMmPerM, "mm");
  fix.utm_e = fields.wire<std::int32_t>(10, "utm_e", kCmPerM, "cm");
  fix.utm_n = fields.wire<std::int32_t>(11, "utm_n", kCmPerM, "cm");
  fix.hdop = fields.wire<std::uint16_t>(12, "hdop", kHdopWirePerHdop, "hdop/10");
  // 0.2.0 has vdop after hdop; 1.5's gps has no field for it.
  std::size_t next = 13;
  if (version == LogFormatVersion::k0_2_0) fields.real(next++, "vdop");
  fix.err_horz = fields.wire<std::uint32_t>(next, "err_horz", kMmPerM, "mm");
  fix.err_vert = fields.wire<std::uint32_t>(next + 1, "err_vert", kMmPerM, "mm");
  fix.quality = fields.integer<std::uint8_t>(next + 2, "quality");
  fix.num_sats = fields.integer<std::uint8_t>(next + 3, "num_sats");
  fields.expect_end(next + 4, "num_sats");
  return protocol::encode(fix);
}

std::vector<std::uint8_t> truth_payload(const LineFields& fields, LogFormatVersion version) {
  protocol::TruthData pose;
  pose.px = fields.wire<std::int32_t>(6, "x", kMmPerM, "mm");
  pose.py = fields.wire<std::int32_t>(7, "y", kMmPerM, "mm");
  if (version == LogFormatVersion::k0_2_0) {
    // x y z roll pitch yaw: 1.5's planar truth has no z, roll or pitch.
    fields.real(8, "z");
    fields.real(9, "roll");
    fields.real(10, "pitch");
    pose.pa = fields.wire<std::int32_t>(11, "yaw", kDegPerRad, "deg");
    fields.expect_end(12, "yaw");
    return protocol::encode(pose);
  }
  pose.pa = fields.wire<std::int32_t>(8, "heading", kDegPerRad, "deg");
  fields.expect_end(9, "heading");
  return protocol::encode(pose);
}

// 0.2.0: id x y z roll pitch yaw, then six uncertainties, per fiducial (the
// writer's mapping from 1.5's range/bearing, undone).
void read_fiducial_3d(const LineFields& fields, std::size_t first, protocol::FiducialItem& item) {
  item.id = fields.integer<std::int16_t>(first, "id");
  const double x = fields.real(first + 1, "x");
  const double y = fields.real(first + 2, "y");
  fields.real(first + 3, "z");
  fields.real(first + 4, "roll");
  fields.real(first + 5, "pitch");
  const double range_mm = std::round(std::hypot(x, y) * kMmPerM);
  if (range_mm > std::numeric_limits<std::int16_t>::max()) {
    fields.fail(first + 1, "fiducial at " + fields.text(first + 1) + ", " + fields.text(first + 2) +
                               " m is beyond the 32.767 m a 1.5 fiducial range holds");
  }
  item.pose[0] = static_cast<std::int16_t>(range_mm);
  item.pose[1] = static_cast<std::int16_t>(std::round(std::atan2(y, x) * kDegPerRad));
  item.pose[2] = fields.wire<std::int16_t>(first + 6, "yaw", kDegPerRad, "deg");
  item.upose[0] = fields.wire<std::int16_t>(first + 7, "x uncertainty", kMmPerM, "mm");
  item.upose[1] = fields.wire<std::int16_t>(first + 8, "y uncertainty", kDegPerRad, "deg");
  fields.real(first + 9, "z uncertainty");
  fields.real(first + 10, "roll uncertainty");
  fields.real(first + 11, "pitch uncertainty");
  item.upose[2] = fields.wire<std::int16_t>(first + 12, "yaw uncertainty", kDegPerRad, "deg");
}

std::vector<std::uint8_t> fiducial_payload(const LineFields& fields, LogFormatVersion version) {
  protocol::FiducialData seen;
  const std::size_t group = version == LogFormatVersion::k0_2_0 ? 13 : 4;
  const auto count = fields.integer<std::uint16_t>(6, "count");
  if (count > protocol::kFiducialMaxSamples) {
    fields.fail(6, "count " + std::to_string(count) + " exceeds the " +
                       std::to_string(protocol::kFiducialMaxSamples) + " fiducials a scan holds");
  }
  seen.count = count;
  const std::size_t end = 7 + group * std::size_t{count};
  if (fields.size() < end) {
    fields.fail_at_end("fiducial line ends after " + std::to_string((fields.size() - 7) / group) +
                       " of its " + std::to_string(count) +
                       (group == 4 ? " fiducials (each is id, range, bearing, orientation)"
                                   : " fiducials (each is id, x y z roll pitch yaw, 6 uncertainties)"));
  }
  fields.expect_end(end, "the last of the " + std::to_string(count) + " fiducials of count");
  for (std::size_t i = 0; i < count; ++i) {
    const std::size_t first = 7 + group * i;
    if (group == 13) {
      read_fiducial_3d(fields, first, seen.fiducials[i]);
      continue;
    }
    auto& item = seen.fiducials[i];
    item.id = fields.integer<std::int16_t>(first, "id");
    item.pose[0] = fields.wire<std::int16_t>(first + 1, "range", kMmPerM, "mm");
    item.pose[1] = fields.wire<std::int16_t>(first + 2, "bearing", kDegPerRad, "deg");
    item.pose[2] = fields.wire<std::int16_t>(first + 3, "orientation", kDegPerRad, "deg");
  }
  return protocol::encode(seen);
}

std::vector<std::uint8_t> payload_of(std::uint16_t interface, std::string_view name,
                                     const LineFields& fields, LogFormatVersion version) {
  using namespace protocol;
  switch (interface) {
    case kLaserCode: return laser_payload(fields);  // 0.2.0 only adds decimals to the resolution
    case kPositionCode: return position_payload(fields);
    case kPosition3dCode: return position3d_payload(fields);
    case kGpsCode: return gps_payload(fields, version);
    case kTruthCode: return truth_payload(fields, version);
    case kFiducialCode: return fiducial_payload(fields, version);
    default:
      if (is_extension_interface(interface)) return extension_payload(interface, fields);
      fields.fail(kPrefixFields, std::string(name) + " lines carry no data fields in a text log");
  }
}

HeaderLine header_line(const LineFields& fields) {
  if (fields.size() < 3) fields.fail_at_end("a '##' header line needs a name and a value");
  HeaderLine header;
  for (std::size_t i = 1; i + 1 < fields.size(); ++i) {
    if (!header.name.empty()) header.name += ' ';
    header.name += fields.text(i);
  }
  header.value = fields.text(fields.size() - 1);
  header.value_column = fields.column(fields.size() - 1);
  return header;
}

SyncLine sync_line(const LineFields& fields) {
  SyncLine sync;
  sync.server_time = fields.timestamp(0, "server time");
  sync.host = fields.text(1);
  sync.port = fields.integer<std::uint16_t>(2, "port");
  fields.integer<std::uint16_t>(4, "index");
  sync.data_time = fields.timestamp(5, "data time");
  fields.expect_end(kPrefixFields, "the data time (sync lines carry no data)");
  return sync;
}

DataLine data_line(const LineFields& fields, LogFormatVersion version) {
  DataLine data;
  data.server_time = fields.timestamp(0, "server time");
  data.host = fields.text(1);
  data.port = fields.integer<std::uint16_t>(2, "port");
  data.interface_name = fields.text(3);
  data.index = fields.integer<std::uint16_t>(4, "index");
  data.data_time = fields.timestamp(5, "data time");

  const auto* interface = protocol::find_interface(std::string_view(data.interface_name));
  protocol::DeviceAddress address{0, data.index};
  if (interface != nullptr) {
    address.interface = interface->code;
    data.device = address;
  }
  data.message.header = protocol::make_header(protocol::MessageType::kData, address,
                                              data.server_time, data.data_time);
  // Fields of a name we do not know cannot be read; the caller decides what to say.
  if (interface != nullptr && fields.size() > kPrefixFields) {
    data.message.payload = payload_of(interface->code, interface->name, fields, version);
  }
  data.message.header.size = static_cast<std::uint32_t>(data.message.payload.size());
  return data;
}

}  // namespace

LogLine parse_log_line(std::string_view text, std::string_view file, int line_number) {
  return parse_log_line(text, file, line_number, LogFormatVersion::k0_0_0);
}

LogLine parse_log_line(std::string_view text, std::string_view file, int line_number,
                       LogFormatVersion version) {
  const LineFields fields(text, file, line_number);
  if (fields.size() == 0) return SkippedLine{};
  const std::string_view first = fields.text_view(0);
  if (first == "#") return SkippedLine{};
  if (first == "##") return header_line(fields);
  // Every data and sync line starts with the six prefix fields.
  fields.at(kPrefixFields - 1, "the data time (a line starts: time host port interface index time)");
  if (fields.text_view(3) == "sync") return sync_line(fields);
  return data_line(fields, version);
}

TextLogReader::TextLogReader(std::istream& in, std::string file, TextLogReaderOptions options)
    : in_(in), file_(std::move(file)), options_(options) {}

std::optional<std::variant<SyncLine, DataLine>> TextLogReader::next() {
  std::string text;
  bool too_long = false;
  while (read_log_line(in_, text, too_long)) {
    ++line_number_;
    LogLine line;
    try {
      if (too_long) throw too_long_line_error(file_, line_number_);
      line = parse_log_line(text, file_, line_number_, format_version_);
    } catch (const LogParseError& error) {
      if (options_.strict) throw;
      ++malformed_count_;
      if (malformed_lines_.size() < options_.kept_errors) malformed_lines_.emplace_back(error.what());
      continue;
    }
    std::optional<std::variant<SyncLine, DataLine>> timed;
    if (auto* sync = std::get_if<SyncLine>(&line)) timed = std::move(*sync);
    if (auto* data = std::get_if<DataLine>(&line)) timed = std::move(*data);
    if (timed) {
      retime(*timed, timed_lines_++);
      return timed;
    }
    if (auto* header = std::get_if<HeaderLine>(&line)) take_header(*header);
  }
  return std::nullopt;
}

void TextLogReader::retime(std::variant<SyncLine, DataLine>& line, std::size_t ordinal) const {
  if (!options_.clock) return;
  const auto seconds = options_.clock->replacement(ordinal);
  if (!seconds) return;
  const auto time = protocol::Timestamp::from_seconds(*seconds);
  if (auto* sync = std::get_if<SyncLine>(&line)) {
    sync->server_time = time;
    sync->data_time = time;
    return;
  }
  auto& data = std::get<DataLine>(line);
  data.server_time = time;
  data.data_time = time;
  data.message.header.time_sec = time.sec;
  data.message.header.time_usec = time.usec;
  data.message.header.timestamp_sec = time.sec;
  data.message.header.timestamp_usec = time.usec;
}

void TextLogReader::take_header(const HeaderLine& header) {
  if (header.name == "Player version") {
    player_version_ = header.value;
  } else if (header.name == "File version") {
    // Not skipped even when lenient: every line after it would be misread.
    const auto version = parse_format_version(header.value);
    if (!version) {
      throw LogParseError(file_, line_number_, header.value_column,
                          "file version " + header.value +
                              " is not read here: this reader reads 0.0.0 (Player 1.5) and 0.2.0 (1.6.5)");
    }
    format_version_ = *version;
    file_version_ = header.value;
  }
}

}  // namespace playerkit::log
