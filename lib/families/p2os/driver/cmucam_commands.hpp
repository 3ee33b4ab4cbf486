#pragma once
// What p2os_cmucam says to a CMUcam on the controller's AUX2 port (p2os.md
// §2.5): text through TTY3, replies fetched with GETAUX2. Every camera
// command is preceded by a lone CR, which stops tracking.

#include <optional>
#include <string>
#include <vector>

#include "families/p2os/protocol/commands.hpp"
#include "protocol/messages/blobfinder.hpp"

namespace playerkit::drivers::p2os {

// "Track the colour in front of the camera now", the start-up tracking.
inline constexpr std::string_view kTrackCurrentColor = "TC\r";

// Reset: stop, `RS`, `RM 3` (raw output, no ACK/NACK), flush AUX2.
std::vector<hardware::p2os::Command> cmucam_reset_commands();
// Stop, then start tracking with `tracking_text` (`TC ...` or `TW`), and ask
// for the first reply.
std::vector<hardware::p2os::Command> cmucam_track_commands(std::string_view tracking_text);
// Flush AUX2, then ask for up to 19 bytes of it (one SERAUX2 comes back).
std::vector<hardware::p2os::Command> cmucam_poll_commands();
// A lone CR: stop tracking.
hardware::p2os::Command cmucam_stop_command();

// SET_COLOR: `TW` when any bound is negative (track whatever is in view),
// else `TC rmin rmax gmin gmax bmin bmax`, with its CR.
std::string tracking_text(const protocol::BlobfinderColorConfig& color);

// SET_IMAGER_PARAMS: `CR` and a register/value pair per field given
// (brightness 6, contrast 5, auto gain 19, colour mode 18), with its CR;
// nothing when no field is given (-1, or out of range).
std::optional<std::string> imager_text(const protocol::BlobfinderImagerConfig& imager);

}  // namespace playerkit::drivers::p2os
