#pragma once
// Turns tokens into sections and properties (server-behaviour.md §9.2):
//
//   file     := { newline | define | global-property | section }
//   section  := word {newline} "(" { newline | property | section } ")"
//   property := word value            -- the value on the name's line
//   value    := number | string | "[" { number | string } "]"   -- one line
//   define   := "define" word word {newline} "(" body ")"
//
// A section whose word names a macro gets the macro's type and a copy of its
// properties and subsections, then its own items on top. Only unit_length and
// unit_angle may be set outside a section. A property given twice in one
// section keeps its first position and takes the later value.

#include <string>
#include <string_view>
#include <vector>

#include "config/property.hpp"
#include "config/token.hpp"
#include "config/units.hpp"

namespace playerkit::config {

struct ParsedSection {
  std::string type;  // the section's word, or the type a macro stands for
  int parent = -1;   // index of the enclosing section; -1 at global level
  SourceLocation where;
  std::vector<Property> properties;
};

struct ParsedConfig {
  std::vector<ParsedSection> sections;  // in order of their opening word, parents first
  Units units;
};

// `tokens` must end with an EndOfFile token. Throws ConfigError.
ParsedConfig parse_tokens(const std::vector<Token>& tokens);

// tokenize_with_includes() followed by parse_tokens().
ParsedConfig parse_text(std::string_view text, const std::string& file);

}  // namespace playerkit::config
