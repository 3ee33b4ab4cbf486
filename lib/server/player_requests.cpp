#include "server/player_requests.hpp"

#include <algorithm>
#include <array>

#include "protocol/binary_codec.hpp"
#include "protocol/messages/player.hpp"

namespace playerkit::server {

namespace {

using protocol::MessageType;

std::uint16_t read_u16(std::span<const std::uint8_t> bytes, std::size_t offset) {
  return static_cast<std::uint16_t>((bytes[offset] << 8) | bytes[offset + 1]);
}

// The request's bytes, zero-extended to the struct's full size: 1.5 read
// fields from short requests as they were, and clients do send short ones.
template <typename T>
T decode_padded(std::span<const std::uint8_t> payload) {
  std::vector<std::uint8_t> padded(T::kWireSize, 0);
  std::copy_n(payload.begin(), std::min(payload.size(), T::kWireSize), padded.begin());
  return protocol::decode<T>(padded);
}

PlayerReply ack(std::vector<std::uint8_t> payload = {}) { return {MessageType::kAck, std::move(payload)}; }
PlayerReply nack(std::vector<std::uint8_t> payload = {}) { return {MessageType::kNack, std::move(payload)}; }

PlayerReply device_list(const ClientState& client, const core::DeviceTable& devices) {
  protocol::DeviceList list;
  list.subtype = protocol::kPlayerDevlistReq;
  for (const core::Device* device : devices.on_port(client.port)) {
    if (list.device_count == list.devices.size()) break;  // the struct holds 64
    list.devices[list.device_count++] = {device->address().interface, device->address().index,
                                         client.port};
  }
  return ack(protocol::encode(list));
}

PlayerReply driver_info(std::span<const std::uint8_t> payload, const core::DeviceTable& devices) {
  auto info = decode_padded<protocol::DriverInfo>(payload);
  const core::Device* device = devices.find(info.id.port, {info.id.code, info.id.index});
  info.subtype = protocol::kPlayerDriverinfoReq;
  info.driver_name.assign(device ? device->info().driver_name : "unknown");
  return ack(protocol::encode(info));  // 1.5 zeroed the id; we echo it
}

// `may_set_up` false: the device's setup has just failed elsewhere; the client
// holds nothing on it and gets 'e'.
PlayerReply device_access(ClientState& client, std::span<const std::uint8_t> payload,
                          const core::DeviceTable& devices, bool may_set_up = true) {
  const auto request = decode_padded<protocol::DeviceAccessRequest>(payload);
  protocol::DeviceAccessReply reply;
  reply.subtype = request.subtype;
  reply.code = request.code;
  reply.index = request.index;
  if (payload.size() < protocol::DeviceAccessRequest::kWireSize) {
    reply.access = static_cast<std::uint8_t>(protocol::Access::kError);
    return nack(protocol::encode(reply));
  }
  core::Device* device = devices.find(client.port, {request.code, request.index});
  reply.access = static_cast<std::uint8_t>(client.subscriptions.request(
      {request.code, request.index}, request.access, may_set_up ? device : nullptr, client.id));
  if (device != nullptr) reply.driver_name.assign(device->info().driver_name);
  return ack(protocol::encode(reply));
}

PlayerReply data_request(ClientState& client, std::span<const std::uint8_t> payload) {
  if (payload.size() != protocol::DataRequest::kWireSize || client.push_mode()) return nack();
  client.data_requested = true;
  PlayerReply reply = ack();
  reply.round_requested = true;
  return reply;
}

PlayerReply data_mode(ClientState& client, std::span<const std::uint8_t> payload) {
  if (payload.size() != protocol::DataModeRequest::kWireSize) return nack();
  const std::uint8_t mode = payload[2];
  if (mode > static_cast<std::uint8_t>(protocol::DataMode::kPullNew)) return nack();
  client.mode = static_cast<protocol::DataMode>(mode);
  if (!client.push_mode()) client.data_requested = false;
  PlayerReply reply = ack();
  reply.schedule_changed = true;
  return reply;
}

PlayerReply data_frequency(ClientState& client, std::span<const std::uint8_t> payload) {
  if (payload.size() != protocol::DataFrequencyRequest::kWireSize) return nack();
  client.frequency = read_u16(payload, 2);
  PlayerReply reply = ack();
  reply.schedule_changed = true;
  return reply;
}

PlayerReply name_service(std::span<const std::uint8_t> payload, const core::DeviceTable& devices) {
  // The name is NUL-terminated within its 64 bytes whatever the client sent.
  std::array<char, 64> name{};
  const std::size_t available = payload.size() > 2 ? payload.size() - 2 : 0;
  std::copy_n(payload.begin() + 2, std::min<std::size_t>(available, name.size() - 1), name.begin());
  protocol::NameServiceRequest reply;
  reply.subtype = protocol::kPlayerNameserviceReq;  // 1.5 wrote it in host order; we use the wire's
  reply.name.assign(std::string_view(name.data()));
  const core::Device* device = devices.find_robot(std::string_view(name.data()));
  reply.port = device ? device->key().port : 0;
  return ack(protocol::encode(reply));
}

}  // namespace

PlayerReply answer_player_request(ClientState& client, std::span<const std::uint8_t> payload,
                                  const core::DeviceTable& devices) {
  if (payload.size() < 2) return nack();
  switch (read_u16(payload, 0)) {
    case protocol::kPlayerDevlistReq: return device_list(client, devices);
    case protocol::kPlayerDriverinfoReq: return driver_info(payload, devices);
    case protocol::kPlayerDevReq: return device_access(client, payload, devices);
    case protocol::kPlayerDataReq: return data_request(client, payload);
    case protocol::kPlayerDatamodeReq: return data_mode(client, payload);
    case protocol::kPlayerDatafreqReq: return data_frequency(client, payload);
    case protocol::kPlayerNameserviceReq: return name_service(payload, devices);
    case protocol::kPlayerAuthReq:  // only meaningful while auth is pending
    default: return nack();
  }
}

core::Device* blocking_setup_among(core::Device& device, const core::DeviceTable& devices) {
  // Sources of sources count too; the depth bounds the search should a
  // configuration name a cycle.
  constexpr int kMaxSourceDepth = 4;
  const auto search = [&devices](core::Device& candidate, int depth, const auto& self) -> core::Device* {
    // A device already running is only counted in: its setup does not run again.
    if (candidate.subscriptions() > 0) return nullptr;
    if (candidate.driver().setup_may_block()) return &candidate;
    if (depth == kMaxSourceDepth) return nullptr;
    for (const core::DeviceKey& key : candidate.driver().source_devices()) {
      core::Device* source = devices.find(key);
      if (source == nullptr || source == &candidate) continue;
      if (core::Device* found = self(*source, depth + 1, self)) return found;
    }
    return nullptr;
  };
  return search(device, 0, search);
}

SetupFirst device_to_set_up_first(const ClientState& client, std::span<const std::uint8_t> payload,
                                  const core::DeviceTable& devices) {
  if (payload.size() < protocol::DeviceAccessRequest::kWireSize ||
      read_u16(payload, 0) != protocol::kPlayerDevReq) {
    return {};
  }
  const auto request = decode_padded<protocol::DeviceAccessRequest>(payload);
  const DeviceAddress address{request.code, request.index};
  core::Device* device = devices.find(client.port, address);
  if (device == nullptr || !is_access_letter(request.access)) return {};
  const auto wanted = static_cast<Access>(request.access);
  const bool subscribes = SubscriptionTable::held_subscriptions(wanted) >
                          SubscriptionTable::held_subscriptions(client.subscriptions.access(address));
  if (!subscribes) return {};
  core::Device* first = blocking_setup_among(*device, devices);
  return {.device = first, .is_source = first != nullptr && first != device};
}

PlayerReply answer_device_request_after_setup(ClientState& client,
                                              std::span<const std::uint8_t> payload,
                                              const core::DeviceTable& devices, bool set_up) {
  return device_access(client, payload, devices, set_up);
}

}  // namespace playerkit::server
