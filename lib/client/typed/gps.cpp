#include "client/typed/gps.hpp"

#include "protocol/si_units.hpp"

namespace playerkit::client {

GpsFix to_si(const protocol::GpsData& d) {
  using protocol::to_si;
  using protocol::WireUnit;
  return {d.time_sec + d.time_usec * 1e-6,
          to_si(WireUnit::kGpsAngle, d.latitude),
          to_si(WireUnit::kGpsAngle, d.longitude),
          to_si(WireUnit::kMillimetre, d.altitude),
          to_si(WireUnit::kCentimetre, d.utm_e),
          to_si(WireUnit::kCentimetre, d.utm_n),
          d.quality,
          d.num_sats,
          to_si(WireUnit::kTenth, d.hdop),
          to_si(WireUnit::kMillimetre, d.err_horz),
          to_si(WireUnit::kMillimetre, d.err_vert)};
}

}  // namespace playerkit::client
