#include "config/parser.hpp"

#include <algorithm>
#include <utility>

#include "config/errors.hpp"
#include "config/limits.hpp"
#include "text/printable.hpp"
#include "config/includes.hpp"

namespace playerkit::config {
namespace {

// Sections are built as a tree first because a macro body is a subtree that
// gets copied into every instance; the tree is flattened once at the end.
struct SectionTree {
  std::string type;
  SourceLocation where;
  std::vector<Property> properties;
  std::vector<SectionTree> children;
};

struct Macro {
  std::string name;
  SourceLocation where;
  SectionTree body;  // its type is the type the macro stands for
  std::size_t items = 0;  // sections and property values in body, for kMaxConfigItems
  int height = 1;         // levels of sections in body, for kMaxSectionDepth
};

int height_of(const SectionTree& tree) {
  int below = 0;
  for (const SectionTree& child : tree.children) below = std::max(below, height_of(child));
  return below + 1;
}

bool starts_value(TokenKind kind) {
  return kind == TokenKind::Number || kind == TokenKind::String || kind == TokenKind::OpenBracket;
}

// A later definition takes the value; the first keeps its place in the order.
void set_property(std::vector<Property>& properties, Property property) {
  const auto same_name = [&](const Property& p) { return p.name == property.name; };
  const auto existing = std::find_if(properties.begin(), properties.end(), same_name);
  if (existing == properties.end()) {
    properties.push_back(std::move(property));
  } else {
    *existing = std::move(property);
  }
}

std::string quoted_value(const Value& value) {
  return value.is_string ? "\"" + text::excerpt(value.text) + "\"" : text::excerpt(value.text);
}

void flatten(SectionTree& tree, int parent, std::vector<ParsedSection>& out) {
  const int index = static_cast<int>(out.size());
  out.push_back(ParsedSection{std::move(tree.type), parent, std::move(tree.where),
                              std::move(tree.properties)});
  for (SectionTree& child : tree.children) flatten(child, index, out);
}

class Parser {
 public:
  explicit Parser(const std::vector<Token>& tokens) : tokens_(tokens) {}

  ParsedConfig run() {
    std::vector<SectionTree> top_level;
    while (true) {
      const Token& token = peek();
      switch (token.kind) {
        case TokenKind::EndOfFile: {
          ParsedConfig config;
          config.units = units_;
          for (SectionTree& tree : top_level) flatten(tree, -1, config.sections);
          return config;
        }
        case TokenKind::Newline:
          ++pos_;
          break;
        case TokenKind::CloseParen:
          throw ConfigError(token.where, "unmatched ')'");
        case TokenKind::Word:
          if (token.text == "define") {
            parse_define();
          } else if (word_starts_property()) {
            parse_global_property();
          } else {
            top_level.push_back(parse_section());
          }
          break;
        default:
          throw unexpected_item(token);
      }
    }
  }

 private:
  const Token& peek(std::size_t ahead = 0) const {
    return tokens_[std::min(pos_ + ahead, tokens_.size() - 1)];
  }
  // The end-of-file token is never consumed, so peek() always has a token.
  const Token& take() {
    const Token& token = peek();
    if (token.kind != TokenKind::EndOfFile) ++pos_;
    return token;
  }
  void skip_newlines() {
    while (peek().kind == TokenKind::Newline) ++pos_;
  }

  static ConfigError unexpected_item(const Token& token) {
    return ConfigError(token.where,
                       "syntax error: expected a property or a section, found " + describe(token));
  }

