// "Who are you?" on a line, Segway style: open the slcan adapter's channel
// at the RMP's 500 kbit/s and listen for the robot's status messages
// (0x400-0x404), then close the channel again, leaving the adapter as it
// was found. Nothing goes on the CAN bus.
#include <set>
#include <string>

#include "families/segwayrmp/protocol/rmp_frames.hpp"
#include "families/segwayrmp/segwayrmp_family.hpp"
#include "links/can/can_bus.hpp"
#include "links/exchange.hpp"

namespace playerkit::families {

namespace rmp = hardware::segwayrmp;

std::optional<Identification> probe_segwayrmp(const ProbeContext& line) {
  links::can::CanBus bus(line.link, links::can::CanTransport::slcan);
  const auto wait = std::chrono::duration_cast<std::chrono::milliseconds>(links::time_until(line.first_reply));
  try {
    bus.start(500000, std::max(wait, std::chrono::milliseconds(1)));
  } catch (const links::ExchangeError&) {
    return std::nullopt;  // no slcan adapter acknowledged
  }
  std::set<std::uint32_t> heard;
  while (heard.size() < 5) {
    const auto frame = bus.receive(line.finish);
    if (!frame) break;
    if (!frame->extended && frame->id >= rmp::kBatteryId && frame->id <= rmp::kBodyDisplacementId) {
      heard.insert(frame->id);
    }
  }
  bus.stop();
  if (heard.size() < 5) return std::nullopt;
  return Identification{
      .driver = "segwayrmp",
      .model = "Segway RMP behind an slcan adapter, 500 kbit/s",
      .interface_name = "position",
      .config_driver = "segwayrmp",
      .note = "add position3d:0 and power:0 sections with driver \"segwayrmp\" for the robot's attitude and battery",
  };
}

}  // namespace playerkit::families
