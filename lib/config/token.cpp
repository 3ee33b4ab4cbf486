#include "config/token.hpp"

namespace playerkit::config {

std::string describe(const Token& token) {
  switch (token.kind) {
    case TokenKind::Word:
      return "word '" + token.text + "'";
    case TokenKind::Number:
      return "number '" + token.text + "'";
    case TokenKind::String:
      return "string \"" + token.text + "\"";
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
