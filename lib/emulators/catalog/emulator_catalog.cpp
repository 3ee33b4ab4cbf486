#include "emulators/catalog/emulator_catalog.hpp"

#include <stdexcept>
#include <utility>

#include "emulators/emulator_option_reader.hpp"

namespace playerkit::emulators {

EmulatorCatalog::EmulatorCatalog(std::vector<EmulatorKind> kinds) : kinds_(std::move(kinds)) {
  for (std::size_t i = 0; i < kinds_.size(); ++i) {
    if (!kinds_[i].make) throw std::invalid_argument("emulator '" + kinds_[i].name + "' has no factory");
    for (std::size_t j = 0; j < i; ++j) {
      if (kinds_[j].name == kinds_[i].name) {
        throw std::invalid_argument("two emulators are named '" + kinds_[i].name + "'");
      }
    }
  }
}

const EmulatorKind* EmulatorCatalog::find(std::string_view name) const {
  for (const auto& kind : kinds_) {
    if (kind.name == name) return &kind;
  }
  return nullptr;
}

std::string EmulatorCatalog::names() const {
  if (kinds_.empty()) return "none";
  std::string names;
  for (const auto& kind : kinds_) names += (names.empty() ? "" : ", ") + kind.name;
  return names;
}

std::unique_ptr<DeviceEmulator> EmulatorCatalog::make(std::string_view name, const EmulatorOptionValues& options,
                                                      const EmulatorWorld& world) const {
  const EmulatorKind* kind = find(name);
  if (!kind) throw std::invalid_argument("no emulator '" + std::string(name) + "'; there are " + names());
  const EmulatorOptionReader reader(*kind, options);
  try {
    return kind->make(reader, world);
  } catch (const std::invalid_argument& e) {
    const std::string what = e.what();
    // The option reader's errors already start with the kind's name.
    if (what.starts_with(kind->name + ": ")) throw;
    throw std::invalid_argument(kind->name + ": " + what);
  }
}

}  // namespace playerkit::emulators
