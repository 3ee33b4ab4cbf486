#include "drivers/passthrough/passthrough_driver.hpp"

#include <algorithm>
#include <exception>
#include <memory>
#include <stdexcept>
#include <utility>

#include "core/device.hpp"
#include "protocol/constants.hpp"
#include "protocol/interfaces.hpp"

namespace playerkit::drivers {

namespace {

using protocol::Access;
using protocol::MessageType;

// How long the thread waits for the remote's next data round before looking
// at commands, requests and the stop flag again: one local server round.
constexpr std::chrono::milliseconds kPollInterval{10};

// The remote pushes rounds this often. Each round carries only new samples
// (PUSH_NEW), so a sensor up to this rate loses none and adds at most one
// period of latency; the SYNCH-only rounds in between cost 32 bytes each.
constexpr std::uint16_t kRemoteRoundsPerSecond = 100;

// A remote round holds one message per subscribed device plus the SYNCH;
// queued devices (comms) may send a backlog. Bound the work per iteration.
constexpr int kMaxMessagesPerRound = 256;

bool can_read(Access access) { return access == Access::kRead || access == Access::kAll; }
bool can_write(Access access) { return access == Access::kWrite || access == Access::kAll; }

}  // namespace

std::string to_string(const RemoteDevice& remote) {
  return protocol::to_string(remote.address) + " on " + remote.host + ":" +
         std::to_string(remote.port);
}

RemoteDevice read_remote_device(std::uint16_t interface, std::string_view host, int port,
                                int index) {
  if (host.empty()) throw std::runtime_error("passthrough: host is empty");
  if (port < 1 || port > 65535) {
    throw std::runtime_error("passthrough: port " + std::to_string(port) +
                             " is not a TCP port (1-65535)");
  }
  if (index < 0 || index > 65535) {
    throw std::runtime_error("passthrough: index " + std::to_string(index) +
                             " is not a device index (0-65535)");
  }
  return {std::string(host), static_cast<std::uint16_t>(port),
          {interface, static_cast<std::uint16_t>(index)}};
}

PassthroughDriver::PassthroughDriver(RemoteDevice remote, PassthroughTimings timings)
    : remote_(std::move(remote)), timings_(timings) {}

void PassthroughDriver::open() {
  connect_and_subscribe();
  // A command written before anyone subscribed is not news for the remote.
  while (device().take_command()) {
  }
}

void PassthroughDriver::close() { client_.reset(); }

void PassthroughDriver::connect_and_subscribe() {
  const std::string where = remote_.host + ":" + std::to_string(remote_.port);
  const std::string what = protocol::to_string(remote_.address);
  // One deadline for all of it: a remote that sends its banner late and then
  // says nothing must not take twice the timeout.
  const auto deadline = std::chrono::steady_clock::now() + timings_.connect_timeout;
  try {
    auto client = client::Client::connect(remote_.host, remote_.port, timings_.connect_timeout);
    client.set_timeout(std::max(std::chrono::milliseconds(1),
                                std::chrono::duration_cast<std::chrono::milliseconds>(
                                    deadline - std::chrono::steady_clock::now())));
    const client::AccessGrant grant = client.request_access(remote_.address, Access::kAll);
    if (grant.driver_name.empty()) {
      throw core::DriverError("the remote server " + where + " has no device " + what);
    }
    if (!can_read(grant.access) && !can_write(grant.access)) {
      throw core::DriverError("the remote server " + where + " refused " + what +
                              " (its driver '" + grant.driver_name + "' granted '" +
                              std::string(1, static_cast<char>(grant.access)) + "')");
    }
    client.set_data_mode(protocol::DataMode::kPushNew);
    client.set_frequency(kRemoteRoundsPerSecond);
    client.set_timeout(timings_.request_timeout);
    granted_ = grant.access;
    client_ = std::move(client);
  } catch (const client::ClientError& e) {
    throw core::DriverError("cannot use " + what + " on the remote server " + where + ": " +
                            e.what());
  }
}

void PassthroughDriver::run(std::stop_token stop) {
  while (!stop.stop_requested()) {
    if (!client_) {
      wait_for_remote(stop);
      continue;
    }
    try {
      relay_one_round();
      forward_commands();
    } catch (const client::ClientError& e) {
      lose_remote(e.what());
      continue;
    }
    // Requests last: a lost remote is noticed inside and answered NACK.
    device().service_requests();
  }
}

void PassthroughDriver::relay_one_round() {
  // A round ends with its SYNCH; stopping there keeps commands and requests
  // from waiting behind a steady stream of rounds.
  for (int count = 0; count < kMaxMessagesPerRound; ++count) {
    auto message = client_->read(kPollInterval);
    if (!message || message->type() == MessageType::kSynch) return;
    // The remote's timestamp, not ours: it says when the sample was taken.
    if (message->type() == MessageType::kData && message->device() == remote_.address) {
      device().publish(std::move(message->payload), message->timestamp());
    }
  }
}

void PassthroughDriver::forward_commands() {
  while (auto command = device().take_command()) {
    if (!can_write(granted_)) {
      if (!warned_read_only_) {
        device().logger().warning(device().name() + ": commands dropped: " +
                                  to_string(remote_) + " is open for reading only");
        warned_read_only_ = true;
      }
      continue;
    }
    client_->write_command(remote_.address, command->payload);
  }
}

core::RequestResult PassthroughDriver::handle_request(const core::Request& request) {
  if (!client_) return core::RequestResult::nack();
  try {
    protocol::Message reply = client_->request(remote_.address, request.payload);
    return {reply.type(), std::move(reply.payload)};
  } catch (const client::TimeoutError&) {
    lose_remote("no reply to a request within " +
                std::to_string(timings_.request_timeout.count()) + " ms");
  } catch (const client::ClientError& e) {
    lose_remote(e.what());
  }
  return core::RequestResult::nack();
}

void PassthroughDriver::lose_remote(const std::string& reason) {
  client_.reset();
  const std::string message = "lost " + to_string(remote_) + " (" + reason + ")";
  device().set_available(false, message);
  device().logger().error(device().name() + ": " + message +
                          "; new subscriptions get 'e'; reconnecting every " +
                          std::to_string(timings_.retry_interval.count()) + " ms");
  next_attempt_ = std::chrono::steady_clock::now() + timings_.retry_interval;
}

void PassthroughDriver::wait_for_remote(const std::stop_token& stop) {
  // Nothing can reach the remote meanwhile: answer at once, and drop
  // commands (an old motion command must not run when the remote returns).
  device().service_requests();
  while (device().take_command()) {
  }
  if (std::chrono::steady_clock::now() < next_attempt_) {
    sleep_for(stop, kPollInterval);
    return;
  }
  next_attempt_ = std::chrono::steady_clock::now() + timings_.retry_interval;
  try {
    connect_and_subscribe();
  } catch (const std::exception& e) {
    device().logger().debug(device().name() + ": still away: " + e.what());
    return;
  }
  while (device().take_command()) {
  }
  device().set_available(true);
  device().logger().info(device().name() + ": " + to_string(remote_) + " is back");
}

core::DriverSpec passthrough_driver_spec() {
  core::DriverSpec spec;
  spec.name = "passthrough";
  for (const auto& info : protocol::all_interfaces()) spec.interfaces.push_back(info.code);
  // Clients may ask for anything, as of any 1.5 device; what the remote
  // grants decides what flows (setup fails if it grants nothing).
  spec.access = Access::kAll;
  spec.factory = [](const core::DriverContext& context) {
    auto remote = read_remote_device(
        context.key.address.interface,
        context.section.read_string("host", kDefaultPassthroughHost),
        context.section.read_int("port", kDefaultPassthroughPort),
        context.section.read_int("index", 0));
    return std::make_unique<PassthroughDriver>(std::move(remote));
  };
  spec.limits = core::DeviceLimits{.request_queue = 8};
  // Messages, not readings: every one the remote sends is passed on, and
  // every command written is forwarded, as the local udpbroadcast does.
  spec.interface_limits[protocol::kCommsCode] =
      core::DeviceLimits{.request_queue = 8, .data_queue = 64, .command_queue = 64};
  spec.summary = "serves a device of another Player server (any interface)";
  spec.doc.manual_section = "7.31";
  spec.doc.needs_hardware = true;  // a remote server
  spec.doc.options = {{"host", "string", "\"localhost\"", "", "the other Player server"},
                      {"port", "int", "6665", "", "its TCP port"},
                      {"index", "int", "0", "", "the index of its device of this section's interface"}};
  spec.doc.requests = {"every request: forwarded to the remote device and its reply returned"};
  spec.doc.example = "laser:0 ( driver \"passthrough\" host \"robot1\" port 6665 index 0 )";
  return spec;
}

}  // namespace playerkit::drivers
