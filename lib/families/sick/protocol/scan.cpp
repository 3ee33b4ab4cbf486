#include "families/sick/protocol/scan.hpp"

#include "families/sick/protocol/byte_fields.hpp"

#include <cstdio>

namespace playerkit::hardware::sick {
using detail::append_le16;
using detail::load_le16;
namespace {

constexpr int kPartialScanShift = 11;
constexpr int kUnitShift = 14;

}  // namespace

std::uint16_t CountWord::encode() const {
  if (count > kMaxCount) throw std::invalid_argument("SICK count word: more than 1023 values");
  if (partial_scan > 3) throw std::invalid_argument("SICK count word: partial-scan index over 3");
  const auto unit_bits = static_cast<unsigned>(unit);
  if (unit_bits > 3) throw std::invalid_argument("SICK count word: unit code over 3");
  return static_cast<std::uint16_t>(count | (partial_scan << kPartialScanShift) |
                                    (unit_bits << kUnitShift));
}

CountWord CountWord::decode(std::uint16_t word) {
  return {static_cast<std::uint16_t>(word & kMaxCount),
          static_cast<std::uint8_t>((word >> kPartialScanShift) & 0x3u),
          static_cast<Unit>(word >> kUnitShift)};
}

std::vector<std::uint8_t> encode_scan(const Scan& scan, std::uint8_t status) {
  if (scan.values.size() > kMaxCount) {
    throw TelegramError("SICK scan: " + std::to_string(scan.values.size()) +
                        " values, a count word holds at most 1023");
  }
  std::vector<std::uint8_t> data;
  data.reserve(6 + 2 * scan.values.size());
  if (scan.subrange) {
    append_le16(data, scan.subrange->first);
    append_le16(data, scan.subrange->last);
  }
  append_le16(data, CountWord{static_cast<std::uint16_t>(scan.values.size()), scan.partial_scan,
                              scan.unit}
                        .encode());
  for (const std::uint16_t value : scan.values) append_le16(data, value);
  return frame_reply(scan.subrange ? kSubrangeScanReply : kScanReply, data, status);
}

Scan parse_scan(const Reply& reply) {
  const bool subrange = reply.code == kSubrangeScanReply;
  if (!subrange && reply.code != kScanReply) {
    char code[4];
    std::snprintf(code, sizeof code, "%02X", reply.code);
    throw TelegramError(std::string("SICK scan: reply code ") + code + " is neither B0 nor B7");
  }
  const char* name = subrange ? "SICK B7 scan" : "SICK B0 scan";
  const std::size_t header = subrange ? 6 : 2;
  if (reply.data.size() < header) {
    throw TelegramError(std::string(name) + ": truncated: " + std::to_string(reply.data.size()) +
                        " data bytes, the header alone is " + std::to_string(header));
  }
  Scan scan;
  if (subrange) scan.subrange = Subrange{load_le16(reply.data, 0), load_le16(reply.data, 2)};
  const CountWord word = CountWord::decode(load_le16(reply.data, header - 2));
  scan.partial_scan = word.partial_scan;
  scan.unit = word.unit;
  const std::size_t expected = header + 2 * std::size_t{word.count};
  if (reply.data.size() != expected) {
    throw TelegramError(std::string(name) + ": " +
                        (reply.data.size() < expected ? "truncated" : "too long") + ": count " +
                        std::to_string(word.count) + " needs " + std::to_string(expected) +
                        " data bytes, got " + std::to_string(reply.data.size()));
  }
  if (scan.subrange && scan.subrange->count() != word.count) {
    throw TelegramError(std::string(name) + ": count " + std::to_string(word.count) +
                        " disagrees with indices " + std::to_string(scan.subrange->first) + ".." +
                        std::to_string(scan.subrange->last));
  }
  scan.values.reserve(word.count);
  for (std::size_t i = 0; i < word.count; ++i) {
    scan.values.push_back(load_le16(reply.data, header + 2 * i));
  }
  return scan;
}

}  // namespace playerkit::hardware::sick
