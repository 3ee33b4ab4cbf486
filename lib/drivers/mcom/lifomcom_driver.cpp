#include "drivers/mcom/lifomcom_driver.hpp"

#include <algorithm>
#include <memory>
#include <optional>

#include "protocol/binary_codec.hpp"
#include "protocol/interfaces.hpp"

namespace playerkit::drivers {

namespace {

using protocol::McomConfig;
using protocol::McomData;
using protocol::McomReturn;

// 1.5 copied the name with strcpy, so the reply carries it up to the first NUL
// and zeros after (never the request's bytes beyond the terminator).
protocol::FixedString<protocol::kMcomChannelLen> normalized_channel(const ChannelKey& key) {
  protocol::FixedString<protocol::kMcomChannelLen> channel;
  std::copy(key.channel.begin(), key.channel.end(), channel.bytes.begin());
  return channel;
}

core::RequestResult answer_with(const ChannelKey& key, const std::optional<McomData>& message) {
  if (!message) return core::RequestResult::nack();
  McomReturn reply;
  reply.type = key.type;
  reply.channel = normalized_channel(key);
  reply.data = *message;
  return core::RequestResult::ack(protocol::encode(reply));
}

}  // namespace

core::RequestResult LifomcomDriver::handle_request(const core::Request& request) {
  if (request.payload.size() != McomConfig::kWireSize) return core::RequestResult::nack();
  const auto config = protocol::decode<McomConfig>(request.payload);
  const ChannelKey key{config.type, config.channel.str()};

  switch (config.command) {
    case protocol::kMcomPushReq: {
      McomData stored = config.data;
      stored.full = 1;  // whatever the client sent, a stored slot is full
      channels_.push(key, stored);
      return core::RequestResult::ack();
    }
    case protocol::kMcomPopReq:
      return answer_with(key, channels_.pop(key));
    case protocol::kMcomReadReq:
      return answer_with(key, channels_.read(key));
    case protocol::kMcomClearReq:
      channels_.clear(key);
      return core::RequestResult::ack();
    case protocol::kMcomSetCapacityReq: {
      // 1.5 took the capacity from the first data byte, as an unsigned char.
      const auto requested = static_cast<unsigned char>(config.data.data.bytes[0]);
      if (requested == 0) return core::RequestResult::nack();
      channels_.set_capacity(key, std::min<std::size_t>(requested, LifoChannels::kMaxCapacity));
      return core::RequestResult::ack();
    }
    default:
      return core::RequestResult::nack();
  }
}

core::DriverSpec lifomcom_driver_spec() {
  core::DriverSpec spec;
  spec.name = "lifomcom";
  spec.interfaces = {protocol::kMcomCode};
  spec.access = protocol::Access::kAll;
  spec.factory = [](const core::DriverContext&) { return std::make_unique<LifomcomDriver>(); };
  spec.limits = core::DeviceLimits{20};  // 1.5's request queue for lifomcom
  spec.summary = "per-channel LIFO message stacks for client-to-client messages (mcom)";
  spec.doc.manual_section = "7.26";
  spec.doc.requests = {"PUSH: a message onto the (type, channel) stack; a full stack drops its oldest",
                       "POP, READ: the newest message (POP removes it); NACK when there is none",
                       "CLEAR: empties the stack", "SET_CAPACITY: 1 to 10 messages (larger is 10), 0 NACK"};
  spec.doc.example = "mcom:0 ( driver \"lifomcom\" )";
  return spec;
}

}  // namespace playerkit::drivers
