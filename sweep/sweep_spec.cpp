// Sweep description JSON -> SweepSpec. Unknown keys are errors with a suggestion (a typo would
// otherwise silently drop a whole axis of the sweep), like the scene loader's (docs/scenes.md).
#include "sweep/sweep_spec.h"

#include <fmt/format.h>
#include <fmt/ranges.h>

#include <algorithm>
#include <cmath>
#include <fstream>
#include <nlohmann/json.hpp>
#include <sstream>

#include "support/suggest.h"

namespace shadowc::sweep {
namespace {

using nlohmann::ordered_json;

class Reader {
 public:
  explicit Reader(std::string label) : label_(std::move(label)) {}

  [[noreturn]] void fail(const std::string& path, const std::string& message) const {
    throw SweepSpecError(fmt::format("{}: error: {}: {}", label_, path, message));
  }
  const std::string& label() const { return label_; }

  void checkKeys(const ordered_json& j, const std::string& path, const std::vector<std::string>& allowed) const {
    if (!j.is_object()) fail(path, "expected an object");
    for (const auto& [key, value] : j.items()) {
      if (std::find(allowed.begin(), allowed.end(), key) != allowed.end()) continue;
      const std::string near = support::closestMatch(key, allowed);
      fail(join(path, key), near.empty() ? fmt::format("unknown field (expected one of: {})", fmt::join(allowed, ", "))
                                         : fmt::format("unknown field (did you mean '{}'?)", near));
    }
  }

  static std::string join(const std::string& path, const std::string& key) {
    return path.empty() ? key : path + "." + key;
  }

  int integer(const ordered_json& j, const std::string& path, int lo, int hi) const {
    if (!j.is_number_integer()) fail(path, "expected a whole number");
    const int64_t v = j.get<int64_t>();
    if (v < lo || v > hi) fail(path, fmt::format("{} is out of range [{}, {}]", v, lo, hi));
    return int(v);
  }

  std::string string(const ordered_json& j, const std::string& path) const {
    if (!j.is_string() || j.get<std::string>().empty()) fail(path, "expected a non-empty string");
    return j.get<std::string>();
  }

  // A size or a list of sizes: 128 or [128, 256].
  std::vector<uint32_t> sizes(const ordered_json& j, const std::string& path) const {
    std::vector<uint32_t> out;
    if (j.is_array()) {
      if (j.empty()) fail(path, "expected at least one size");
      for (size_t i = 0; i < j.size(); ++i)
        out.push_back(uint32_t(integer(j[i], fmt::format("{}[{}]", path, i), 1, 16384)));
    } else {
      out.push_back(uint32_t(integer(j, path, 1, 16384)));
    }
    return out;
  }

