// The typed value reader of checker phase 1 (value_reader.h).
#include "spec/value_reader.h"

#include <algorithm>
#include <cmath>

#include "spec/filter_spec.h"
#include "support/suggest.h"

namespace shadowc::spec {

using dsl::Argument;
using dsl::DiagId;
using dsl::Value;

std::string joinNames(const Names& names) {
  std::string out;
  for (std::string_view n : names) out += (out.empty() ? "" : ", ") + std::string(n);
  return out;
}

std::string describeValue(const Value& v) {
  switch (v.kind) {
    case Value::Kind::Number:
      return "number '" + v.text + "'";
    case Value::Kind::Size:
      return "size '" + v.text + "'";
    case Value::Kind::Name:
      return "name '" + v.text + (v.hasArguments ? "(...)'" : "'");
  }
  return "'" + v.text + "'";
}

std::optional<size_t> ValueReader::variant(const Value& v, const std::string& what, const Names& options) {
  if (v.kind != Value::Kind::Name) {
    at(v, DiagId::wrongType, what, "one of: " + joinNames(options), describeValue(v));
    return std::nullopt;
  }
  auto it = std::find(options.begin(), options.end(), v.text);
  if (it == options.end()) {
    at(v, DiagId::unknownValue, v.text, what, joinNames(options));
    sink_.suggest(support::closestMatch(v.text, options));
    return std::nullopt;
  }
  return static_cast<size_t>(it - options.begin());
}
std::optional<size_t> ValueReader::choice(const Value* v, const std::string& what, const Names& options) {
  auto idx = variant(*v, what, options);
  if (idx && v->hasArguments) {
    at(*v, DiagId::takesNoArguments, v->text);
    return std::nullopt;
  }
  return idx;
}
std::optional<double> ValueReader::number(const Value* v, const std::string& what, const Range& r,
                                          const std::string& rangeText) {
  if (v->kind != Value::Kind::Number) {
    at(*v, DiagId::wrongType, what, "a number", describeValue(*v));
    return std::nullopt;
  }
  if (!r.contains(v->number)) {
    at(*v, DiagId::outOfRange, what, rangeText.empty() ? r.text() : rangeText, v->text);
    return std::nullopt;
  }
  return v->number;
}
std::optional<int> ValueReader::integer(const Value* v, const std::string& what, int lo, int hi,
                                        const std::string& rangeText) {
  if (v->kind == Value::Kind::Number && !v->integer && v->number != std::floor(v->number)) {
    at(*v, DiagId::notInteger, what, v->text);
    return std::nullopt;
  }
  auto n = number(v, what, Range{double(lo), double(hi)}, rangeText);
  if (!n) return std::nullopt;
  return static_cast<int>(*n);
}
std::optional<int> ValueReader::squareSize(const Value* v, const std::string& what, int lo, int hi) {
  if (v->kind != Value::Kind::Size) {
    at(*v, DiagId::wrongType, what, "a size NxN such as 3x3", describeValue(*v));
    return std::nullopt;
  }
  if (v->width != v->height) {
    at(*v, DiagId::sizeNotSquare, what, v->width, v->height);
    return std::nullopt;
  }
  if (v->width < lo || v->width > hi) {
    at(*v, DiagId::outOfRange, what, fmt::format("NxN with N in [{}, {}]", lo, hi), v->text);
    return std::nullopt;
  }
  return v->width;
}

std::optional<int> ValueReader::quadtreeHeight(const Value* v, const std::string& what) {
  if (v->kind == Value::Kind::Number && v->number == std::floor(v->number) &&
      (v->number < kMinQuadtreeHeight || v->number > kMaxQuadtreeHeight)) {
    at(*v, DiagId::quadtreeHeightRange, what, kMinQuadtreeHeight, kMaxQuadtreeHeight, v->text);
    return std::nullopt;
  }
  return integer(v, what, kMinQuadtreeHeight, kMaxQuadtreeHeight);
}

bool ValueReader::bind(const Value& call, const std::vector<Param>& params, Bound& out) {
  if (params.empty()) {
    if (!call.arguments.empty()) {
      at(call, DiagId::takesNoArguments, call.text);
      return false;
    }
    return true;
  }
  Names names, positional;
  for (const Param& p : params) {
    names.push_back(p.name);
    if (p.positional) positional.push_back(p.name);
  }
  bool ok = true;
  size_t nextPositional = 0;
  for (const Argument& a : call.arguments) {
    std::string_view name;
    if (a.name.empty()) {
      if (nextPositional >= positional.size()) {
        at(a.value, DiagId::tooManyArguments, call.text, positional.size());
        ok = false;
        continue;
      }
      name = positional[nextPositional++];
    } else {
      auto it = std::find(names.begin(), names.end(), a.name);
      if (it == names.end()) {
        sink_.report(DiagId::unknownArgument, a.line, a.column, static_cast<int>(a.name.size()), a.name, call.text,
                     joinNames(names));
        sink_.suggest(support::closestMatch(a.name, names));
        ok = false;
        continue;
      }
      name = *it;
    }
    if (out.count(name)) {
      sink_.report(DiagId::duplicateArgument, a.line, a.column,
                   static_cast<int>(a.name.empty() ? a.value.length : a.name.size()), name, call.text);
      ok = false;
      continue;
    }
    out[name] = &a.value;
  }
  return ok;
}
std::optional<ValueReader::SceneOr> ValueReader::numberOrScene(const Value* v, const std::string& what,
                                                               const Range& r) {
  if (!v || (v->kind == Value::Kind::Name && v->text == "scene" && !v->hasArguments)) return SceneOr{true, 0.0};
  if (v->kind == Value::Kind::Name) {
    at(*v, DiagId::wrongType, what, "a number or 'scene'", describeValue(*v));
    return std::nullopt;
  }
  if (auto n = number(v, what, r)) return SceneOr{false, *n};
  return std::nullopt;
}

}  // namespace shadowc::spec