  // The word at the current position starts a property if a value follows on
  // its line, and a section if '(' follows, possibly after line breaks.
  bool word_starts_property() const {
    const Token& word = peek();
    const Token& next = peek(1);
    if (starts_value(next.kind)) return true;
    std::size_t ahead = 1;
    while (peek(ahead).kind == TokenKind::Newline) ++ahead;
    const Token& after_breaks = peek(ahead);
    if (after_breaks.kind == TokenKind::OpenParen) return false;
    if (ahead > 1 && starts_value(after_breaks.kind)) {
      throw ConfigError(word.where,
                        "missing value for '" + text::excerpt(word.text) +
                            "': a property's value must be on the same line as its name");
    }
    throw ConfigError(next.where, "syntax error: expected a value or '(' after '" + text::excerpt(word.text) +
                                      "', found " + describe(next));
  }

  const Macro* find_macro(const std::string& name) const {
    const auto named = [&](const Macro& m) { return m.name == name; };
    const auto found = std::find_if(macros_.begin(), macros_.end(), named);
    return found == macros_.end() ? nullptr : &*found;
  }

  SectionTree parse_section() {
    const Token& word = take();
    SectionTree section;
    const Macro* macro = find_macro(word.text);
    // Checked before a macro's body is copied: macros made of macros double
    // in size at each level, so copying first could exhaust memory.
    enter_section(word, macro);
    if (macro != nullptr) {
      section = macro->body;
    } else {
      section.type = word.text;
    }
    section.where = word.where;
    skip_newlines();
    const Token& open = take();  // word_starts_property() made sure it is '('
    parse_body(section, open, "section '" + text::excerpt(word.text) + "'");
    --depth_;
    return section;
  }

  // Nesting and size limits (limits.hpp): deep nesting would overflow the
  // stack of this recursive parser, and macro copies multiply memory.
  void enter_section(const Token& word, const Macro* macro) {
    if (depth_ + (macro != nullptr ? macro->height : 1) > kMaxSectionDepth) {
      throw ConfigError(word.where, "sections nested more than " + std::to_string(kMaxSectionDepth) + " deep");
    }
    count_items(macro != nullptr ? macro->items : 1, word.where);
    ++depth_;
  }

  void count_items(std::size_t count, const SourceLocation& where) {
    items_ += count;
    if (items_ > kMaxConfigItems) {
      throw ConfigError(where, "more than " + std::to_string(kMaxConfigItems) +
                                   " sections and values once macros are expanded");
    }
  }

  // The items between '(' (already taken) and its ')'.
  void parse_body(SectionTree& section, const Token& open, const std::string& what) {
    while (true) {
      const Token& token = peek();
      switch (token.kind) {
        case TokenKind::Newline:
          ++pos_;
          break;
        case TokenKind::CloseParen:
          ++pos_;
          return;
        case TokenKind::EndOfFile:
          throw ConfigError(open.where, "unmatched '(': " + what + " is not closed with ')'");
        case TokenKind::Word:
          if (token.text == "define") {
            throw ConfigError(token.where, "'define' is only allowed at global level");
          }
          if (word_starts_property()) {
            Property property = parse_property();
            count_items(property.values.size(), property.where);
            set_property(section.properties, std::move(property));
          } else {
            section.children.push_back(parse_section());
          }
          break;
        default:
          throw unexpected_item(token);
      }
    }
  }

  Property parse_property() {
    const Token& name = take();
    Property property;
    property.name = name.text;
    property.where = name.where;
    const Token& first = take();
    if (first.kind != TokenKind::OpenBracket) {
      property.values.push_back(value_of(first));
      return property;
    }
    property.is_tuple = true;
    while (true) {
      const Token& element = take();
      switch (element.kind) {
        case TokenKind::CloseBracket:
          return property;
        case TokenKind::Number:
        case TokenKind::String:
          property.values.push_back(value_of(element));
          break;
        case TokenKind::Newline:
        case TokenKind::EndOfFile:
          throw ConfigError(first.where, "unmatched '[': the tuple of '" + text::excerpt(name.text) +
                                             "' must end with ']' on the same line");
        default: {
          const std::string expected = "a number or a string in the tuple of '" + text::excerpt(name.text) + "'";
          throw ConfigError(element.where,
                            "syntax error: expected " + expected + ", found " + describe(element));
        }
      }
    }
  }

