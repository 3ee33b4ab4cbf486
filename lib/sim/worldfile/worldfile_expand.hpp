#pragma once
// Macro expansion (§1.3): statements become the entity tree.
//
// * `define NEW BASE ( body )` registers NEW; if NEW is defined again the
//   first definition wins (with a warning).
// * `NEW ( inst )` makes one entity whose type is the innermost non-macro
//   word. The deepest base's body is applied first, then each derived
//   macro's, then `inst`; a later assignment replaces an earlier one.
// * Children come in that same order: macro bodies' (deepest first), then
//   the instance's.
// * A macro is looked up when it is instantiated, so it must be defined
//   (textually, at top level) before the entity that uses it.

#include <vector>

#include "sim/worldfile/worldfile_statements.hpp"
#include "sim/worldfile/worldfile_tree.hpp"

namespace playerkit::sim::worldfile {

// Fills tree.world (type "world", at `file`), tree.macros and tree.warnings.
// A word that is no macro (yet) is left as the entity's type: whether it is
// a known type is the loader's to say. Throws WorldFileError: a macro
// defined in terms of itself or containing itself, nesting deeper than
// kMaxEntityDepth, more than kMaxWorldItems entities and assignments.
void expand_statements(const std::vector<Statement>& statements, const std::string& file, WorldTree& tree);

}  // namespace playerkit::sim::worldfile
