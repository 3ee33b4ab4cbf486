#include <numbers>
#include <stdexcept>

#include "log/text_log_extensions.hpp"
#include "log/text_log_units.hpp"
#include "log/text_log_printf.hpp"
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

double arcsec_to_rad(double arcsec) { return deg_to_rad(arcsec / 3600.0); }

void append_wifi(std::string& line, const protocol::WifiData& wifi) {
  // Exactly the groups 1.5's readlog parses: ip qual level noise per link, no count.
  for (std::size_t i = 0; i < wifi.link_count && i < wifi.links.size(); ++i) {
    const auto& link = wifi.links[i];
    const auto ip = link.ip.view();
    for (char c : ip) {
      if (c == ' ' || c == '\t' || c == '\n' || c == '\r' || c == '\v' || c == '\f') {
        throw std::invalid_argument("text log: wifi ip '" + std::string(ip) +
                                    "' holds whitespace, which would split it into two fields");
      }
    }
    if (ip == "-") throw std::invalid_argument("text log: wifi ip '-' is how an empty ip is written");
    if (i > 0) line += ' ';
    line += ip.empty() ? std::string_view("-") : ip;
    append_printf(line, " %d %d %d", static_cast<int>(link.qual), static_cast<int>(link.level),
                  static_cast<int>(link.noise));
  }
}

void append_sonar(std::string& line, const protocol::SonarData& sonar) {
  append_printf(line, "%d", static_cast<int>(sonar.range_count));
  for (std::size_t i = 0; i < sonar.range_count; ++i) append_printf(line, " %.3f", mm_to_m(sonar.ranges[i]));
}

void append_ir(std::string& line, const protocol::IrData& ir) {
  append_printf(line, "%d", static_cast<int>(ir.range_count));
  for (std::size_t i = 0; i < ir.range_count; ++i) {
    append_printf(line, " %.3f %d", mm_to_m(ir.ranges[i]), static_cast<int>(ir.voltages[i]));
  }
}

void append_power(std::string& line, const protocol::PowerData& power) {
  append_printf(line, "%.1f", power.charge / 10.0);  // volts, as 1.6.5 wrote them
}

void append_bumper(std::string& line, const protocol::BumperData& bumper) {
  append_printf(line, "%d", static_cast<int>(bumper.bumper_count));
  for (std::size_t i = 0; i < bumper.bumper_count; ++i) append_printf(line, " %d", static_cast<int>(bumper.bumpers[i]));
}

void append_ptz(std::string& line, const protocol::PtzData& ptz) {
  append_printf(line, "%+.4f %+.4f %+.4f %+.4f %+.4f", deg_to_rad(ptz.pan), deg_to_rad(ptz.tilt),
                deg_to_rad(ptz.zoom), deg_to_rad(ptz.panspeed), deg_to_rad(ptz.tiltspeed));
}

void append_localize(std::string& line, const protocol::LocalizeData& localize) {
  append_printf(line, "%d %u.%06u %u", static_cast<int>(localize.pending_count), localize.pending_time_sec,
                localize.pending_time_usec, localize.hypoth_count);
  // Mean and covariance in m and rad; 7 decimals of a radian hold every arc-second.
  const double to_si[3] = {1e-3, 1e-3, arcsec_to_rad(1)};
  for (std::size_t h = 0; h < localize.hypoth_count && h < localize.hypoths.size(); ++h) {
    const auto& hypothesis = localize.hypoths[h];
    append_printf(line, " %+.3f %+.3f %+.7f", mm_to_m(hypothesis.mean[0]), mm_to_m(hypothesis.mean[1]),
                  arcsec_to_rad(hypothesis.mean[2]));
    for (std::size_t r = 0; r < 3; ++r) {
      for (std::size_t c = 0; c < 3; ++c) {
        append_printf(line, " %.17g", static_cast<double>(hypothesis.cov[r][c]) * to_si[r] * to_si[c]);
      }
    }
    append_printf(line, " %.6f", hypothesis.alpha / 1e6);
  }
}

void append_blobfinder(std::string& line, const protocol::BlobfinderData& seen) {
  std::size_t total = 0;
  for (const auto& channel : seen.header) total += channel.num;
  append_printf(line, "%d %d %zu", static_cast<int>(seen.width), static_cast<int>(seen.height), total);
  for (std::size_t c = 0; c < seen.header.size(); ++c) {
    const auto& channel = seen.header[c];
    if (std::size_t{channel.index} + channel.num > seen.blobs.size()) {
      throw std::invalid_argument("text log: blobfinder channel " + std::to_string(c) + " names blobs " +
                                  std::to_string(channel.index) + ".." +
                                  std::to_string(channel.index + channel.num) + " of only " +
                                  std::to_string(seen.blobs.size()));
    }
    for (std::size_t i = channel.index; i < std::size_t{channel.index} + channel.num; ++i) {
      const auto& blob = seen.blobs[i];
      append_printf(line, " %zu %u %u %d %d %d %d %d %d %.3f", c, blob.color, blob.area,
                    static_cast<int>(blob.x), static_cast<int>(blob.y), static_cast<int>(blob.left),
                    static_cast<int>(blob.right), static_cast<int>(blob.top),
                    static_cast<int>(blob.bottom), mm_to_m(blob.range));
    }
  }
}

}  // namespace

bool is_extension_interface(std::uint16_t interface) {
  using namespace protocol;
  switch (interface) {
    case kWifiCode: case kSonarCode: case kIrCode: case kPowerCode:
    case kBumperCode: case kLocalizeCode: case kPtzCode: case kBlobfinderCode: return true;
    default: return false;
  }
}

void append_extension_fields(std::string& line, std::uint16_t interface,
                             std::span<const std::uint8_t> payload) {
  using namespace protocol;
  switch (interface) {
    case kWifiCode: append_wifi(line, decode<WifiData>(payload)); break;
    case kSonarCode: append_sonar(line, decode<SonarData>(payload)); break;
    case kIrCode: append_ir(line, decode<IrData>(payload)); break;
    case kPowerCode: append_power(line, decode<PowerData>(payload)); break;
    case kBumperCode: append_bumper(line, decode<BumperData>(payload)); break;
    case kLocalizeCode: append_localize(line, decode<LocalizeData>(payload)); break;
    case kPtzCode: append_ptz(line, decode<PtzData>(payload)); break;
    case kBlobfinderCode: append_blobfinder(line, decode<BlobfinderData>(payload)); break;
    default: break;
  }
}

}  // namespace playerkit::log
