#pragma once
// RTCM-104 corrections for the receiver, heard on UDP (garminnmea.md §2.1):
// a socket bound to the port on one local address (every one by default),
// joined to the multicast group on that address's interface when it can be. Each datagram is written to the
// receiver byte for byte.

#include <cstdint>
#include <string>
#include <vector>

namespace playerkit::drivers::garminnmea {

class DgpsRelay {
 public:
  // Throws std::runtime_error when the port cannot be bound. A failed
  // multicast join is not an error (a container has no route): `warning()`
  // says so, and datagrams sent to the port directly still arrive.
  DgpsRelay(const std::string& group, int port, const std::string& bind_address = "0.0.0.0");
  ~DgpsRelay();
  DgpsRelay(const DgpsRelay&) = delete;
  DgpsRelay& operator=(const DgpsRelay&) = delete;

  // Every datagram waiting now (none: empty), never blocking.
  std::vector<std::vector<std::uint8_t>> take_datagrams();
  [[nodiscard]] const std::string& warning() const { return warning_; }

 private:
  int socket_ = -1;
  std::string warning_;
};

}  // namespace playerkit::drivers::garminnmea
