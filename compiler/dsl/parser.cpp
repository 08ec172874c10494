// Parser of the filter-description language (grammar: docs/dsl.md). Recursive descent over
// arguments only, bounded by kMaxNesting; statement-level recovery at the next line.
#include "dsl/parser.h"

namespace shadowc::dsl {
namespace {

class Parser {
 public:
  Parser(const std::vector<Token>& tokens, DiagnosticSink& sink) : t_(tokens), sink_(sink) {}

  File parseFile() {
    File file;
    if (peek().kind == TokenKind::End) {
      if (sink_.errors() == 0) report(DiagId::emptyFile, peek());
      return file;
    }
    if (!isName(peek(), "filter")) {
      report(DiagId::expectedFilter, peek(), describe(peek()));
      if (peek().kind == TokenKind::Name) sink_.suggest(support::closestMatch(peek().text, {"filter"}));
      // Resynchronize on the first `filter` further down, if any.
      while (peek().kind != TokenKind::End && !isName(peek(), "filter")) ++pos_;
      if (peek().kind == TokenKind::End) return file;
    }
    const Token& kw = next();
    file.hasFilter = true;
    FilterDecl& f = file.filter;
    f.line = kw.line, f.column = kw.column;
    if (peek().kind == TokenKind::Name && !peek().lineStart) {
      f.name = std::string(next().text);
    } else {
      report(DiagId::expectedFilterName, peek(), describe(peek()));
    }
    if (peek().kind == TokenKind::LBrace) {
      next();
    } else {
      report(DiagId::expectedOpenBrace, peek(), describe(peek()));
      if (peek().kind != TokenKind::Name) skipStatement();
    }
    while (!sink_.stopped()) {
      const Token& tok = peek();
      if (tok.kind == TokenKind::End) {
        report(DiagId::missingCloseBrace, tok, f.name.empty() ? "<unnamed>" : f.name, f.line);
        return file;
      }
      if (tok.kind == TokenKind::RBrace) {
        next();
        break;
      }
      if (tok.kind != TokenKind::Name) {
        report(DiagId::expectedSetting, tok, describe(tok));
        ++pos_;
        skipStatement();
        continue;
      }
      parseSetting(f);
    }
    if (!sink_.stopped() && peek().kind != TokenKind::End)
      report(DiagId::trailingContent, peek(), describe(peek()), f.name);
    return file;
  }

 private:
  const Token& peek(size_t ahead = 0) const { return t_[std::min(pos_ + ahead, t_.size() - 1)]; }
  const Token& next() {
    const Token& tok = t_[pos_];
    if (pos_ + 1 < t_.size()) ++pos_;
    return tok;
  }
  static bool isName(const Token& tok, std::string_view text) {
    return tok.kind == TokenKind::Name && tok.text == text;
  }
  template <typename... Args>
  void report(DiagId id, const Token& at, const Args&... args) {
    sink_.report(id, at.line, at.column, static_cast<int>(std::max<size_t>(at.text.size(), 1)), args...);
  }
  // Statement-level recovery: skip to the first token of a later line, or to a '}'.
  void skipStatement() {
    while (true) {
      const Token& tok = peek();
      if (tok.kind == TokenKind::End || tok.kind == TokenKind::RBrace) return;
      if (tok.lineStart && tok.kind == TokenKind::Name) return;
      ++pos_;
    }
  }
  // Points just past `tok` ("expected ')'" belongs after the last thing written).
  void reportAfter(DiagId id, const Token& tok, const std::string& a, const std::string& b, const std::string& c) {
    sink_.report(id, tok.line, tok.column + static_cast<int>(tok.text.size()), 1, a, b, c);
  }

  void parseSetting(FilterDecl& f) {
    const Token& kw = next();
    Setting s;
    s.keyword = std::string(kw.text);
    s.line = kw.line, s.column = kw.column;
    const Token& after = peek();
    if (after.lineStart || after.kind == TokenKind::RBrace || after.kind == TokenKind::End) {
      f.settings.push_back(std::move(s));  // no value: the checker decides whether one is needed
      return;
    }
    s.hasValue = true;
    if (!parseTerm(s.value, 0)) {
      skipStatement();
      return;
    }
    const Token& end = peek();
    if (!end.lineStart && end.kind != TokenKind::RBrace && end.kind != TokenKind::End) {
      report(DiagId::expectedEndOfLine, end, s.keyword, describe(end));
      skipStatement();
    }
    f.settings.push_back(std::move(s));
  }

  // term = NAME [ '(' [arg {',' arg}] ')' ] | NUMBER | SIZE
  bool parseTerm(Value& v, int depth) {
    const Token& tok = peek();
    v.line = tok.line, v.column = tok.column, v.length = static_cast<int>(tok.text.size());
    v.text = std::string(tok.text);
    switch (tok.kind) {
      case TokenKind::Number:
        next();
        v.kind = Value::Kind::Number, v.number = tok.number, v.integer = tok.integer;
        return true;
      case TokenKind::Size:
        next();
        v.kind = Value::Kind::Size, v.width = tok.width, v.height = tok.height;
        return true;
      case TokenKind::Name:
        next();
        v.kind = Value::Kind::Name;
        if (peek().kind == TokenKind::LParen) return parseArguments(v, depth);
        return true;
      default:
        report(DiagId::expectedValue, tok, describe(tok));
        return false;
    }
  }

  bool parseArguments(Value& v, int depth) {
    const Token& open = next();
    if (depth + 1 > kMaxNesting) {
      report(DiagId::nestingTooDeep, open, kMaxNesting);
      return false;
    }
    v.hasArguments = true;
    if (peek().kind == TokenKind::RParen) {
      next();
      return true;
    }
    while (true) {
      Argument a;
      a.line = peek().line, a.column = peek().column;
      if (peek().kind == TokenKind::Name && peek(1).kind == TokenKind::Colon) {
        a.name = std::string(next().text);
        next();
      }
      if (!parseTerm(a.value, depth + 1)) return false;
      v.arguments.push_back(std::move(a));
      const Token& sep = peek();
      if (sep.kind == TokenKind::Comma) {
        next();
        continue;
      }
      if (sep.kind == TokenKind::RParen) {
        next();
        return true;
      }
      reportAfter(DiagId::unterminatedArguments, t_[pos_ - 1], std::to_string(open.line), std::to_string(open.column),
                  describe(sep));
      return false;
    }
  }

  const std::vector<Token>& t_;
  DiagnosticSink& sink_;
  size_t pos_ = 0;
};

}  // namespace

File parse(const std::vector<Token>& tokens, DiagnosticSink& sink) { return Parser(tokens, sink).parseFile(); }

}  // namespace shadowc::dsl
