#include "families/family_registry.hpp"

#include <stdexcept>
#include <string>
#include <utility>

namespace playerkit::families {

void FamilyRegistry::add(FamilySpec family) {
  if (find(family.name)) throw std::invalid_argument("the family '" + family.name + "' is registered twice");
  for (const auto& kind : family.emulators) {
    for (const auto& other : families_) {
      for (const auto& taken : other.emulators) {
        if (taken.name == kind.name) {
          throw std::invalid_argument("the families '" + other.name + "' and '" + family.name +
                                      "' both have an emulator named '" + kind.name + "'");
        }
      }
    }
  }
  families_.push_back(std::move(family));
}

const FamilySpec* FamilyRegistry::find(std::string_view name) const {
  for (const auto& family : families_) {
    if (family.name == name) return &family;
  }
  return nullptr;
}

emulators::EmulatorCatalog FamilyRegistry::emulator_catalog() const {
  std::vector<emulators::EmulatorKind> kinds;
  for (const auto& family : families_) kinds.insert(kinds.end(), family.emulators.begin(), family.emulators.end());
  return emulators::EmulatorCatalog(std::move(kinds));
}

TraceFraming FamilyRegistry::framing(std::string_view family) const {
  const FamilySpec* spec = find(family);
  return spec ? spec->framing : TraceFraming{};
}

}  // namespace playerkit::families
