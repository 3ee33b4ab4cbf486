#include "links/can/socketcan_link.hpp"

#include <linux/can.h>
#include <linux/can/raw.h>
#include <net/if.h>
#include <poll.h>
#include <sys/ioctl.h>
#include <sys/socket.h>
#include <unistd.h>

#include <cerrno>
#include <array>
#include <cstring>

#include "framing/can_frame.hpp"
#include "links/link_error.hpp"

namespace playerkit::links::can {

namespace {

UniqueFd bound_socket(const std::string& interface_name, const std::vector<CanIdFilter>& filters) {
  const std::string port = "socketcan:" + interface_name;
  if (interface_name.empty() || interface_name.size() >= IFNAMSIZ) {
    throw LinkError(LinkErrorKind::bad_address, port, port + ": not a network interface name");
  }
  UniqueFd socket_fd(::socket(PF_CAN, SOCK_RAW | SOCK_CLOEXEC | SOCK_NONBLOCK, CAN_RAW));
  if (!socket_fd.valid()) throw system_error(port, "cannot open a CAN socket (no SocketCAN in this kernel?)", errno);
  const unsigned index = ::if_nametoindex(interface_name.c_str());
  if (index == 0) {
    throw LinkError(LinkErrorKind::missing, port,
                    port + ": no such network interface (ip link add dev " + interface_name + " type vcan, "
                           "or the adapter's driver)");
  }
  std::vector<can_filter> kernel_filters;
  for (const CanIdFilter& filter : filters) kernel_filters.push_back({filter.id, filter.mask});
  if (!kernel_filters.empty() &&
      ::setsockopt(socket_fd.get(), SOL_CAN_RAW, CAN_RAW_FILTER, kernel_filters.data(),
                   static_cast<socklen_t>(kernel_filters.size() * sizeof(can_filter))) != 0) {
    throw system_error(port, "cannot set the receive filter", errno);
  }
  sockaddr_can address{};
  address.can_family = AF_CAN;
  address.can_ifindex = static_cast<int>(index);
  if (::bind(socket_fd.get(), reinterpret_cast<const sockaddr*>(&address), sizeof address) != 0) {
    throw system_error(port, "cannot bind to the interface", errno);
  }
  return socket_fd;
}

}  // namespace

SocketCanLink::SocketCanLink(std::string interface_name, std::vector<CanIdFilter> filters)
    : interface_(std::move(interface_name)), filters_(std::move(filters)) {
  open();
}

SocketCanLink::~SocketCanLink() { close(); }

void SocketCanLink::open() {
  socket_ = bound_socket(interface_, filters_);
  pending_in_.clear();
  pending_out_.clear();
}

void SocketCanLink::close() noexcept { socket_.reset(); }

void SocketCanLink::reopen(Deadline /*deadline*/) {
  close();
  open();
  counters().reconnects.add();
}

void SocketCanLink::flush_input() {
  pending_in_.clear();
  std::array<std::uint8_t, sizeof(can_frame)> discard{};
  while (socket_.valid() && ::recv(socket_.get(), discard.data(), discard.size(), MSG_DONTWAIT) > 0) {
  }
}

std::size_t SocketCanLink::read_available(std::span<std::uint8_t> buffer, Deadline deadline) {
  if (!socket_.valid()) throw LinkError(LinkErrorKind::closed, describe(), describe() + ": closed");
  if (pending_in_.empty()) {
    const short events = wait_for_fd(socket_.get(), POLLIN, deadline);
    if (events == 0) return 0;
    can_frame record{};
    const ssize_t got = ::recv(socket_.get(), &record, sizeof record, MSG_DONTWAIT);
    if (got < 0) {
      if (errno == EAGAIN || errno == EWOULDBLOCK || errno == EINTR) return 0;
      if (errno == ENETDOWN || errno == ENODEV) {
        throw LinkError(LinkErrorKind::disconnected, describe(), describe() + ": the interface went down");
      }
      throw system_error(describe(), "read", errno);
    }
    // The record in framing's byte order (the host's, which is what the kernel gave).
    const auto* bytes = reinterpret_cast<const std::uint8_t*>(&record);
    pending_in_.assign(bytes, bytes + static_cast<std::size_t>(got));
  }
  const std::size_t count = std::min(buffer.size(), pending_in_.size());
  std::memcpy(buffer.data(), pending_in_.data(), count);
  pending_in_.erase(pending_in_.begin(), pending_in_.begin() + static_cast<std::ptrdiff_t>(count));
  return count;
}

std::size_t SocketCanLink::write_available(std::span<const std::uint8_t> bytes, Deadline deadline) {
  if (!socket_.valid()) throw LinkError(LinkErrorKind::closed, describe(), describe() + ": closed");
  std::size_t taken = 0;
  while (taken < bytes.size()) {
    const std::size_t wanted = framing::kCanRecordSize - pending_out_.size();
    const std::size_t part = std::min(wanted, bytes.size() - taken);
    pending_out_.insert(pending_out_.end(), bytes.begin() + static_cast<std::ptrdiff_t>(taken),
                        bytes.begin() + static_cast<std::ptrdiff_t>(taken + part));
    if (pending_out_.size() < framing::kCanRecordSize) return taken + part;
    for (;;) {
      const ssize_t sent = ::send(socket_.get(), pending_out_.data(), pending_out_.size(), MSG_DONTWAIT);
      if (sent == static_cast<ssize_t>(pending_out_.size())) break;
      if (sent < 0 && (errno == EAGAIN || errno == ENOBUFS || errno == EINTR)) {
        // The interface's queue is full: wait for room, as a UART's would be.
        if (wait_for_fd(socket_.get(), POLLOUT, deadline) == 0) {
          pending_out_.resize(pending_out_.size() - part);
          return taken;
        }
        continue;
      }
      if (sent < 0 && (errno == ENETDOWN || errno == ENODEV)) {
        throw LinkError(LinkErrorKind::disconnected, describe(), describe() + ": the interface went down");
      }
      throw system_error(describe(), "write", errno);
    }
    pending_out_.clear();
    taken += part;
  }
  return taken;
}

std::string socketcan_unavailable_reason(const std::string& interface_name) {
  try {
    SocketCanLink probe(interface_name, {});
    return {};
  } catch (const LinkError& e) {
    return e.what();
  }
}

}  // namespace playerkit::links::can
