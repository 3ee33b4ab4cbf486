// Compile-time proof that every struct's field list adds up to the size the spec
// states for it. A typo in a field type or array length fails the build here.

#include "protocol/layout.hpp"
#include "protocol/messages/all.hpp"

namespace playerkit::protocol {
namespace {

template <class... T>
constexpr bool all_layouts_match(TypeList<T...>) {
  return (layout_matches_spec<T>() && ...);
}

static_assert(all_layouts_match(AllWireStructs{}),
              "a wire struct's fields do not add up to its kWireSize");

}  // namespace
}  // namespace playerkit::protocol
