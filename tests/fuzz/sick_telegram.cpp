// SICK LMS 2xx / PLS bytes through hardware::sick: a stream cut into
// telegrams by SickFrameFormat, each valid one unwrapped and read as the
// driver reads replies and scans (or, in the host's direction, as the
// emulator reads requests). What decodes must encode and decode to the same
// value again.
//
// Input: byte 0 picks the direction (bit 0) and seeds the chunk sizes.

#include <stdexcept>

#include "fuzz_support.hpp"
#include "fuzz_targets.hpp"
#include "frame_stream.hpp"
#include "families/sick/protocol/codes.hpp"
#include "families/sick/protocol/frame_format.hpp"
#include "families/sick/protocol/replies.hpp"
#include "families/sick/protocol/requests.hpp"
#include "families/sick/protocol/scan.hpp"
#include "families/sick/protocol/telegram.hpp"

namespace playerkit::fuzz {
namespace sick_telegram_detail {

namespace sick = hardware::sick;
constexpr const char* kTarget = "sick_telegram";

void check(bool holds, const char* what) {
  if (!holds) invariant_failed(kTarget, what);
}

template <class Value>
void round_trip(const Value& value, std::uint8_t status, Value (*parse)(const sick::Reply&), const char* what) {
  check(parse(sick::unframe_reply(sick::encode_reply(value, status))) == value, what);
}

void reply(const sick::Reply& r) {
  try {
    switch (r.code) {
      case sick::kSwitchModeReply:
        round_trip(sick::parse_mode_reply(r), r.status, &sick::parse_mode_reply, "mode reply changed");
        break;
      case sick::kTypeReply:
        (void)sick::parse_type_reply(r).trimmed();
        round_trip(sick::parse_type_reply(r), r.status, &sick::parse_type_reply, "type reply changed");
        break;
      case sick::kVariantReply: {
        const auto variant = sick::parse_variant_reply(r);
        if (variant.variant.supported()) {
          (void)variant.variant.value_count();
          (void)variant.variant.first_angle_rad();
          (void)variant.variant.step_rad();
        }
        round_trip(variant, r.status, &sick::parse_variant_reply, "variant reply changed");
        break;
      }
      case sick::kConfigReply: {
        const auto config = sick::parse_config_reply(r);
        (void)config.config.blanking();
        (void)sick::metres_per_step(config.config.unit());
        round_trip(config, r.status, &sick::parse_config_reply, "config reply changed");
        break;
      }
      case sick::kSetConfigReply:
        round_trip(sick::parse_set_config_reply(r), r.status, &sick::parse_set_config_reply,
                   "set-config reply changed");
        break;
      case sick::kNotAcknowledged:
        round_trip(sick::parse_not_acknowledged(r), r.status, &sick::parse_not_acknowledged, "NAK changed");
        break;
      case sick::kScanReply:
      case sick::kSubrangeScanReply: {
        const auto scan = sick::parse_scan(r);
        for (const std::uint16_t value : scan.values) {
          (void)sick::distance_of(value);
          (void)sick::flags_of(value);
        }
        (void)sick::metres_per_step(scan.unit);
        check(sick::parse_scan(sick::unframe_reply(sick::encode_scan(scan, r.status))) == scan, "scan changed");
        break;
      }
      default:
        break;
    }
  } catch (const sick::TelegramError&) {
  }
}

void request(std::span<const std::uint8_t> body) {
  try {
    const auto decoded = sick::decode_request(body);
    (void)sick::describe(decoded);
    check(sick::decode_request(sick::request_body(decoded)) == decoded, "request changed through request_body");
  } catch (const sick::TelegramError&) {
  }
}

}  // namespace sick_telegram_detail

int sick_telegram(const std::uint8_t* data, std::size_t size) {
  using namespace sick_telegram_detail;
  ByteSource in(data, size);
  const std::uint8_t control = in.byte();
  const bool from_device = (control & 1) == 0;
  const auto format = from_device ? sick::SickFrameFormat::replies() : sick::SickFrameFormat::requests();
  split_frames(kTarget, format, in.rest(), control, [&](std::span<const std::uint8_t> telegram, bool valid) {
    if (!valid) return;
    try {
      if (from_device) {
        reply(sick::unframe_reply(telegram));
      } else {
        request(sick::unframe_request(telegram));
      }
    } catch (const sick::TelegramError&) {
      invariant_failed(kTarget, "a telegram SickFrameFormat accepted is refused when unwrapped");
    }
  });
  return 0;
}

}  // namespace playerkit::fuzz
