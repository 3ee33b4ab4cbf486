#pragma once
// Asking a line "are you a SICK laser?" (sicklms200.md §2.1, sickpls.md §2):
// installation mode with one model's password; A0 00 says it is that model,
// A0 01 "a SICK, but the other model", so the other password follows. An
// accepted password is asked again: a mode reply does not say which password
// it answers, and a late one to the probe before may be on the line. An LMS
// is then asked its type (T3). It is left in installation mode at the speed
// it was found. Scans of a laser still streaming are skipped: the request
// stops it.

#include <optional>

#include "families/family_spec.hpp"
#include "families/sick/protocol/codes.hpp"

namespace playerkit::families {

// `first` is the password tried first (the model the line's framing suits).
// nullopt when nothing SICK answered by the deadlines. LinkErrors pass through.
std::optional<Identification> probe_sick(const ProbeContext& line, hardware::sick::Model first);

}  // namespace playerkit::families
