#include "sim/worldfile/worldfile_tree.hpp"

namespace playerkit::sim::worldfile {

const Property* Entity::find(std::string_view name) const {
  for (const Property& property : properties) {
    if (property.name == name) return &property;
  }
  return nullptr;
}

}  // namespace playerkit::sim::worldfile
