#pragma once
// Internal: reading one entity's properties as numbers, lengths, angles,
// strings and tuples, the way Stage reads them back (§1.5, §1.6), and
// telling which properties were never read.

#include <cstdint>
#include <initializer_list>
#include <optional>
#include <set>
#include <string>
#include <string_view>
#include <vector>

#include "sim/world/model_spec.hpp"
#include "sim/worldfile/worldfile_tree.hpp"

namespace playerkit::sim::worldfile {

// §1.5: unit_length and unit_angle, read from the world after the whole
// file is parsed, apply to every length and angle property of the file.
struct Units {
  double metres_per_length = 1.0;
  double radians_per_angle = std::numbers::pi / 180.0;
};
Units read_units(const WorldTree& tree, std::vector<std::string>& warnings);

enum class Quantity { plain, length, angle };

class PropertyReader {
 public:
  PropertyReader(const Entity& entity, const Units& units, std::vector<std::string>& warnings);

  [[nodiscard]] const Entity& entity() const { return entity_; }

  // The property, now counted as read; nullptr when absent.
  const Property* take(std::string_view name);
  bool has(std::string_view name);
  // Properties read and deliberately unused (GUI, controllers, drawing).
  void skip(std::initializer_list<std::string_view> names);

  // One value (the first, if a tuple is given, as Stage does) converted as
  // C's atof would (with a warning when the text is not all number).
  double number(std::string_view name, double fallback, Quantity quantity = Quantity::plain);
  int integer(std::string_view name, int fallback);
  std::string text(std::string_view name, const std::string& fallback);
  // Every value of a tuple as text (colour lists).
  std::vector<std::string> texts(std::string_view name);

  // A tuple of at least `layout.size()` numbers, converted by quantity;
  // extra values are ignored, as in Stage. nullopt when absent. A shorter
  // tuple is an error (Stage 3/4 exit, 1.3 crashed): "pose needs 4 values
  // [x y z a], found 3". `shape` names the elements for that message.
  std::optional<std::vector<double>> tuple(std::string_view name, std::initializer_list<Quantity> layout,
                                           std::string_view shape);

  // Numbers of a value anywhere (a tuple element), as number() converts them.
  double number_of(const Value& value, Quantity quantity);

  // A warning for each property never taken, skipped or asked about:
  // "file:line:col: unknown property "colr" of a position, ignored (did you
  // mean "color"?)". Properties for which `ignorable` is true are not named.
  void report_unread(bool (*ignorable)(std::string_view name) = nullptr);

  void warn(const SourceLocation& where, const std::string& message);
  [[nodiscard]] const Units& units() const { return units_; }

 private:
  const Entity& entity_;
  Units units_;
  std::vector<std::string>& warnings_;
  std::set<std::string, std::less<>> asked_;
};

// "gui_*" and other drawing-only properties.
bool is_gui_property(std::string_view name);

}  // namespace playerkit::sim::worldfile