  // The token just taken, a number or a string, as a value. A word glued to a
  // number ("1e-3", "10cm") would otherwise surface later as a puzzling error
  // about the word.
  Value value_of(const Token& token) const {
    const Token& next = peek();
    const bool glued_word =
        token.kind == TokenKind::Number && next.kind == TokenKind::Word &&
        next.where.file == token.where.file && next.where.line == token.where.line &&
        next.where.column == token.where.column + static_cast<int>(token.text.size());
    if (glued_word) {
      throw ConfigError(token.where, "malformed number '" + text::excerpt(token.text + next.text) +
                                         "': a number may only contain digits, '.', '+' and '-'");
    }
    return Value{token.text, token.kind == TokenKind::String, token.where};
  }

  void parse_global_property() {
    const Token& name = peek();
    const bool is_length = name.text == "unit_length";
    if (!is_length && name.text != "unit_angle") {
      throw ConfigError(name.where, "property '" + text::excerpt(name.text) +
                                        "' is outside any section (only unit_length and "
                                        "unit_angle may be set at global level)");
    }
    const Property property = parse_property();
    if (property.is_tuple) {
      throw ConfigError(property.where, property.name + " takes a single value, not a tuple");
    }
    const Value& value = property.values.front();
    if (is_length) {
      const auto factor = length_unit(value.text);
      if (!factor) {
        throw ConfigError(value.where, "unknown unit_length " + quoted_value(value) +
                                           " (expected \"m\", \"cm\" or \"mm\")");
      }
      units_.length = *factor;
    } else {
      const auto factor = angle_unit(value.text);
      if (!factor) {
        throw ConfigError(value.where, "unknown unit_angle " + quoted_value(value) +
                                           " (expected \"degrees\" or \"radians\")");
      }
      units_.angle = *factor;
    }
  }

  void parse_define() {
    ++pos_;  // the word "define"
    const Token& name = take();
    if (name.kind != TokenKind::Word) {
      throw ConfigError(name.where, "syntax error: expected a macro name after 'define', found " +
                                        describe(name));
    }
    const Token& base = take();
    if (base.kind != TokenKind::Word) {
      throw ConfigError(base.where, "syntax error: expected the type of macro '" + text::excerpt(name.text) +
                                        "' after its name, found " + describe(base));
    }
    skip_newlines();
    const Token& open = take();
    if (open.kind != TokenKind::OpenParen) {
      throw ConfigError(open.where, "syntax error: expected '(' after 'define " + text::excerpt(name.text) + " " +
                                        text::excerpt(base.text) + "', found " + describe(open));
    }
    if (const Macro* existing = find_macro(name.text)) {
      throw ConfigError(name.where, "macro '" + text::excerpt(name.text) + "' is already defined at " +
                                        to_string(existing->where));
    }
    Macro macro{name.text, name.where, {}};
    const std::size_t items_before = items_;
    const Macro* base_macro = find_macro(base.text);
    enter_section(base, base_macro);
    if (base_macro != nullptr) {
      macro.body = base_macro->body;
    } else {
      macro.body.type = base.text;
    }
    parse_body(macro.body, open, "macro '" + text::excerpt(name.text) + "'");
    --depth_;
    macro.items = items_ - items_before;
    macro.height = height_of(macro.body);
    macros_.push_back(std::move(macro));
  }

  const std::vector<Token>& tokens_;
  std::size_t pos_ = 0;
  std::vector<Macro> macros_;
  int depth_ = 0;           // sections open around the current token
  std::size_t items_ = 0;   // sections and property values made so far
  Units units_;
};

}  // namespace

ParsedConfig parse_tokens(const std::vector<Token>& tokens) { return Parser(tokens).run(); }

ParsedConfig parse_text(std::string_view text, const std::string& file) {
  return parse_tokens(tokenize_with_includes(text, file));
}

}  // namespace playerkit::config
