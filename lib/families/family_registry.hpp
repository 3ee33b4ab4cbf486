#pragma once
// The hardware families a program knows, in registration order. The built-in
// ones are the families CMake built (builtin_families.hpp); a test may add
// families of its own.

#include <string_view>
#include <vector>

#include "emulators/catalog/emulator_catalog.hpp"
#include "families/family_spec.hpp"

namespace playerkit::families {

class FamilyRegistry {
 public:
  // Throws std::invalid_argument for a name already registered, and for an
  // emulator name another family has (emulators share one namespace).
  void add(FamilySpec family);

  [[nodiscard]] const std::vector<FamilySpec>& all() const { return families_; }
  // nullptr when there is none of that name.
  [[nodiscard]] const FamilySpec* find(std::string_view name) const;

  // Every family's emulators, in registration order.
  [[nodiscard]] emulators::EmulatorCatalog emulator_catalog() const;
  // The family's trace framing; empty for an unknown family or one without.
  [[nodiscard]] TraceFraming framing(std::string_view family) const;

 private:
  std::vector<FamilySpec> families_;
};

}  // namespace playerkit::families
