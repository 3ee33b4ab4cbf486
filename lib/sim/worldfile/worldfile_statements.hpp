#pragma once
// The grammar of §1.2, as Stage's parser behaves: the token stream becomes
// statements (properties, entities, defines) with macros not yet expanded.
//
//   file      := { property | entity | define }
//   define    := 'define' WORD WORD '(' body ')'          top level only
//   entity    := WORD { newline | comment } '(' body ')'
//   property  := WORD value                               value on the name's line
//   value     := NUMBER | STRING | '[' { NUMBER | STRING } ']'   a tuple on one line

#include <string>
#include <vector>

#include "sim/worldfile/worldfile_lexer.hpp"
#include "sim/worldfile/worldfile_tree.hpp"

namespace playerkit::sim::worldfile {

enum class StatementKind { Property, Entity, Define };

struct Statement {
  StatementKind kind = StatementKind::Property;
  std::string word;       // the property's name, the entity's type or macro, the define's new name
  std::string base;       // a define's base
  SourceLocation where;   // of `word` ('define' for a define)
  std::vector<Value> values;  // a property's
  bool tuple = false;
  std::vector<Statement> body;  // an entity's or a define's
};

// Throws WorldFileError at the first token that breaks the grammar, saying
// what was expected there.
std::vector<Statement> parse_statements(const std::vector<Token>& tokens);

}  // namespace playerkit::sim::worldfile
