#pragma once
// Colour names as Stage reads them: an exact, case-sensitive match in X11's
// rgb.txt (§1.8). Only the names Stage worlds and Stage's own defaults use
// are kept (the basic names, their numbered 1-4 shades for a few, the usual
// compound names in both spellings, "gray0".."gray100" and "grey0".."grey100").

#include <optional>
#include <string_view>

#include "sim/world/model_spec.hpp"

namespace playerkit::sim::worldfile {

// nullopt for a name not in the table (Stage then warns and uses red).
std::optional<Rgb> x11_color(std::string_view name);

}  // namespace playerkit::sim::worldfile
