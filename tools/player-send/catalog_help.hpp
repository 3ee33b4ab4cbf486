#pragma once
// What can be sent to each interface, written from lib/protocol's catalog so
// that --help never disagrees with what player-send accepts:
//
//   position
//     cmd: xpos ypos yaw xspeed yspeed yawspeed state type
//     req get-geom: base pose and footprint (no fields)
//     req set-odom: set the odometric pose; fields: x y theta

#include <cstddef>
#include <string>
#include <vector>

#include "protocol/catalog.hpp"

namespace playerkit::player_send {

// The names a FIELD=VALUE argument may use for this struct, in wire order:
// "xspeed", "pose[3]" (a list of 3), "ranges[]" (a list of any length up to
// the struct's limit), "cov[3][3]", "tx[8].{intensity,len}" (a list of
// structs), "id.code", "channel (text)".
// subtype_size > 0 leaves out the leading subtype field, which player-send
// fills in from the request's name.
std::vector<std::string> settable_fields(const protocol::PayloadCodec& codec, std::size_t subtype_size = 0);

// One interface's commands and requests; empty when it has neither.
std::string interface_help(const protocol::InterfaceMessages& messages);

// Every interface that takes commands or requests, then one line naming the
// interfaces that take neither.
std::string catalog_help();

}  // namespace playerkit::player_send
