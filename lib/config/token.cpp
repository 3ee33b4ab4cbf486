#include "config/token.hpp"

#include "text/printable.hpp"

namespace playerkit::config {

std::string describe(const Token& token) {
  switch (token.kind) {
    case TokenKind::Word:
      return "word '" + text::excerpt(token.text) + "'";
    case TokenKind::Number:
      return "number '" + text::excerpt(token.text) + "'";
    case TokenKind::String:
      return "string \"" + text::excerpt(token.text) + "\"";
    case TokenKind::OpenParen:
      return "'('";
    case TokenKind::CloseParen:
      return "')'";
    case TokenKind::OpenBracket:
      return "'['";
    case TokenKind::CloseBracket:
      return "']'";
    case TokenKind::Newline:
      return "newline";
    case TokenKind::EndOfFile:
      return "end of file";
  }
  return "token";
}

}  // namespace playerkit::config
