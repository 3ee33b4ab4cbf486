#include "sim/worldfile/worldfile_syntax.hpp"

#include "sim/worldfile/worldfile_expand.hpp"
#include "sim/worldfile/worldfile_includes.hpp"
#include "sim/worldfile/worldfile_statements.hpp"

namespace playerkit::sim::worldfile {
namespace {

WorldTree tree_from_tokens(TokenizedWorld tokenized, const std::string& name) {
  const std::vector<Statement> statements = parse_statements(tokenized.tokens);
  tokenized.tokens.clear();
  WorldTree tree;
  tree.files = std::move(tokenized.files);
  expand_statements(statements, name, tree);
  return tree;
}

}  // namespace

WorldTree read_world_tree(const std::filesystem::path& file) {
  return tree_from_tokens(tokenize_world_file(file), file.string());
}

WorldTree parse_world_text(std::string_view text, const std::string& name, const std::filesystem::path& directory) {
  return tree_from_tokens(tokenize_world_text(text, name, directory), name);
}

}  // namespace playerkit::sim::worldfile
