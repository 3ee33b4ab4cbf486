#pragma once
// What a hardware family tells the tools about itself, in one value: how to
// recognise its devices on a port (probes), how to cut its bytes into
// telegrams for traces (framing), and which devices it can emulate. Its
// drivers register through CMake (playerkit_driver_family) and carry the
// family's name in core::DriverSpec::family.
//
// `player-drivers probe/emulate/run --trace/list/info` iterate over the
// registered families (family_registry.hpp); no code outside a family's folder
// names it. A family's folder (lib/families/<name>/README.md) holds its
// protocol bytes, driver(s), emulator(s) and the function returning this spec.

#include <functional>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "core/driver_registry.hpp"
#include "emulators/emulator_kind.hpp"
#include "framing/frame_format.hpp"
#include "links/byte_link.hpp"
#include "links/deadline.hpp"
#include "links/serial_settings.hpp"

namespace playerkit::families {

// What answered a probe.
struct Identification {
  std::string driver;  // what to run: "p2os", "sicklms200"
  std::string model;   // what it said it is: "Pioneer p3dx \"playerkit\"", "LMS200;30106"
  // A section to paste into a configuration: `position:0 ( driver "p2os_position" port "PORT" )`.
  std::string interface_name;
  std::string config_driver;
  // Anything the user should know first ("add the other p2os_* devices ..."); may be empty.
  std::string note;
};

// The line a probe asks on, opened and set to `baud` (0 on a TCP port).
struct ProbeContext {
  links::ByteLink& link;
  int baud = 0;
  links::Deadline first_reply;  // for the device's first answer
  links::Deadline finish;       // for the rest of the exchange, once it answered
};

// One way to ask a line "who are you?".
struct ProbeMethod {
  std::string label;  // "P2OS", "SICK (LMS password)"
  // The line speeds to try, likeliest first; a port tries every family's
  // first rate before any family's second.
  std::vector<int> bauds;
  links::SerialSettings line;  // character framing and flow control (its baud is ignored)
  // nullopt when nothing of the family answered by the deadlines. LinkErrors pass through.
  std::function<std::optional<Identification>(const ProbeContext&)> ask;
};

// The frame formats of a family's telegrams, host -> device and device -> host,
// for `run --trace`. Null: bytes are printed as they came.
struct TraceFraming {
  std::shared_ptr<const framing::FrameFormat> outgoing;
  std::shared_ptr<const framing::FrameFormat> incoming;
};

struct FamilySpec {
  std::string name;     // as in core::DriverSpec::family and PLAYERKIT_DRIVERS_<NAME>
  std::string summary;  // one line: "Pioneer robots (P2OS/AROS): eleven devices on one serial link"
  std::vector<ProbeMethod> probes;
  TraceFraming framing;
  std::vector<emulators::EmulatorKind> emulators;
  // Drivers the family brings beyond the built-in list: those of a family
  // made in a test or a plugin. A built-in family's drivers register
  // through CMake (playerkit_driver_family) and are not repeated here.
  std::vector<core::DriverSpec> drivers;
  // `player-drivers --help` examples, each a command line and what it does.
  std::vector<std::string> examples;
};

}  // namespace playerkit::families
