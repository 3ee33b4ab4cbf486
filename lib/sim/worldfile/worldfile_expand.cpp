#include "sim/worldfile/worldfile_expand.hpp"

#include <algorithm>
#include <map>

#include "sim/worldfile/worldfile_error.hpp"
#include "sim/worldfile/worldfile_limits.hpp"
#include "text/printable.hpp"

namespace playerkit::sim::worldfile {
namespace {

std::string quoted_macro(const std::string& name) { return "\"" + text::excerpt(name) + "\""; }

class MacroExpander {
 public:
  MacroExpander(const std::vector<Statement>& statements, WorldTree& tree) : statements_(statements), tree_(tree) {}

  void run(const std::string& file) {
    tree_.world.type = "world";
    tree_.world.where = SourceLocation{file};
    for (const Statement& statement : statements_) {
      switch (statement.kind) {
        case StatementKind::Define:
          define(statement);
          break;
        case StatementKind::Property:
          assign(tree_.world, statement);
          break;
        case StatementKind::Entity:
          tree_.world.children.push_back(instantiate(statement, 1));
          break;
      }
    }
  }

 private:
  void define(const Statement& statement) {
    const auto [existing, inserted] = macros_.emplace(statement.word, &statement);
    if (inserted) {
      tree_.macros.push_back(MacroDefinition{statement.word, statement.where});
      return;
    }
    tree_.warnings.push_back(located(statement.where, "macro " + quoted_macro(statement.word) +
                                                          " is defined again; the first definition, at " +
                                                          to_string(existing->second->where) + ", is kept"));
  }

  void count_item(const SourceLocation& where) {
    if (++items_ > kMaxWorldItems) {
      throw WorldFileError(where, "more than " + std::to_string(kMaxWorldItems) +
                                      " entities and properties once macros are expanded");
    }
  }

  void assign(Entity& entity, const Statement& statement) {
    count_item(statement.where);
    Property property{statement.word, statement.where, statement.values, statement.tuple};
    for (Property& existing : entity.properties) {
      if (existing.name == statement.word) {
        existing = std::move(property);
        return;
      }
    }
    entity.properties.push_back(std::move(property));
  }

  Entity instantiate(const Statement& statement, int depth) {
    if (depth > kMaxEntityDepth) {
      throw WorldFileError(statement.where, "entities nested more than " + std::to_string(kMaxEntityDepth) +
                                                " deep once macros are expanded");
    }
    count_item(statement.where);
    std::vector<const Statement*> chain;  // the macros from the word written to the deepest base
    std::string word = statement.word;
    for (;;) {
      const auto found = macros_.find(word);
      if (found == macros_.end()) break;
      const Statement* macro = found->second;
      if (std::find(chain.begin(), chain.end(), macro) != chain.end()) {
        throw WorldFileError(statement.where, "macro " + quoted_macro(word) + " is defined in terms of itself" +
                                                  " (its definition is at " + to_string(macro->where) + ")");
      }
      if (std::find(expanding_.begin(), expanding_.end(), macro) != expanding_.end()) {
        throw WorldFileError(statement.where, "macro " + quoted_macro(word) + " contains an entity of its own type" +
                                                  " (its definition is at " + to_string(macro->where) + ")");
      }
      chain.push_back(macro);
      word = macro->base;
    }
    Entity entity;
    entity.type = word;
    entity.where = statement.where;
    for (const Statement* macro : chain) entity.macros.push_back(macro->word);
    for (auto macro = chain.rbegin(); macro != chain.rend(); ++macro) {
      expanding_.push_back(*macro);
      apply((*macro)->body, entity, depth);
      expanding_.pop_back();
    }
    apply(statement.body, entity, depth);
    return entity;
  }

  void apply(const std::vector<Statement>& body, Entity& entity, int depth) {
    for (const Statement& statement : body) {
      if (statement.kind == StatementKind::Property) {
        assign(entity, statement);
      } else if (statement.kind == StatementKind::Entity) {
        entity.children.push_back(instantiate(statement, depth + 1));
      }
    }
  }

  const std::vector<Statement>& statements_;
  WorldTree& tree_;
  std::map<std::string, const Statement*> macros_;                // defined so far
  std::vector<const Statement*> expanding_;                       // macro bodies being applied
  std::size_t items_ = 0;
};

}  // namespace

void expand_statements(const std::vector<Statement>& statements, const std::string& file, WorldTree& tree) {
  MacroExpander(statements, tree).run(file);
}

}  // namespace playerkit::sim::worldfile
