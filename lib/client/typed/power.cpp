#include "client/typed/power.hpp"

#include "protocol/si_units.hpp"

namespace playerkit::client {

PowerState to_si(const protocol::PowerData& data) {
  return {protocol::to_si(protocol::WireUnit::kDecivolt, data.charge)};
}

}  // namespace playerkit::client
