#include "core/source_request.hpp"

#include <atomic>
#include <utility>

namespace playerkit::core {

namespace {

ClientId new_driver_client() {
  static std::atomic<ClientId> next{kFirstDriverClient};
  return next.fetch_add(1, std::memory_order_relaxed);
}

}  // namespace

std::optional<Reply> ask_source(Device& source, std::vector<std::uint8_t> payload,
                                std::chrono::milliseconds timeout) {
  const ClientId asker = new_driver_client();
  const auto deadline = std::chrono::steady_clock::now() + timeout;
  source.expect_reply(asker);
  std::optional<Reply> reply;
  if (source.enqueue_request({asker, source.key().address, std::move(payload), source.clock().now()}) ==
      Device::RequestStatus::kQueued) {
    reply = source.await_reply(asker, deadline);
  }
  source.forget_reply(asker);
  return reply;
}

}  // namespace playerkit::core
