#pragma once
// Asking an open line "who are you?" in each supported protocol, at the
// line's current speed, with deadlines; nothing is configured on the device
// beyond what the question needs.
//
//   P2OS (p2os.md §2.4): SYNC0, SYNC1, SYNC2; the SYNC2 reply names the robot,
//     its class and subclass. A robot still connected from an earlier
//     session (sending SIPs) gets CLOSE first, as the reference driver does.
//     It is left synchronised, waiting for OPEN; a driver's SYNC0 restarts it.
//   SICK (sicklms200.md §2.1, sickpls.md §2): installation mode with one
//     model's password; A0 00 says it is that model, A0 01 "a SICK, but the
//     other model", so the other password follows. An LMS is then asked its
//     type (T3). It is left in installation mode at the speed it was found.
//     Scans of a laser still streaming are skipped: the request stops it.

#include <optional>
#include <string>

#include "hardware/sick/codes.hpp"
#include "links/byte_link.hpp"
#include "links/deadline.hpp"

namespace playerkit::player_drivers {

struct Identification {
  std::string driver;  // "p2os", "sicklms200", "sickpls"
  std::string model;   // "Pioneer p3dx \"playerkit\"", "LMS200;30106", "PLS"
};

struct ProbeDeadlines {
  links::Deadline first_reply;  // for the device's first answer
  links::Deadline finish;       // for the rest of the exchange, once it answered
};

// nullopt when nothing P2OS answered by the deadlines. LinkErrors pass through.
std::optional<Identification> probe_p2os(links::ByteLink& link, const ProbeDeadlines& deadlines);

// `first` is the password tried first (the model the line's framing suits).
std::optional<Identification> probe_sick(links::ByteLink& link, hardware::sick::Model first,
                                         const ProbeDeadlines& deadlines);

}  // namespace playerkit::player_drivers
