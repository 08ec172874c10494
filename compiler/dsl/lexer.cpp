// Lexer: bytes -> tokens, linear time, no recursion (a 10 MB input costs one pass).
#include "dsl/lexer.h"

#include <cmath>
#include <cstdlib>

namespace shadowc::dsl {
namespace {

bool isNameStart(char c) { return (c >= 'a' && c <= 'z') || (c >= 'A' && c <= 'Z') || c == '_'; }
bool isDigit(char c) { return c >= '0' && c <= '9'; }
bool isNameChar(char c) { return isNameStart(c) || isDigit(c); }

// Offset of the first byte that makes `s` not UTF-8 text (NUL counts), or npos.
size_t firstNonText(std::string_view s, const char** why) {
  for (size_t i = 0; i < s.size();) {
    const auto c = static_cast<unsigned char>(s[i]);
    if (c == 0) return *why = "NUL byte", i;
    if (c < 0x80) {
      ++i;
      continue;
    }
    int extra = 0;
    unsigned minCode = 0;
    if ((c & 0xE0) == 0xC0)
      extra = 1, minCode = 0x80;
    else if ((c & 0xF0) == 0xE0)
      extra = 2, minCode = 0x800;
    else if ((c & 0xF8) == 0xF0)
      extra = 3, minCode = 0x10000;
    else
      return *why = "invalid UTF-8", i;
    unsigned code = c & (0x3F >> extra);
    for (int k = 1; k <= extra; ++k) {
      if (i + k >= s.size()) return *why = "invalid UTF-8", i;
      const auto cc = static_cast<unsigned char>(s[i + k]);
      if ((cc & 0xC0) != 0x80) return *why = "invalid UTF-8", i;
      code = (code << 6) | (cc & 0x3F);
    }
    if (code < minCode || code > 0x10FFFF || (code >= 0xD800 && code <= 0xDFFF)) return *why = "invalid UTF-8", i;
    i += static_cast<size_t>(extra) + 1;
  }
  return std::string_view::npos;
}

}  // namespace

std::string describe(const Token& t) {
  switch (t.kind) {
    case TokenKind::Name:
      return "name '" + std::string(t.text) + "'";
    case TokenKind::Number:
      return "number '" + std::string(t.text) + "'";
    case TokenKind::Size:
      return "size '" + std::string(t.text) + "'";
    case TokenKind::End:
      return "end of file";
    default:
      return "'" + std::string(t.text) + "'";
  }
}

std::vector<Token> lex(std::string_view src, DiagnosticSink& sink, std::vector<int>* badLines) {
  std::vector<Token> tokens;
  const char* why = "";
  if (const size_t bad = firstNonText(src, &why); bad != std::string_view::npos) {
    int line = 1, col = 1;
    for (size_t i = 0; i < bad; ++i) src[i] == '\n' ? (++line, col = 1) : ++col;
    sink.report(DiagId::notText, line, col, 1, why, bad);
    tokens.push_back(Token{TokenKind::End, {}, line, col, true});
    return tokens;
  }
  size_t i = 0;
  int line = 1;
  size_t lineBegin = 0;
  bool atLineStart = true;
  auto column = [&](size_t at) { return static_cast<int>(at - lineBegin) + 1; };
  auto markBad = [&] {
    if (badLines && (badLines->empty() || badLines->back() != line)) badLines->push_back(line);
  };
  while (i < src.size() && !sink.stopped()) {
    const char c = src[i];
    if (c == '\n') {
      ++i, ++line, lineBegin = i, atLineStart = true;
      continue;
    }
    if (c == ' ' || c == '\t' || c == '\r') {
      ++i;
      continue;
    }
    if (c == '#') {
      while (i < src.size() && src[i] != '\n') ++i;
      continue;
    }
    Token t;
    t.line = line, t.column = column(i), t.lineStart = atLineStart;
    const size_t start = i;
    if (isNameStart(c)) {
      while (i < src.size() && isNameChar(src[i])) ++i;
      t.kind = TokenKind::Name;
      t.text = src.substr(start, i - start);
      if (t.text.size() > kMaxNameLength) {
        markBad();
        sink.report(DiagId::identifierTooLong, t.line, t.column, static_cast<int>(t.text.size()), t.text.size(),
                    kMaxNameLength);
        continue;
      }
    } else if (isDigit(c) || ((c == '-' || c == '+' || c == '.') && i + 1 < src.size() &&
                              (isDigit(src[i + 1]) || (src[i + 1] == '.' && c != '.')))) {
      // A number, or a size WxH: the whole run of number-ish characters is one token so that
      // "1.2.3" or "3x" is one error rather than several.
      ++i;  // the first character (digit, sign or '.') always belongs to the token
      while (i < src.size() && (isNameChar(src[i]) || src[i] == '.' ||
                                ((src[i] == '-' || src[i] == '+') && (src[i - 1] == 'e' || src[i - 1] == 'E'))))
        ++i;
      t.text = src.substr(start, i - start);
      const std::string text(t.text);
      const int len = static_cast<int>(text.size());
      if (const size_t x = text.find('x'); x != std::string::npos && isDigit(text[0])) {
        const std::string w = text.substr(0, x), h = text.substr(x + 1);
        auto allDigits = [](const std::string& s) {
          if (s.empty() || s.size() > 6) return false;
          for (char d : s)
            if (!isDigit(d)) return false;
          return true;
        };
        if (!allDigits(w) || !allDigits(h)) {
          markBad();
          sink.report(DiagId::malformedSize, t.line, t.column, len, text);
          continue;
        }
        t.kind = TokenKind::Size, t.width = std::atoi(w.c_str()), t.height = std::atoi(h.c_str());
      } else {
        char* end = nullptr;
        const double v = std::strtod(text.c_str(), &end);
        if (end != text.c_str() + text.size()) {
          markBad();
          sink.report(DiagId::malformedNumber, t.line, t.column, len, text);
          continue;
        }
        if (!std::isfinite(v) || std::fabs(v) > 1e30) {
          markBad();
          sink.report(DiagId::numberOutOfRange, t.line, t.column, len, text);
          continue;
        }
        t.kind = TokenKind::Number, t.number = v;
        t.integer = text.find_first_of(".eE") == std::string::npos;
      }
    } else {
      ++i;
      t.text = src.substr(start, 1);
      switch (c) {
        case '{':
          t.kind = TokenKind::LBrace;
          break;
        case '}':
          t.kind = TokenKind::RBrace;
          break;
        case '(':
          t.kind = TokenKind::LParen;
          break;
        case ')':
          t.kind = TokenKind::RParen;
          break;
        case ',':
          t.kind = TokenKind::Comma;
          break;
        case ':':
          t.kind = TokenKind::Colon;
          break;
        default: {
          // Multi-byte UTF-8 characters are reported whole.
          size_t n = 1;
          while (start + n < src.size() && (static_cast<unsigned char>(src[start + n]) & 0xC0) == 0x80) ++n;
          i = start + n;
          markBad();
          sink.report(DiagId::invalidCharacter, t.line, t.column, 1, std::string(src.substr(start, n)));
          continue;
        }
      }
    }
    atLineStart = false;
    tokens.push_back(t);
  }
  Token end;
  end.kind = TokenKind::End, end.line = line, end.column = column(i), end.lineStart = true;
  tokens.push_back(end);
  return tokens;
}

}  // namespace shadowc::dsl
