#include "drivers/comms/udpbroadcast_driver.hpp"

#include <chrono>
#include <exception>
#include <memory>
#include <stdexcept>
#include <string>
#include <system_error>

#include "core/device.hpp"
#include "core/option_reader.hpp"
#include "protocol/constants.hpp"
#include "protocol/interfaces.hpp"

namespace playerkit::drivers {

namespace {

// How long the thread waits for a datagram before looking at commands,
// requests and the stop flag again: one server round (10 ms), so neither a
// command nor shutdown waits noticeably longer than elsewhere.
constexpr std::chrono::milliseconds kPollInterval{10};

// A flood of datagrams must not starve commands and requests.
constexpr int kMaxDatagramsPerRound = 64;

}  // namespace

const core::OptionSchema& udpbroadcast_option_schema() {
  static const core::OptionSchema schema{
      core::OptionSpec::text("addr", std::string(kDefaultBroadcastAddress))
          .check([](std::string_view address) -> std::string {
            if (Ipv4Endpoint::parse(address, kDefaultBroadcastPort)) return "";
            return "\"" + std::string(address) + "\" is not an IPv4 address in dotted form";
          })
          .doc("where datagrams go (1.5: 10.255.255.255; set it for a real network)"),
      core::OptionSpec::integer("port", kDefaultBroadcastPort, 1, 65535)
          .doc("the UDP port sent to and listened on"),
  };
  return schema;
}

Ipv4Endpoint read_broadcast_destination(std::string_view address, int port) {
  if (port < 1 || port > 65535) {
    throw std::runtime_error("udpbroadcast: port " + std::to_string(port) +
                             " is not a UDP port (1-65535)");
  }
  auto destination = Ipv4Endpoint::parse(address, static_cast<std::uint16_t>(port));
  if (!destination) {
    throw std::runtime_error("udpbroadcast: addr \"" + std::string(address) +
                             "\" is not an IPv4 address in dotted form");
  }
  return *destination;
}

UdpBroadcastDriver::UdpBroadcastDriver(Ipv4Endpoint destination)
    // One byte more than a payload may hold, so that an oversized datagram shows.
    : destination_(destination), receive_buffer_(protocol::kMaxPayloadSize + 1) {}

void UdpBroadcastDriver::open() {
  try {
    socket_ = BroadcastSocket::bind_shared(destination_.port);
  } catch (const std::system_error& e) {
    throw core::DriverError("udpbroadcast: cannot listen on UDP port " +
                            std::to_string(destination_.port) + ": " + e.what());
  }
  // Commands written before the subscription would otherwise go out now.
  while (device().take_command()) {
  }
}

void UdpBroadcastDriver::close() {
  // A client may write and hang up at once: what it wrote still goes out.
  if (socket_) send_waiting_commands();
  socket_.reset();
}

void UdpBroadcastDriver::run(std::stop_token stop) {
  while (!stop.stop_requested()) {
    device().service_requests();
    send_waiting_commands();
    if (socket_->wait_readable(kPollInterval)) publish_waiting_datagrams();
  }
}

void UdpBroadcastDriver::send_waiting_commands() {
  while (const auto command = device().take_command()) {
    try {
      socket_->send_to(destination_, command->payload);
    } catch (const std::system_error& e) {
      // Delivery is best effort (manual §7.43); keep serving.
      device().logger().warning(device().name() + ": message not sent: " + e.what());
    }
  }
}

void UdpBroadcastDriver::publish_waiting_datagrams() {
  for (int received = 0; received < kMaxDatagramsPerRound; ++received) {
    std::optional<std::size_t> length;
    try {
      length = socket_->receive(receive_buffer_);
    } catch (const std::system_error& e) {
      device().logger().warning(device().name() + ": receive failed: " + e.what());
      return;
    }
    if (!length) return;
    if (*length == 0) continue;  // player_comms_data_t needs at least one byte
    if (*length > protocol::kMaxPayloadSize) {
      device().logger().warning(device().name() + ": dropped a datagram of " +
                                std::to_string(*length) + " bytes (at most " +
                                std::to_string(protocol::kMaxPayloadSize) + " fit a message)");
      continue;
    }
    const auto begin = receive_buffer_.begin();
    device().publish({begin, begin + static_cast<std::ptrdiff_t>(*length)});
  }
}

core::DriverSpec udpbroadcast_driver_spec() {
  core::DriverSpec spec;
  spec.name = "udpbroadcast";
  spec.interfaces = {protocol::kCommsCode};
  spec.access = protocol::Access::kAll;
  spec.factory = [](const core::DriverContext& context) {
    const core::OptionReader options(context.section, "udpbroadcast", udpbroadcast_option_schema());
    return std::make_unique<UdpBroadcastDriver>(
        read_broadcast_destination(options.text("addr"), options.integer("port")));
  };
  // Every command is sent and every datagram reaches every client once, as
  // 1.5's per-client queues did: messages, unlike motor commands, add up.
  spec.limits = core::DeviceLimits{.request_queue = 8, .data_queue = 64, .command_queue = 64};
  spec.summary = "sends comms commands as UDP broadcasts and publishes every datagram heard";
  spec.doc.manual_section = "7.43";
  spec.doc.schema = udpbroadcast_option_schema();
  spec.doc.requests = {"none: every request NACK"};
  spec.doc.example = "comms:0 ( driver \"udpbroadcast\" addr \"127.255.255.255\" port 6013 )";
  return spec;
}

}  // namespace playerkit::drivers
