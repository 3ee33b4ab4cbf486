#include <algorithm>
#include <array>

#include "drivers/sim/simulated_drivers.hpp"
#include "protocol/binary_codec.hpp"
#include "protocol/messages/blobfinder.hpp"

namespace playerkit::drivers::sim {

double SimBlobfinderDriver::reading_time(const World& world) const { return world.blobs(model()).time; }

std::optional<std::vector<std::uint8_t>> SimBlobfinderDriver::encode_reading(const World& world) {
  const playerkit::sim::BlobScan& scan = world.blobs(model());
  protocol::BlobfinderData data;
  data.width = wire_value<std::uint16_t>(scan.image_width);
  data.height = wire_value<std::uint16_t>(scan.image_height);
  // The world orders blobs by channel: each channel's run becomes its
  // header entry, cut to 1.5's nominal 10 blobs per channel and 32 channels.
  for (const playerkit::sim::Blob& blob : scan.blobs) {
    if (blob.channel < 0 || blob.channel >= static_cast<int>(protocol::kBlobfinderMaxChannels)) continue;
    protocol::BlobfinderChannel& channel = data.header[static_cast<std::size_t>(blob.channel)];
    if (channel.num == 0) channel.index = static_cast<std::uint16_t>(data.blobs.size());
    if (channel.num >= protocol::kBlobfinderMaxBlobsPerChannel) continue;
    ++channel.num;
    protocol::BlobfinderBlob wire;
    wire.color = blob.color.packed();
    wire.area = wire_value<std::uint32_t>(blob.area);
    wire.x = wire_value<std::uint16_t>(blob.x);
    wire.y = wire_value<std::uint16_t>(blob.y);
    wire.left = wire_value<std::uint16_t>(blob.left);
    wire.right = wire_value<std::uint16_t>(blob.right);
    wire.top = wire_value<std::uint16_t>(blob.top);
    wire.bottom = wire_value<std::uint16_t>(blob.bottom);
    wire.range = wire_value<std::uint16_t>(blob.range * kMillimetresPerMetre);
    data.blobs.push_back(wire);
  }
  return protocol::encode(data);
}

}  // namespace playerkit::drivers::sim