 private:
  std::string label_;
};

// A number as the DSL writes it: whole numbers without a fraction, the rest in the shortest
// form that reads back the same (fmt's "{}").
std::string numberText(double v) {
  if (std::abs(v) < 1e15 && v == std::round(v)) return fmt::format("{}", int64_t(v));
  return fmt::format("{}", v);
}

std::string valueText(const Reader& r, const ordered_json& v, const std::string& path) {
  if (v.is_string()) return v.get<std::string>();
  if (v.is_number()) return numberText(v.get<double>());
  r.fail(path, "expected a number or a string");
}

// A parameter's values: a list ([4, 16, "int32"]) or a range {"from", "to", "step" | "factor"}.
Param readParam(const Reader& r, const std::string& name, const ordered_json& j, const std::string& path) {
  Param p{name, {}};
  if (name.empty() ||
      !std::all_of(name.begin(), name.end(), [](char c) { return std::isalnum((unsigned char)c) || c == '_'; }))
    r.fail(path, "a parameter name is letters, digits and '_'");
  if (j.is_array()) {
    if (j.empty()) r.fail(path, "expected at least one value");
    for (size_t i = 0; i < j.size(); ++i) p.values.push_back(valueText(r, j[i], fmt::format("{}[{}]", path, i)));
  } else if (j.is_object()) {
    r.checkKeys(j, path, {"from", "to", "step", "factor"});
    if (!j.contains("from") || !j.contains("to")) r.fail(path, "a range needs \"from\" and \"to\"");
    if (j.contains("step") && j.contains("factor")) r.fail(path, "give \"step\" or \"factor\", not both");
    auto num = [&](const char* key) {
      if (!j[key].is_number()) r.fail(Reader::join(path, key), "expected a number");
      return j[key].get<double>();
    };
    const double from = num("from"), to = num("to");
    if (to < from) r.fail(path, fmt::format("\"to\" ({}) is below \"from\" ({})", to, from));
    if (j.contains("factor")) {
      const double f = num("factor");
      if (!(f > 1) || !(from > 0))
        r.fail(Reader::join(path, "factor"), "a geometric range needs factor > 1 and from > 0");
      for (double v = from; v <= to * (1 + 1e-9); v *= f) p.values.push_back(numberText(v));
    } else {
      const double step = j.contains("step") ? num("step") : 1.0;
      if (!(step > 0)) r.fail(Reader::join(path, "step"), "expected a positive step");
      // Index arithmetic, not repeated addition, so 0.1 steps do not drift.
      const int64_t n = int64_t(std::floor((to - from) / step + 1e-9)) + 1;
      for (int64_t i = 0; i < n; ++i)
        p.values.push_back(numberText(std::round((from + double(i) * step) * 1e12) / 1e12));
    }
    if (p.values.size() > 4096) r.fail(path, fmt::format("{} values; at most 4096", p.values.size()));
  } else {
    r.fail(path, "expected a list of values or a range {\"from\", \"to\", \"step\" | \"factor\"}");
  }
  return p;
}

std::vector<Param> readParams(const Reader& r, const ordered_json& j, const std::string& path) {
  if (!j.is_object()) r.fail(path, "expected an object: parameter name -> values");
  std::vector<Param> out;
  for (const auto& [name, values] : j.items()) out.push_back(readParam(r, name, values, Reader::join(path, name)));
  return out;
}

std::string readText(const Reader& r, const std::filesystem::path& file, const std::string& path) {
  std::ifstream in(file, std::ios::binary);
  if (!in) r.fail(path, fmt::format("cannot read '{}'", file.string()));
  std::ostringstream s;
  s << in.rdbuf();
  return s.str();
}

BaseFilter readFilter(const Reader& r, const ordered_json& j, const std::string& path, size_t index,
                      const std::filesystem::path& baseDir) {
  BaseFilter f;
  if (j.is_string()) {  // shorthand: a file path
    const std::filesystem::path file = baseDir / j.get<std::string>();
    f.text = readText(r, file, path);
    f.source = file.lexically_normal().string();
    f.name = file.stem().string();
    return f;
  }
  r.checkKeys(j, path, {"name", "file", "text", "set", "params"});
  if (j.contains("file") == j.contains("text")) r.fail(path, "give exactly one of \"file\" and \"text\"");
  if (j.contains("file")) {
    const std::filesystem::path file = baseDir / r.string(j["file"], Reader::join(path, "file"));
    f.text = readText(r, file, Reader::join(path, "file"));
    f.source = file.lexically_normal().string();
    f.name = file.stem().string();
  } else {
    f.text = r.string(j["text"], Reader::join(path, "text"));
    f.source = fmt::format("{}:{}", r.label(), path);
    f.name = fmt::format("filter{}", index);
  }
  if (j.contains("name")) f.name = r.string(j["name"], Reader::join(path, "name"));
  if (j.contains("set")) {
    const ordered_json& s = j["set"];
    if (!s.is_object())
      r.fail(Reader::join(path, "set"), "expected an object: setting keyword -> value text (null removes it)");
    for (const auto& [key, value] : s.items()) {
      const std::string p = Reader::join(Reader::join(path, "set"), key);
      if (value.is_null())
        f.set.emplace_back(key, std::nullopt);
      else if (value.is_string())
        f.set.emplace_back(key, value.get<std::string>());
      else
        f.set.emplace_back(key, valueText(r, value, p));
    }
  }
  if (j.contains("params")) f.params = readParams(r, j["params"], Reader::join(path, "params"));
  return f;
}

SceneEntry readScene(const Reader& r, const ordered_json& j, const std::string& path,
                     const std::filesystem::path& baseDir) {
  SceneEntry s;
  auto resolve = [&](const std::string& scene) {
    // A .json path resolves against the sweep file's folder; a bare name is a built-in.
    return scene.ends_with(".json") ? (baseDir / scene).lexically_normal().string() : scene;
  };
  if (j.is_string()) {
    s.scene = resolve(j.get<std::string>());
  } else {
    r.checkKeys(j, path, {"scene", "name", "light_size"});
    if (!j.contains("scene")) r.fail(path, "needs \"scene\": a built-in name or a .json path");
    s.scene = resolve(r.string(j["scene"], Reader::join(path, "scene")));
    if (j.contains("light_size")) {
      const ordered_json& v = j["light_size"];
      if (!v.is_number() || !(v.get<double>() >= 0) || v.get<double>() > 10000)
        r.fail(Reader::join(path, "light_size"), "expected a light width in [0, 10000] world units (0 = point light)");
      s.lightSize = v.get<double>();
    }
    if (j.contains("name")) s.label = r.string(j["name"], Reader::join(path, "name"));
  }
  if (s.label.empty()) {
    s.label = std::filesystem::path(s.scene).stem().string();
    if (s.lightSize) s.label += "_light" + numberText(*s.lightSize);
  }
  return s;
}

}  // namespace

const char* shaderKindName(ShaderKind kind) { return kind == ShaderKind::Generic ? "generic" : "specialized"; }

SweepSpec parseSweepSpec(const std::string& jsonText, const std::string& label, const std::filesystem::path& baseDir) {
  const Reader r(label);
  ordered_json j;
  try {
    j = ordered_json::parse(jsonText);
  } catch (const ordered_json::parse_error& e) {
    // nlohmann gives a byte offset; the user wants line:col.
    const size_t at = std::min<size_t>(e.byte == 0 ? 0 : e.byte - 1, jsonText.size());
    const size_t line = size_t(std::count(jsonText.begin(), jsonText.begin() + long(at), '\n')) + 1;
    const size_t lineStart = jsonText.rfind('\n', at == 0 ? 0 : at - 1);
    const size_t col = at - (lineStart == std::string::npos ? 0 : lineStart + 1) + 1;
    std::string what = e.what();
    if (const size_t p = what.find("parse error"); p != std::string::npos) what = what.substr(p);
    throw SweepSpecError(fmt::format("{}:{}:{}: error: malformed JSON: {}", label, line, col, what));
  } catch (const ordered_json::exception& e) {  // well-formed but refused, e.g. a number beyond double
    throw SweepSpecError(fmt::format("{}: error: malformed JSON: {}", label, e.what()));
  }
  r.checkKeys(j, "",
              {"name", "filters", "params", "scenes", "screen", "map", "reference_samples", "runs", "warmup", "shaders",
               "counters", "sizes"});
  SweepSpec s;
  s.name = j.contains("name") ? r.string(j["name"], "name") : std::filesystem::path(label).stem().string();
  if (!j.contains("filters") || !j["filters"].is_array() || j["filters"].empty())
    r.fail("filters", "expected a non-empty list of filters (file paths or {\"file\"|\"text\", ...})");
  for (size_t i = 0; i < j["filters"].size(); ++i)
    s.filters.push_back(readFilter(r, j["filters"][i], fmt::format("filters[{}]", i), i, baseDir));
  if (j.contains("params")) s.params = readParams(r, j["params"], "params");
  if (!j.contains("scenes") || !j["scenes"].is_array() || j["scenes"].empty())
    r.fail("scenes",
           "expected a non-empty list of scenes (built-in names, .json paths or {\"scene\", \"light_size\"})");
  for (size_t i = 0; i < j["scenes"].size(); ++i)
    s.scenes.push_back(readScene(r, j["scenes"][i], fmt::format("scenes[{}]", i), baseDir));
  for (size_t i = 0; i < s.scenes.size(); ++i)
    for (size_t k = 0; k < i; ++k)
      if (s.scenes[i].label == s.scenes[k].label)
        r.fail(fmt::format("scenes[{}]", i),
               fmt::format("two scenes are named '{}'; give one a \"name\"", s.scenes[i].label));
  if (j.contains("screen")) s.screens = r.sizes(j["screen"], "screen");
  if (j.contains("map")) s.maps = r.sizes(j["map"], "map");
  if (j.contains("sizes")) {
    if (j.contains("screen") || j.contains("map"))
      r.fail("sizes", "give either \"sizes\" (screen, map pairs) or \"screen\" and \"map\", not both");
    const ordered_json& sz = j["sizes"];
    if (!sz.is_array() || sz.empty())
      r.fail("sizes", "expected a list of [screen, map] pairs: [[128, 512], [256, 1024]]");
    for (size_t i = 0; i < sz.size(); ++i) {
      const std::string at = fmt::format("sizes[{}]", i);
      if (!sz[i].is_array() || sz[i].size() != 2) r.fail(at, "expected a [screen, map] pair");
      s.sizes.emplace_back(r.sizes(sz[i][0], at + "[0]").front(), r.sizes(sz[i][1], at + "[1]").front());
    }
  }
  if (j.contains("reference_samples"))
    s.referenceSamples = r.integer(j["reference_samples"], "reference_samples", 1, 256);
  if (j.contains("runs")) {
    if (j["runs"].is_string() && j["runs"].get<std::string>() == "auto")
      s.runs = rt::RunCount::untilPrecise();
    else if (j["runs"].is_string())
      r.fail("runs", "expected a whole number or \"auto\"");
    else
      s.runs = r.integer(j["runs"], "runs", 1, 1000);
  }
  if (j.contains("warmup")) s.warmup = r.integer(j["warmup"], "warmup", 0, 1000);
  if (j.contains("counters")) {
    if (!j["counters"].is_boolean()) r.fail("counters", "expected true or false");
    s.counters = j["counters"].get<bool>();
  }
  if (j.contains("shaders")) {
    const ordered_json& sh = j["shaders"];
    if (!sh.is_array() || sh.empty())
      r.fail("shaders", "expected a list: [\"specialized\"], [\"specialized\", \"generic\"]");
    s.shaders.clear();
    for (size_t i = 0; i < sh.size(); ++i) {
      const std::string v = r.string(sh[i], fmt::format("shaders[{}]", i));
      if (v == "specialized")
        s.shaders.push_back(ShaderKind::Specialized);
      else if (v == "generic")
        s.shaders.push_back(ShaderKind::Generic);
      else
        r.fail(fmt::format("shaders[{}]", i), fmt::format("'{}' is not a shader kind (specialized, generic)", v));
    }
  }
  return s;
}

SweepSpec loadSweepSpec(const std::filesystem::path& file) {
  std::ifstream in(file, std::ios::binary);
  if (!in) throw SweepSpecError(fmt::format("{}: error: cannot read the sweep description", file.string()));
  std::ostringstream text;
  text << in.rdbuf();
  SweepSpec s = parseSweepSpec(text.str(), file.string(), file.parent_path());
  s.file = file;
  return s;
}

}  // namespace shadowc::sweep
