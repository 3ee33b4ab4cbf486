// A client built against an installed playerkit by tests/bats/install.bats:
// lists the server's devices and prints the first position:0 reading.
//   devices_cpp HOST PORT
#include <chrono>
#include <cstdio>
#include <exception>
#include <string>

#include "client/client.hpp"
#include "client/typed/message_as.hpp"
#include "client/typed/position.hpp"
#include "protocol/device_address.hpp"
#include "protocol/interfaces.hpp"

int main(int argc, char** argv) {
  namespace client = playerkit::client;
  namespace protocol = playerkit::protocol;
  const auto port = argc == 3 ? protocol::parse_decimal_u16(argv[2]) : std::nullopt;
  if (!port) {
    std::fprintf(stderr, "usage: devices_cpp HOST PORT\n");
    return 2;
  }
  try {
    auto connection = client::Client::connect(argv[1], *port);
    for (const auto& device : connection.device_list()) {
      std::printf("device %s %s\n", protocol::to_string(device.address).c_str(), device.driver_name.c_str());
    }
    const protocol::DeviceAddress position{protocol::kPositionCode, 0};
    connection.request_access(position, protocol::Access::kRead);
    for (int attempt = 0; attempt < 100; ++attempt) {
      const auto message = connection.read(std::chrono::seconds(5));
      if (!message) {
        break;
      }
      if (message->type() == protocol::MessageType::kData && message->device() == position) {
        const auto state = client::to_si(client::data_as<protocol::PositionData>(*message));
        std::printf("position:0 x=%.3f y=%.3f\n", state.pose.x, state.pose.y);
        return 0;
      }
    }
    std::fprintf(stderr, "devices_cpp: no position:0 data\n");
  } catch (const std::exception& error) {
    std::fprintf(stderr, "devices_cpp: %s\n", error.what());
  }
  return 1;
}
