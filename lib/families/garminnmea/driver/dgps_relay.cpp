#include "families/garminnmea/driver/dgps_relay.hpp"

#include <arpa/inet.h>
#include <netinet/in.h>
#include <sys/socket.h>
#include <unistd.h>

#include <array>
#include <cerrno>
#include <cstring>
#include <stdexcept>

namespace playerkit::drivers::garminnmea {

DgpsRelay::DgpsRelay(const std::string& group, int port, const std::string& bind_address) {
  socket_ = ::socket(AF_INET, SOCK_DGRAM | SOCK_NONBLOCK | SOCK_CLOEXEC, 0);
  if (socket_ < 0) throw std::runtime_error(std::string("no UDP socket for DGPS corrections: ") + std::strerror(errno));
  const int yes = 1;
  ::setsockopt(socket_, SOL_SOCKET, SO_REUSEADDR, &yes, sizeof yes);
  sockaddr_in address{};
  address.sin_family = AF_INET;
  inet_pton(AF_INET, bind_address.c_str(), &address.sin_addr);  // checked with the options
  address.sin_port = htons(static_cast<std::uint16_t>(port));
  if (::bind(socket_, reinterpret_cast<const sockaddr*>(&address), sizeof address) != 0) {
    const std::string why = std::strerror(errno);
    ::close(socket_);
    throw std::runtime_error("cannot bind UDP port " + std::to_string(port) + " for DGPS corrections: " + why);
  }
  ip_mreq membership{};
  inet_pton(AF_INET, group.c_str(), &membership.imr_multiaddr);
  membership.imr_interface = address.sin_addr;
  if (::setsockopt(socket_, IPPROTO_IP, IP_ADD_MEMBERSHIP, &membership, sizeof membership) != 0) {
    warning_ = "cannot join DGPS multicast group " + group + " (" + std::strerror(errno) +
               "): only corrections sent to UDP port " + std::to_string(port) + " directly are relayed";
  }
}

DgpsRelay::~DgpsRelay() {
  if (socket_ >= 0) ::close(socket_);
}

std::vector<std::vector<std::uint8_t>> DgpsRelay::take_datagrams() {
  std::vector<std::vector<std::uint8_t>> datagrams;
  std::array<std::uint8_t, 1024> buffer{};  // 1.5's largest relayed datagram
  while (true) {
    const ssize_t got = ::recv(socket_, buffer.data(), buffer.size(), 0);
    if (got <= 0) return datagrams;
    datagrams.emplace_back(buffer.begin(), buffer.begin() + got);
  }
}

}  // namespace playerkit::drivers::garminnmea
