#pragma once
// What a host's packet asks of the camera (sonyevid30.md §2.1, §6.4), as the
// camera reads it: the emulator's side of the messages visca.hpp writes.

#include <cstdint>
#include <span>

#include "families/sonyevid30/protocol/visca.hpp"

namespace playerkit::hardware::sonyevid30 {

struct HostMessage {
  enum class Kind {
    pan_tilt_inquiry,
    zoom_inquiry,
    other_inquiry,      // any other `81 09 ...`: answered, not modelled
    absolute_pan_tilt,  // pan, tilt, speeds
    drive_pan_tilt,     // drive_pan, drive_tilt, speeds
    zoom_direct,        // zoom
    zoom_drive,         // zoom_speed: 0 stop, + tele, - wide (01 04 07 00 / 2p / 3p)
    other_command,      // any other `81 01 ...`: accepted, not modelled
    cancel,             // socket
    address_set,        // broadcast 88 30 01 FF
    if_clear,           // broadcast 88 01 00 01 FF
    malformed,          // a syntax error
  };
  Kind kind = Kind::malformed;
  int pan = 0;  // camera units
  int tilt = 0;
  int pan_speed = 0;
  int tilt_speed = 0;
  Drive drive_pan = Drive::stop;
  Drive drive_tilt = Drive::stop;
  int zoom = 0;
  int zoom_speed = 0;
  int socket = 0;
};

// One whole packet, header and terminator included, sent to camera 1 or broadcast.
[[nodiscard]] HostMessage parse_host_message(std::span<const std::uint8_t> packet);

}  // namespace playerkit::hardware::sonyevid30
