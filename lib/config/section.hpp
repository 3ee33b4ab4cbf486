#pragma once
// One section of a config file, e.g. `laser:0 ( port "/dev/ttyS1" pose [0 0 0] )`,
// with typed reads of its properties (server-behaviour.md §9.3).
//
// Every read_* and tuple_size() marks the property as used (even when the
// caller's fallback is returned because a tuple element is missing), so that
// ConfigFile::unused_properties() can report options no driver asked for.
// The marks are the only mutable state; a Section is not meant to be read from
// several threads at once.

#include <cstddef>
#include <string>
#include <string_view>
#include <vector>

#include "config/parser.hpp"
#include "config/property.hpp"
#include "config/units.hpp"

namespace playerkit::config {

class Section {
 public:
  Section(ParsedSection parsed, Units units);

  // The section's word, e.g. "laser:0" or "robot:6666:bob" (for a macro
  // instance, the type the macro stands for).
  const std::string& type() const { return type_; }
  // Index of the enclosing section in ConfigFile::sections(); -1 at global level.
  int parent() const { return parent_; }
  const SourceLocation& where() const { return where_; }

  // Presence test; does not count as a read.
  bool has(std::string_view name) const;
  // The property as written (for locations in a driver's own messages), or
  // nullptr; does not count as a read.
  const Property* property(std::string_view name) const;
  // In the order they first appear.
  std::vector<std::string> property_names() const;
  const std::vector<Property>& properties() const { return properties_; }

  // Plain reads use the first value, so they also work on a tuple. The
  // fallback is returned untouched (not converted) when the property is absent.
  std::string read_string(std::string_view name, std::string_view fallback) const;
  int read_int(std::string_view name, int fallback) const;           // C atoi: "12abc" -> 12
  double read_float(std::string_view name, double fallback) const;   // C atof
  double read_length(std::string_view name, double fallback) const;  // -> metres
  double read_angle(std::string_view name, double fallback) const;   // -> radians
  // A relative path is made absolute against the directory of the file the
  // value is written in; a path starting with '/' or '~' is kept as is.
  std::string read_filename(std::string_view name, std::string_view fallback) const;

  // 0 if absent, 1 for a plain value, else the number of tuple elements.
  std::size_t tuple_size(std::string_view name) const;
  // Element `index`; the fallback when the property is absent or shorter.
  std::string read_tuple_string(std::string_view name, std::size_t index,
                                std::string_view fallback) const;
  int read_tuple_int(std::string_view name, std::size_t index, int fallback) const;
  double read_tuple_float(std::string_view name, std::size_t index, double fallback) const;
  double read_tuple_length(std::string_view name, std::size_t index, double fallback) const;
  double read_tuple_angle(std::string_view name, std::size_t index, double fallback) const;

  const Units& units() const { return units_; }

 private:
  // Marks the property used and returns element `index`, or nullptr.
  const Value* read_value(std::string_view name, std::size_t index) const;

  std::string type_;
  int parent_;
  SourceLocation where_;
  std::vector<Property> properties_;
  Units units_;
};

}  // namespace playerkit::config
