#pragma once
// A property as written in a section: `name value` or `name [ v1 v2 ... ]`.

#include <string>
#include <vector>

#include "config/source_location.hpp"

namespace playerkit::config {

struct Value {
  std::string text;        // as written; a string's contents without the quotes
  bool is_string = false;  // "..." rather than a number
  SourceLocation where;

  friend bool operator==(const Value&, const Value&) = default;
};

struct Property {
  std::string name;
  std::vector<Value> values;  // one for a plain value, any number for a tuple
  bool is_tuple = false;
  SourceLocation where;  // of the name
  // Set by every Section read so that unread properties can be reported.
  // Mutable because drivers read through a const Section.
  mutable bool used = false;
};

}  // namespace playerkit::config
