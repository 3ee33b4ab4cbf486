#pragma once
// A Linux SocketCAN raw socket (AF_CAN, CAN_RAW) bound to one interface
// ("can0", "vcan0") as a ByteLink: each frame read or written is one
// 16-byte `struct can_frame` record (framing/can_frame.hpp), so the framed
// reader, the counters and `--trace` work on it as on a serial line.

#include <cstdint>
#include <string>
#include <vector>

#include "links/byte_link.hpp"
#include "links/fd_io.hpp"

namespace playerkit::links::can {

// Frames passed up: received_id & mask == id & mask (the kernel's rule).
struct CanIdFilter {
  std::uint32_t id = 0;
  std::uint32_t mask = 0;
};

class SocketCanLink final : public ByteLink {
 public:
  // Throws LinkError(missing) for an interface that does not exist,
  // io_error when the kernel has no CAN support.
  SocketCanLink(std::string interface_name, std::vector<CanIdFilter> filters);
  ~SocketCanLink() override;

  void flush_input() override;
  void drain() override {}
  void close() noexcept override;
  [[nodiscard]] bool is_open() const override { return socket_.valid(); }
  void reopen(Deadline deadline) override;
  [[nodiscard]] std::string describe() const override { return "socketcan:" + interface_; }
  [[nodiscard]] int native_handle() const override { return socket_.get(); }

 protected:
  std::size_t read_available(std::span<std::uint8_t> buffer, Deadline deadline) override;
  std::size_t write_available(std::span<const std::uint8_t> bytes, Deadline deadline) override;

 private:
  void open();

  const std::string interface_;
  const std::vector<CanIdFilter> filters_;
  UniqueFd socket_;
  // A record read but not yet handed out whole (a reader asking for less).
  std::vector<std::uint8_t> pending_in_;
  // The start of a record being written (a writer handing over less).
  std::vector<std::uint8_t> pending_out_;
};

// Whether `interface_name` exists and a CAN_RAW socket can be bound to it;
// when not, why (for a test's skip message and the driver's refusal).
[[nodiscard]] std::string socketcan_unavailable_reason(const std::string& interface_name);

}  // namespace playerkit::links::can
