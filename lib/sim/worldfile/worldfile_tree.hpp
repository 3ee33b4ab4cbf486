#pragma once
// A world file after parsing and macro expansion: a tree of entities with
// their properties, every one keeping where it was written.

#include <string>
#include <string_view>
#include <vector>

#include "sim/worldfile/worldfile_location.hpp"

namespace playerkit::sim::worldfile {

struct Value {
  bool is_string = false;  // a "string" (text without quotes), else a number as written
  std::string text;
  SourceLocation where;
};

struct Property {
  std::string name;
  SourceLocation where;  // of the name, in the assignment that won
  std::vector<Value> values;
  bool tuple = false;  // written as [ ... ]
};

struct Entity {
  std::string type;                 // the innermost non-macro word: "position" for a pioneer2dx
  std::vector<std::string> macros;  // the macros it went through, as written first: "pioneer2dx", "pioneer_base"
  SourceLocation where;             // where the entity was written (the instance, not the define)
  // In order of first assignment. A later assignment of the same name
  // replaces the whole value, a tuple included (Stage 3/4; 1.3 replaced
  // element by element).
  std::vector<Property> properties;
  // The macro bodies' children first (deepest base first), then the
  // instance's own, each in written order.
  std::vector<Entity> children;

  [[nodiscard]] const Property* find(std::string_view name) const;
  // The macro or type word it was written with ("pioneer2dx").
  [[nodiscard]] const std::string& written_type() const { return macros.empty() ? type : macros.front(); }
};

struct MacroDefinition {
  std::string name;
  SourceLocation where;  // of its `define`
};

struct WorldTree {
  Entity world;                        // type "world": the top-level properties and entities
  std::vector<std::string> files;      // the main file, then each include as read
  std::vector<MacroDefinition> macros;  // every define that took effect (first definitions), in file order
  std::vector<std::string> warnings;   // "file:line:col: message"
};

}  // namespace playerkit::sim::worldfile
