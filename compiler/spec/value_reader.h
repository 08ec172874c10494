// Checker phase 1, the typed value reader under read_settings.cpp: one value of a setting read
// as a variant, an enum choice, a number or whole number in a range, a square size or a quadtree
// height, and call arguments bound to parameters (positional in declaration order, or by name).
// Each failure is one located diagnostic (E03xx) with a suggestion where one exists; the reader
// knows no setting, so every setting is read with the same words and ranges.
#pragma once

#include <fmt/format.h>

#include <map>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "dsl/ast.h"
#include "dsl/diagnostics.h"

namespace shadowc::spec {

using Names = std::vector<std::string_view>;

// "a, b, c" for messages.
std::string joinNames(const Names& names);
// "number '3'", "size '3x3'", "name 'pcf(...)'": what a value is, for wrongType messages.
std::string describeValue(const dsl::Value& v);

struct Range {
  double lo, hi;
  bool loOpen = false, hiOpen = false;
  std::string text() const { return fmt::format("in {}{}, {}{}", loOpen ? "(" : "[", lo, hi, hiOpen ? ")" : "]"); }
  bool contains(double v) const { return (loOpen ? v > lo : v >= lo) && (hiOpen ? v < hi : v <= hi); }
};

struct Param {
  std::string_view name;
  bool positional = false;
};
using Bound = std::map<std::string_view, const dsl::Value*>;

class ValueReader {
 public:
  explicit ValueReader(dsl::DiagnosticSink& sink) : sink_(sink) {}

  template <typename... Args>
  void at(const dsl::Value& v, dsl::DiagId id, const Args&... args) {
    sink_.report(id, v.line, v.column, v.length, args...);
  }
  // Index of v's name in `options` (v may carry arguments), or nullopt after a diagnostic.
  std::optional<size_t> variant(const dsl::Value& v, const std::string& what, const Names& options);
  // Like variant() for a plain enum value: arguments are an error.
  std::optional<size_t> choice(const dsl::Value* v, const std::string& what, const Names& options);
  std::optional<double> number(const dsl::Value* v, const std::string& what, const Range& r,
                               const std::string& rangeText = "");
  std::optional<int> integer(const dsl::Value* v, const std::string& what, int lo, int hi,
                             const std::string& rangeText = "");
  std::optional<int> squareSize(const dsl::Value* v, const std::string& what, int lo, int hi);
  // One range for every quadtree height (kernel and blocker walks, Next/Child tables, unrolled
  // traversal): height 0 would be a single box query (that is 'kernel penumbra'), and height 6
  // has 5461 nodes, past what a constant table or an unrolled walk should fold in.
  std::optional<int> quadtreeHeight(const dsl::Value* v, const std::string& what);
  // A number in `r`, or the bare name 'scene' (the runtime supplies the value): nullopt after a
  // diagnostic, else {fromScene, value}. `what` names the argument in messages.
  struct SceneOr {
    bool fromScene = true;
    double value = 0;
  };
  std::optional<SceneOr> numberOrScene(const dsl::Value* v, const std::string& what, const Range& r);
  // Binds call arguments to parameters (positional in declaration order, or by name).
  bool bind(const dsl::Value& call, const std::vector<Param>& params, Bound& out);

  static const dsl::Value* get(const Bound& b, std::string_view name) {
    auto it = b.find(name);
    return it == b.end() ? nullptr : it->second;
  }
  // "'name' of 'call'", how messages name an argument.
  static std::string arg(std::string_view name, const dsl::Value& call) {
    return fmt::format("'{}' of '{}'", name, call.text);
  }

 protected:
  dsl::DiagnosticSink& sink_;
};

}  // namespace shadowc::spec
