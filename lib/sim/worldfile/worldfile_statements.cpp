#include "sim/worldfile/worldfile_statements.hpp"

#include "sim/worldfile/worldfile_error.hpp"
#include "sim/worldfile/worldfile_limits.hpp"
#include "text/printable.hpp"

namespace playerkit::sim::worldfile {
namespace {

bool starts_value(TokenKind kind) {
  return kind == TokenKind::Number || kind == TokenKind::String || kind == TokenKind::OpenTuple;
}
bool is_value_end(TokenKind kind) {
  return kind == TokenKind::Number || kind == TokenKind::String || kind == TokenKind::CloseTuple;
}

Statement started(StatementKind kind, const Token& word) {
  Statement statement;
  statement.kind = kind;
  statement.word = word.text;
  statement.where = word.where;
  return statement;
}

std::string quoted_word(const std::string& word) { return "\"" + text::excerpt(word) + "\""; }

// `pose[1 2 3]` lexes as the word "pose[1" (brackets belong to words).
bool looks_like_glued_tuple(const std::string& word) {
  const auto open = word.find('[');
  if (open == std::string::npos || word.back() == ']') return false;
  const char after = open + 1 < word.size() ? word[open + 1] : ' ';
  return after == '-' || after == '+' || after == '.' || (after >= '0' && after <= '9');
}

class StatementParser {
 public:
  explicit StatementParser(const std::vector<Token>& tokens) : tokens_(tokens) {}

  std::vector<Statement> run() { return body(nullptr, 0); }

 private:
  const Token& at(std::size_t index) const { return tokens_[std::min(index, tokens_.size() - 1)]; }

  // Statements up to the ')' closing `open` (nullptr: the top level, up to
  // the end of the file).
  std::vector<Statement> body(const Token* open, int depth) {
    std::vector<Statement> statements;
    for (;;) {
      const Token& token = at(next_);
      switch (token.kind) {
        case TokenKind::Newline:
        case TokenKind::Comment:
          ++next_;
          continue;
        case TokenKind::EndOfFile:
          if (open != nullptr) {
            throw WorldFileError(open->where, "missing ')': the entity opened here is not closed");
          }
          return statements;
        case TokenKind::CloseEntity:
          if (open == nullptr) throw WorldFileError(token.where, "misplaced ')': no entity is open here");
          ++next_;
          return statements;
        case TokenKind::Word:
          if (token.text == "define") {
            if (open != nullptr) {
              throw WorldFileError(token.where, "a define is allowed only at top level, outside every entity");
            }
            statements.push_back(define());
          } else {
            statements.push_back(word_statement(depth));
          }
          continue;
        default:
          break;
      }
      std::string message = "expected a property name or an entity type, found " + describe(token);
      if ((token.kind == TokenKind::Number || token.kind == TokenKind::String) && next_ > 0 &&
          is_value_end(at(next_ - 1).kind) && at(next_ - 1).where.line == token.where.line) {
        message += " (a property has one value: put several in a [tuple])";
      }
      throw WorldFileError(token.where, message);
    }
  }

  Statement word_statement(int depth) {
    const Token& word = at(next_);
    if (looks_like_glued_tuple(word.text)) {
      throw WorldFileError(word.where, quoted_word(word.text) +
                                           " is one word: put a space between a property's name and its [tuple]");
    }
    std::size_t after = next_ + 1;
    if (starts_value(at(after).kind)) {
      next_ = after;
      Statement property = started(StatementKind::Property, word);
      value(property);
      return property;
    }
    // An entity's '(' may follow after line breaks and comments.
    while (at(after).kind == TokenKind::Newline || at(after).kind == TokenKind::Comment) ++after;
    const Token& next = at(after);
    if (next.kind == TokenKind::OpenEntity) {
      if (depth + 1 > kMaxEntityDepth) {
        throw WorldFileError(next.where, "entities nested more than " + std::to_string(kMaxEntityDepth) + " deep");
      }
      next_ = after + 1;
      Statement entity = started(StatementKind::Entity, word);
      entity.body = body(&next, depth + 1);
      return entity;
    }
    if (starts_value(next.kind)) {
      throw WorldFileError(word.where, "a property's value must start on the same line as its name (" +
                                           quoted_word(word.text) + ")");
    }
    if (next.kind == TokenKind::Word && at(next_ + 1).kind == TokenKind::Word) {
      throw WorldFileError(next.where, "the value of " + quoted_word(word.text) +
                                           " must be a number, a \"string\" or a [tuple], found " + describe(next));
    }
    const Token& immediate = at(next_ + 1);
    const bool line_ends = immediate.kind == TokenKind::Newline || immediate.kind == TokenKind::Comment;
    throw WorldFileError(word.where, quoted_word(word.text) +
                                         " must be followed by a value on the same line (a property) or by "
                                         "'(' (an entity), found " +
                                         (line_ends ? std::string("the end of the line") : describe(immediate)));
  }

  void value(Statement& property) {
    const Token& first = at(next_);
    if (first.kind != TokenKind::OpenTuple) {
      property.values.push_back(Value{first.kind == TokenKind::String, first.text, first.where});
      ++next_;
      return;
    }
    property.tuple = true;
    for (++next_;; ++next_) {
      const Token& token = at(next_);
      switch (token.kind) {
        case TokenKind::Number:
        case TokenKind::String:
          property.values.push_back(Value{token.kind == TokenKind::String, token.text, token.where});
          continue;
        case TokenKind::CloseTuple:
          ++next_;
          return;
        case TokenKind::Newline:
        case TokenKind::EndOfFile:
          throw WorldFileError(first.where, "tuples must close on one line: this '[' has no ']' on its line");
        case TokenKind::Comment:
          throw WorldFileError(token.where, "a tuple cannot hold a comment: close it with ']' on its line first");
        default:
          throw WorldFileError(token.where, "a tuple holds numbers and strings only, found " + describe(token));
      }
    }
  }

  Statement define() {
    const Token& keyword = at(next_);
    const std::string usage = " (a macro is written 'define NAME BASE ( ... )')";
    Statement statement = started(StatementKind::Define, keyword);
    statement.word.clear();
    int names = 0;
    for (++next_;; ++next_) {
      const Token& token = at(next_);
      switch (token.kind) {
        case TokenKind::Newline:
        case TokenKind::Comment:
          continue;
        case TokenKind::Word:
          if (names == 2) throw WorldFileError(token.where, "extra tokens in macro definition" + usage);
          (names++ == 0 ? statement.word : statement.base) = token.text;
          continue;
        case TokenKind::OpenEntity: {
          if (names < 2) throw WorldFileError(keyword.where, "missing name in macro definition" + usage);
          ++next_;
          statement.body = body(&token, 1);
          return statement;
        }
        default:
          throw WorldFileError(token.where, "syntax error in macro definition: expected " +
                                                std::string(names < 2 ? "a name" : "'('") + ", found " +
                                                describe(token) + usage);
      }
    }
  }

  const std::vector<Token>& tokens_;
  std::size_t next_ = 0;
};

}  // namespace

std::vector<Statement> parse_statements(const std::vector<Token>& tokens) {
  if (tokens.empty() || tokens.back().kind != TokenKind::EndOfFile) {
    throw std::invalid_argument("parse_statements: tokens must end with EndOfFile");
  }
  return StatementParser(tokens).run();
}

}  // namespace playerkit::sim::worldfile
