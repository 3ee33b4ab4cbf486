#include "server/data_round.hpp"

#include "protocol/interfaces.hpp"
#include "protocol/message.hpp"

namespace playerkit::server {

namespace {

void append_message(std::vector<std::uint8_t>& out, protocol::MessageHeader header,
                    std::span<const std::uint8_t> payload) {
  header.size = static_cast<std::uint32_t>(payload.size());
  const auto header_bytes = protocol::encode_header(header);
  out.insert(out.end(), header_bytes.begin(), header_bytes.end());
  out.insert(out.end(), payload.begin(), payload.end());
}

}  // namespace

DataRound build_data_round(ClientState& client, const core::DeviceTable& devices,
                           protocol::Timestamp now, std::vector<std::uint8_t> storage) {
  DataRound round;
  round.bytes = std::move(storage);
  round.bytes.clear();
  for (SubscriptionTable::Entry& entry : client.subscriptions.entries()) {
    if (!SubscriptionTable::can_read(entry.access)) continue;
    core::Device* device = devices.find(client.port, entry.device);
    if (device == nullptr || !device->readable()) continue;
    if (device->queues_data()) {
      // Messages, not readings: each one once, in order, whatever the mode.
      const auto samples = device->data_since(entry.last_sequence);
      for (const auto& sample : samples) {
        append_message(round.bytes,
                       protocol::make_header(protocol::MessageType::kData, entry.device, now,
                                             sample->timestamp),
                       sample->payload);
        ++round.data_messages;
        entry.last_sequence = sample->sequence;
      }
      if (!samples.empty()) device->readers().taken(client.id, entry.last_sequence);
      continue;
    }
    const auto sample = device->latest_data();
    // 1.5 sent whatever the buffer held before the first publish; we send nothing.
    if (sample->sequence == 0) continue;
    if (client.new_only()) {
      if (sample->timestamp == entry.last_sent) continue;
      entry.last_sent = sample->timestamp;
    }
    append_message(round.bytes,
                   protocol::make_header(protocol::MessageType::kData, entry.device, now,
                                         sample->timestamp),
                   sample->payload);
    ++round.data_messages;
  }
  append_message(round.bytes,
                 protocol::make_header(protocol::MessageType::kSynch,
                                       {protocol::kPlayerCode, 0}, now, now),
                 {});
  return round;
}

}  // namespace playerkit::server
