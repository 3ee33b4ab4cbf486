#pragma once
// `lifomcom` (manual §6.18, §7.26): clients exchange short messages through
// per-(type, channel) LIFO stacks held by the server. Everything happens in
// configuration requests (player_mcom_config_t, exactly 140 bytes):
//
//   push          -> ACK, empty
//   pop / read    -> ACK with player_mcom_return_t (type, channel, data with
//                    full = 1); NACK with no payload when the stack is empty,
//                    as 1.5 did (its "(EMPTY)" marker never left the driver)
//   clear         -> ACK, empty
//   set-capacity  -> capacity = data.data[0], clamped to MCOM_N_BUFS; 0 NACK
//   anything else, or a payload that is not 140 bytes -> NACK
//
// The stacks outlive subscriptions, so a message pushed by a client that then
// disconnects is still there for the next one.

#include "core/driver.hpp"
#include "core/driver_registry.hpp"
#include "drivers/mcom/lifo_channels.hpp"

namespace playerkit::drivers {

class LifomcomDriver final : public core::Driver {
 public:
  core::RequestResult handle_request(const core::Request& request) override;

 private:
  LifoChannels channels_;
};

core::DriverSpec lifomcom_driver_spec();

}  // namespace playerkit::drivers
