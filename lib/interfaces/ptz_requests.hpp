#pragma once
// The ptz interface's requests (wire-format.md §5 "ptz"), answered once for
// every head: CONTROL_MODE (the 2-byte struct) and GENERIC_CONFIG (the full
// 35-byte struct, its raw bytes for the unit). Any other size, an unknown
// subtype or a request the head declines is NACKed.

#include <optional>

#include "core/exchange.hpp"
#include "protocol/messages/ptz.hpp"

namespace playerkit::interfaces {

// The defaults decline.
class PtzHead {
 public:
  virtual ~PtzHead() = default;

  // kPtzVelocityControl or kPtzPositionControl (any other value is passed on too).
  virtual bool set_control_mode(std::uint8_t /*mode*/) { return false; }
  // The unit's own command bytes; its reply, or nothing to NACK.
  [[nodiscard]] virtual std::optional<protocol::PtzGenericConfig> generic_config(
      const protocol::PtzGenericConfig& /*command*/) {
    return std::nullopt;
  }
};

[[nodiscard]] core::RequestResult answer_ptz_request(PtzHead& head, const core::Request& request);

}  // namespace playerkit::interfaces
