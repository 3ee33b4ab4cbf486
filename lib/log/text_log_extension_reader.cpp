#include <cmath>
#include <limits>
#include <numbers>

#include "log/text_log_extensions.hpp"
#include "log/text_log_units.hpp"
#include "protocol/binary_codec.hpp"
#include "protocol/interfaces.hpp"
#include "protocol/messages/blobfinder.hpp"
#include "protocol/messages/bumper.hpp"
#include "protocol/messages/ir.hpp"
#include "protocol/messages/localize.hpp"
#include "protocol/messages/power.hpp"
#include "protocol/messages/ptz.hpp"
#include "protocol/messages/sonar.hpp"
#include "protocol/messages/wifi.hpp"

namespace playerkit::log {
namespace {

using namespace text_log_units;

constexpr std::size_t kFirst = 6;  // the first field after the prefix

// A leading count at `i`, at most `max`, followed by exactly count groups of
// `group` fields: the number of items.
std::size_t counted_items(const LineFields& fields, std::size_t i, std::string_view what, std::size_t max,
                          std::size_t group, std::string_view item) {
  const auto count = fields.integer<std::uint32_t>(i, what);
  if (count > max) {
    fields.fail(i, std::string(what) + " " + std::to_string(count) + " exceeds the " + std::to_string(max) +
                       " the message holds");
  }
  const std::size_t end = i + 1 + group * count;
  if (fields.size() < end) {
    fields.fail_at_end("line ends after " + std::to_string((fields.size() - i - 1) / group) + " of its " +
                       std::to_string(count) + " " + std::string(item));
  }
  fields.expect_end(end, "the last of the " + std::to_string(count) + " " + std::string(item));
  return count;
}

std::vector<std::uint8_t> wifi_payload(const LineFields& fields) {
  protocol::WifiData wifi;
  const std::size_t groups = (fields.size() - kFirst) / 4;
  if ((fields.size() - kFirst) % 4 != 0) {
    fields.fail_at_end("wifi fields come in groups of 4 (ip qual level noise); the last group has " +
                       std::to_string((fields.size() - kFirst) % 4));
  }
  if (groups > protocol::kWifiMaxLinks) {
    fields.fail(kFirst + 4 * protocol::kWifiMaxLinks,
                "more than the " + std::to_string(protocol::kWifiMaxLinks) + " links a wifi message holds");
  }
  wifi.link_count = static_cast<std::uint16_t>(groups);
  for (std::size_t g = 0; g < groups; ++g) {
    const std::size_t first = kFirst + 4 * g;
    auto& link = wifi.links[g];
    const auto ip = fields.text_view(first);
    if (ip.size() >= link.ip.kCapacity) {
      fields.fail(first, "wifi ip of " + std::to_string(ip.size()) + " characters does not fit its 32-byte field");
    }
    link.ip = ip == "-" ? std::string_view() : ip;
    link.qual = fields.integer<std::uint16_t>(first + 1, "qual");
    link.level = fields.integer<std::uint16_t>(first + 2, "level");
    link.noise = fields.integer<std::uint16_t>(first + 3, "noise");
  }
  return protocol::encode(wifi);
}

std::vector<std::uint8_t> sonar_payload(const LineFields& fields) {
  protocol::SonarData sonar;
  const auto count = counted_items(fields, kFirst, "range_count", protocol::kSonarMaxSamples, 1, "ranges");
  sonar.range_count = static_cast<std::uint16_t>(count);
  for (std::size_t i = 0; i < count; ++i) {
    sonar.ranges[i] = fields.wire<std::uint16_t>(kFirst + 1 + i, "range", kMmPerM, "mm");
  }
  return protocol::encode(sonar);
}

std::vector<std::uint8_t> ir_payload(const LineFields& fields) {
  protocol::IrData ir;
  const auto count = counted_items(fields, kFirst, "range_count", protocol::kIrMaxSamples, 2,
                                   "samples (each is a range and a voltage)");
  ir.range_count = static_cast<std::uint16_t>(count);
  for (std::size_t i = 0; i < count; ++i) {
    ir.ranges[i] = fields.wire<std::uint16_t>(kFirst + 1 + 2 * i, "range", kMmPerM, "mm");
    ir.voltages[i] = fields.integer<std::uint16_t>(kFirst + 2 + 2 * i, "voltage");
  }
  return protocol::encode(ir);
}

std::vector<std::uint8_t> power_payload(const LineFields& fields) {
  protocol::PowerData power;
  power.charge = fields.wire<std::uint16_t>(kFirst, "volts", 10.0, "0.1 V");
  fields.expect_end(kFirst + 1, "volts");
  return protocol::encode(power);
}

std::vector<std::uint8_t> bumper_payload(const LineFields& fields) {
  protocol::BumperData bumper;
  const auto count = counted_items(fields, kFirst, "bumper_count", protocol::kBumperMaxSamples, 1, "bumpers");
  bumper.bumper_count = static_cast<std::uint8_t>(count);
  for (std::size_t i = 0; i < count; ++i) bumper.bumpers[i] = fields.integer<std::uint8_t>(kFirst + 1 + i, "bumper");
  return protocol::encode(bumper);
}

std::vector<std::uint8_t> ptz_payload(const LineFields& fields) {
  protocol::PtzData ptz;
  ptz.pan = fields.wire<std::int16_t>(kFirst, "pan", kDegPerRad, "deg");
  ptz.tilt = fields.wire<std::int16_t>(kFirst + 1, "tilt", kDegPerRad, "deg");
  ptz.zoom = fields.wire<std::int16_t>(kFirst + 2, "zoom", kDegPerRad, "deg");
  ptz.panspeed = fields.wire<std::int16_t>(kFirst + 3, "panspeed", kDegPerRad, "deg/s");
  ptz.tiltspeed = fields.wire<std::int16_t>(kFirst + 4, "tiltspeed", kDegPerRad, "deg/s");
  fields.expect_end(kFirst + 5, "tiltspeed");
  return protocol::encode(ptz);
}

std::int64_t covariance(const LineFields& fields, std::size_t i, double wire_per_si) {
  const double value = std::round(fields.scientific(i, "covariance") * wire_per_si);
  // 2^63 as a double; anything at or beyond it does not fit int64.
  constexpr double kLimit = 9223372036854775808.0;
  if (!(value < kLimit && value >= -kLimit)) {
    fields.fail(i, "covariance " + fields.text(i) + " does not fit the wire's 64-bit field");
  }
  return static_cast<std::int64_t>(value);
}

std::vector<std::uint8_t> localize_payload(const LineFields& fields) {
  protocol::LocalizeData localize;
  localize.pending_count = fields.integer<std::uint16_t>(kFirst, "pending_count");
  const auto pending_time = fields.timestamp(kFirst + 1, "pending_time");
  localize.pending_time_sec = pending_time.sec;
  localize.pending_time_usec = pending_time.usec;
  constexpr std::size_t kGroup = 13;  // x y yaw, 9 covariances, alpha
  const auto count = counted_items(fields, kFirst + 2, "hypoth_count", protocol::kLocalizeMaxHypoths, kGroup,
                                   "hypotheses (each is x y yaw, 9 covariances, alpha)");
  localize.hypoth_count = static_cast<std::uint32_t>(count);
  const double wire_per_si[3] = {kMmPerM, kMmPerM, kArcsecPerRad};
  for (std::size_t h = 0; h < count; ++h) {
    const std::size_t first = kFirst + 3 + kGroup * h;
    auto& hypothesis = localize.hypoths[h];
    hypothesis.mean[0] = fields.wire<std::int32_t>(first, "x", kMmPerM, "mm");
    hypothesis.mean[1] = fields.wire<std::int32_t>(first + 1, "y", kMmPerM, "mm");
    hypothesis.mean[2] = fields.wire<std::int32_t>(first + 2, "yaw", kArcsecPerRad, "arcsec");
    for (std::size_t r = 0; r < 3; ++r) {
      for (std::size_t c = 0; c < 3; ++c) {
        hypothesis.cov[r][c] = covariance(fields, first + 3 + 3 * r + c, wire_per_si[r] * wire_per_si[c]);
      }
    }
    hypothesis.alpha = fields.wire<std::uint32_t>(first + 12, "alpha", 1e6, "1e-6");
  }
  return protocol::encode(localize);
}

std::vector<std::uint8_t> blobfinder_payload(const LineFields& fields) {
  protocol::BlobfinderData seen;
  seen.width = fields.integer<std::uint16_t>(kFirst, "width");
  seen.height = fields.integer<std::uint16_t>(kFirst + 1, "height");
  constexpr std::size_t kGroup = 10;
  const auto count = counted_items(fields, kFirst + 2, "blob_count", protocol::kBlobfinderMaxBlobs, kGroup,
                                   "blobs (each is channel color area x y left right top bottom range)");
  std::size_t channel = 0;
  for (std::size_t b = 0; b < count; ++b) {
    const std::size_t first = kFirst + 3 + kGroup * b;
    const auto this_channel = fields.integer<std::uint8_t>(first, "channel");
    if (this_channel >= protocol::kBlobfinderMaxChannels) {
      fields.fail(first, "channel " + fields.text(first) + " is beyond the " +
                             std::to_string(protocol::kBlobfinderMaxChannels) + " channels");
    }
    if (this_channel < channel) {
      fields.fail(first, "blobs must come grouped by channel in ascending order; channel " + fields.text(first) +
                             " follows channel " + std::to_string(channel));
    }
    channel = this_channel;
    seen.header[channel].num = static_cast<std::uint16_t>(seen.header[channel].num + 1);
    protocol::BlobfinderBlob blob;
    blob.color = fields.integer<std::uint32_t>(first + 1, "color");
    blob.area = fields.integer<std::uint32_t>(first + 2, "area");
    blob.x = fields.integer<std::uint16_t>(first + 3, "x");
    blob.y = fields.integer<std::uint16_t>(first + 4, "y");
    blob.left = fields.integer<std::uint16_t>(first + 5, "left");
    blob.right = fields.integer<std::uint16_t>(first + 6, "right");
    blob.top = fields.integer<std::uint16_t>(first + 7, "top");
    blob.bottom = fields.integer<std::uint16_t>(first + 8, "bottom");
    blob.range = fields.wire<std::uint16_t>(first + 9, "range", kMmPerM, "mm");
    seen.blobs.push_back(blob);
  }
  // Each channel's blobs start where the lower channels' end.
  std::uint16_t offset = 0;
  for (auto& entry : seen.header) {
    entry.index = offset;
    offset = static_cast<std::uint16_t>(offset + entry.num);
  }
  return protocol::encode(seen);
}

}  // namespace

std::vector<std::uint8_t> extension_payload(std::uint16_t interface, const LineFields& fields) {
  using namespace protocol;
  switch (interface) {
    case kWifiCode: return wifi_payload(fields);
    case kSonarCode: return sonar_payload(fields);
    case kIrCode: return ir_payload(fields);
    case kPowerCode: return power_payload(fields);
    case kBumperCode: return bumper_payload(fields);
    case kLocalizeCode: return localize_payload(fields);
    case kPtzCode: return ptz_payload(fields);
    case kBlobfinderCode: return blobfinder_payload(fields);
    default: fields.fail(kFirst, "not an extension interface");
  }
}

}  // namespace playerkit::log
