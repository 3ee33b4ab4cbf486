#include "emulators/emulator_kind.hpp"

namespace playerkit::emulators {

std::string config_example(const EmulatorKind& kind, std::string_view port) {
  return kind.interface_name + ":0 ( driver \"" + kind.driver + "\" port \"" + std::string(port) + "\" )";
}

}  // namespace playerkit::emulators
