// Checker and normalizer: AST -> FilterSpec (docs/dsl.md lists every setting, default and range).
// Three phases, so the order of settings in a file never matters:
//   1. read: each setting's value and arguments, typed and range-checked (E03xx);
//   2. normalize: defaults that depend on other settings (kernel from blocker, sampling from
//      kernel, exponents from the storage precision, splits from the layer count);
//   3. combinations: impossible pairs are errors with the reason (E04xx), dubious ones are
//      warnings (W05xx).
#include "spec/check.h"

#include <algorithm>
#include <cmath>
#include <map>

#include "spec/precision.h"

namespace shadowc::spec {
namespace {

using dsl::Argument;
using dsl::DiagId;
using dsl::Setting;
using dsl::Value;
using Names = std::vector<std::string_view>;

std::string join(const Names& names) {
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
using Bound = std::map<std::string_view, const Value*>;

const Names kSettings = {"light",    "depth", "moments",  "storage", "blur",      "mips",     "blocker", "kernel",
                         "sampling", "bias",  "fallback", "contact", "early_out", "bleeding", "map_size"};

class Checker {
 public:
  Checker(const dsl::FilterDecl& f, dsl::DiagnosticSink& sink) : f_(f), sink_(sink) {}

  FilterSpec run() {
    errorsBefore_ = sink_.errors();
    spec_.name = f_.name;
    spec_.location = SourceLocation{sink_.file(), f_.line, f_.column};
    std::map<std::string_view, const Setting*> seen;
    for (const Setting& s : f_.settings) {
      if (sink_.stopped()) break;
      auto known = std::find(kSettings.begin(), kSettings.end(), s.keyword);
      if (known == kSettings.end()) {
        sink_.report(DiagId::unknownSetting, s.line, s.column, static_cast<int>(s.keyword.size()), s.keyword);
        sink_.suggest(dsl::closestMatch(s.keyword, kSettings));
        continue;
      }
      // `depth` and `moments` are the two spellings of one axis: the representation.
      const bool isRepresentation = s.keyword == "depth" || s.keyword == "moments";
      const std::string_view group = isRepresentation ? std::string_view("representation") : *known;
      if (const Setting* first = seen[group]) {
        const std::string label = isRepresentation && first->keyword != s.keyword
                                      ? "representation ('" + first->keyword + "' or '" + s.keyword + "')"
                                      : s.keyword;
        sink_.report(DiagId::duplicateSetting, s.line, s.column, static_cast<int>(s.keyword.size()), label,
                     first->line);
        sink_.report(DiagId::firstSetHere, first->line, first->column, static_cast<int>(first->keyword.size()),
                     first->keyword);
        continue;
      }
      seen[group] = &s;
      if (std::binary_search(f_.badLines.begin(), f_.badLines.end(), s.line)) continue;  // already reported
      if (!s.hasValue && s.keyword != "depth") {
        sink_.report(DiagId::missingValue, s.line, s.column, static_cast<int>(s.keyword.size()), s.keyword);
        continue;
      }
      read(s);
    }
    if (sink_.stopped()) return spec_;
    normalize();
    // A setting that failed to read keeps its default, so combination checks would report
    // follow-on errors about settings the user did write: check combinations on clean input only.
    if (sink_.errors() == errorsBefore_ && f_.badLines.empty()) combinations();
    return spec_;
  }

 private:
  // ---- reporting helpers ---------------------------------------------------------------------
  template <typename... Args>
  void at(const Value& v, DiagId id, const Args&... args) {
    sink_.report(id, v.line, v.column, v.length, args...);
  }
  // Where a combination error points: the value of the setting when present, else the filter.
  template <typename... Args>
  void atSetting(const Setting* s, DiagId id, const Args&... args) {
    if (s && s->hasValue)
      sink_.report(id, s->value.line, s->value.column, s->value.length, args...);
    else if (s)
      sink_.report(id, s->line, s->column, static_cast<int>(s->keyword.size()), args...);
    else
      sink_.report(id, f_.line, f_.column, 6, args...);
  }

  // ---- typed readers ---------------------------------------------------------------------------
  // Index of v's name in `options` (v may carry arguments), or nullopt after a diagnostic.
  std::optional<size_t> variant(const Value& v, const std::string& what, const Names& options) {
    if (v.kind != Value::Kind::Name) {
      at(v, DiagId::wrongType, what, "one of: " + join(options), describeValue(v));
      return std::nullopt;
    }
    auto it = std::find(options.begin(), options.end(), v.text);
    if (it == options.end()) {
      at(v, DiagId::unknownValue, v.text, what, join(options));
      sink_.suggest(dsl::closestMatch(v.text, options));
      return std::nullopt;
    }
    return static_cast<size_t>(it - options.begin());
  }
  // Like variant() for a plain enum value: arguments are an error.
  std::optional<size_t> choice(const Value* v, const std::string& what, const Names& options) {
    auto idx = variant(*v, what, options);
    if (idx && v->hasArguments) {
      at(*v, DiagId::takesNoArguments, v->text);
      return std::nullopt;
    }
    return idx;
  }
  std::optional<double> number(const Value* v, const std::string& what, const Range& r,
                               const std::string& rangeText = "") {
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
  std::optional<int> integer(const Value* v, const std::string& what, int lo, int hi,
                             const std::string& rangeText = "") {
    if (v->kind == Value::Kind::Number && !v->integer && v->number != std::floor(v->number)) {
      at(*v, DiagId::notInteger, what, v->text);
      return std::nullopt;
    }
    auto n = number(v, what, Range{double(lo), double(hi)}, rangeText);
    if (!n) return std::nullopt;
    return static_cast<int>(*n);
  }
  std::optional<int> squareSize(const Value* v, const std::string& what, int lo, int hi) {
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

  // Binds call arguments to parameters (positional in declaration order, or by name).
  bool bind(const Value& call, const std::vector<Param>& params, Bound& out) {
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
                       join(names));
          sink_.suggest(dsl::closestMatch(a.name, names));
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
  static const Value* get(const Bound& b, std::string_view name) {
    auto it = b.find(name);
    return it == b.end() ? nullptr : it->second;
  }
  static std::string arg(std::string_view name, const Value& call) {
    return fmt::format("'{}' of '{}'", name, call.text);
  }

  // ---- phase 1: read settings ------------------------------------------------------------------
  void read(const Setting& s) {
    const Value& v = s.value;
    const std::string what = "'" + s.keyword + "'";
    if (s.keyword == "light")
      light_ = &s, readLight(v, what);
    else if (s.keyword == "depth")
      readDepth(s);
    else if (s.keyword == "moments")
      representation_ = &s, readMoments(v, what);
    else if (s.keyword == "storage")
      storage_ = &s, readStorage(v, what);
    else if (s.keyword == "blur")
      blur_ = &s, readBlur(v, what);
    else if (s.keyword == "mips") {
      mips_ = &s;
      if (auto c = choice(&v, what, {"off", "on"})) spec_.prefilter.mips = *c == 1;
    } else if (s.keyword == "blocker")
      blocker_ = &s, readBlocker(v, what);
    else if (s.keyword == "kernel")
      kernel_ = &s, readKernel(v, what);
    else if (s.keyword == "sampling")
      sampling_ = &s, readSampling(v, what);
    else if (s.keyword == "bias")
      readBias(v, what);
    else if (s.keyword == "fallback")
      fallback_ = &s, readFallback(v, what);
    else if (s.keyword == "contact")
      contact_ = &s, readContact(v, what);
    else if (s.keyword == "early_out") {
      if (auto c = choice(&v, what, {"none", "minmax"})) spec_.earlyOutMinMax = *c == 1;
    } else if (s.keyword == "bleeding")
      bleeding_ = &s, readBleeding(v, what);
    else if (s.keyword == "map_size") {
      if (auto n = integer(&v, what, 16, 16384)) spec_.mapSize = *n;
    }
  }

  void readLight(const Value& v, const std::string& what) {
    auto idx = variant(v, what, {"area", "disk", "point"});
    if (!idx) return;
    Bound b;
    if (*idx == 2) {
      if (bind(v, {}, b)) spec_.light = LightSpec{LightShape::Point, false, 0.0};
      return;
    }
    spec_.light.shape = *idx == 0 ? LightShape::Rect : LightShape::Disk;
    if (!bind(v, {{"size", true}}, b)) return;
    const Value* size = get(b, "size");
    if (!size || (size->kind == Value::Kind::Name && size->text == "scene" && !size->hasArguments)) {
      spec_.light.sizeFromScene = true, spec_.light.size = 0.0;
      return;
    }
    if (size->kind == Value::Kind::Name) {
      at(*size, DiagId::wrongType, arg("size", v), "a number or 'scene'", describeValue(*size));
      return;
    }
    if (auto n = number(size, arg("size", v), Range{0, 1e4, true})) {
      spec_.light.sizeFromScene = false, spec_.light.size = *n;
      lightSizeGiven_ = true;
    }
  }

  void readDepth(const Setting& s) {
    representation_ = &s;
    if (s.hasValue) at(s.value, DiagId::takesNoArguments, s.keyword);
    spec_.representation = Representation::Depth;
  }

  void readMoments(const Value& v, const std::string& what) {
    auto idx = variant(v, what, {"linear", "exp", "evsm2", "evsm4", "power_cdf", "msm"});
    if (!idx) return;
    spec_.representation = Representation::Moments;
    const Warp warps[] = {Warp::Linear, Warp::Exp, Warp::Evsm2, Warp::Evsm4, Warp::PowerCdf, Warp::Msm};
    MomentsSpec& m = spec_.moments;
    m.warp = warps[*idx];
    std::vector<Param> params;
    if (m.warp == Warp::Exp || m.warp == Warp::Evsm2 || m.warp == Warp::Evsm4) params.push_back({"exponent", true});
    if (m.warp == Warp::Evsm4) params.push_back({"negative_exponent", true});
    if (m.warp == Warp::Msm) params.push_back({"moment_bias", true});
    if (m.warp != Warp::Exp && m.warp != Warp::PowerCdf && m.warp != Warp::Msm)
      params.push_back({"min_variance", false});
    for (std::string_view p : {"layers", "split", "overlap"}) params.push_back({p, false});
    Bound b;
    bind(v, params, b);
    if (const Value* x = get(b, "layers")) {
      // 0 layers would store nothing; 16 layers of rg32f is already 128 bytes per texel.
      if (auto n =
              integer(x, arg("layers", v), 1, 16, "at least 1 (a moments map has one layer or more) and at most 16"))
        m.layers = *n;
    }
    if (const Value* x = get(b, "overlap")) {
      if (auto n = number(x, arg("overlap", v), Range{0, 0.25})) m.overlap = *n;
    }
    if (const Value* x = get(b, "exponent")) {
      if (auto n = number(x, arg("exponent", v), Range{0, 100, true})) m.positiveExponent = *n, exponent_ = x;
    }
    if (const Value* x = get(b, "negative_exponent")) {
      if (auto n = number(x, arg("negative_exponent", v), Range{0, 100, true}))
        m.negativeExponent = *n, negativeExponent_ = x;
    }
    if (const Value* x = get(b, "min_variance")) {
      if (auto n = number(x, arg("min_variance", v), Range{0, 1})) m.minVariance = *n, minVariance_ = x;
    }
    if (const Value* x = get(b, "moment_bias")) {
      // 0 would leave the Hankel matrix of a single depth singular (Algorithm 3 divides by it).
      if (auto n = number(x, arg("moment_bias", v), Range{0, 0.01, true})) m.momentBias = *n, momentBias_ = x;
    }
    if (const Value* x = get(b, "split")) readSplit(*x, arg("split", v));
  }

  void readSplit(const Value& v, const std::string& what) {
    auto idx = variant(v, what, {"uniform", "explicit", "lloyd"});
    if (!idx) return;
    MomentsSpec& m = spec_.moments;
    split_ = &v;
    Bound b;
    if (*idx == 0) {
      if (bind(v, {}, b)) m.split = SplitPlacement::Uniform;
    } else if (*idx == 2) {
      m.split = SplitPlacement::Lloyd;
      if (bind(v, {{"iterations", true}}, b))
        if (const Value* x = get(b, "iterations"))
          if (auto n = integer(x, arg("iterations", v), 1, 64)) m.lloydIterations = *n;
    } else {
      m.split = SplitPlacement::Explicit;
      explicitSplits_.clear();
      if (v.arguments.empty()) {
        at(v, DiagId::missingArgument, v.text, "boundaries");
        return;
      }
      for (const Argument& a : v.arguments) {
        if (!a.name.empty()) {
          sink_.report(DiagId::unknownArgument, a.line, a.column, static_cast<int>(a.name.size()), a.name, v.text,
                       "(positional depth boundaries only)");
          return;
        }
        auto n = number(&a.value, "a split boundary", Range{0, 1});
        if (!n) return;
        explicitSplits_.push_back(*n);
      }
      explicitOk_ = true;
    }
  }

  void readStorage(const Value& v, const std::string& what) {
    auto idx = variant(v, what, {"fp32", "fp16", "unorm16", "sat"});
    if (!idx) return;
    Bound b;
    const StorageFormat formats[] = {StorageFormat::Fp32, StorageFormat::Fp16, StorageFormat::Unorm16};
    if (*idx < 3) {
      if (bind(v, {}, b)) spec_.storage = StorageSpec{formats[*idx], SatKind::None};
      return;
    }
    if (!bind(v, {{"kind", true}, {"format", false}}, b)) return;
    const Value* kind = get(b, "kind");
    if (!kind) {
      at(v, DiagId::missingArgument, "sat", "kind (int32, fp32_centered or fp32)");
      return;
    }
    auto k = choice(kind, arg("kind", v), {"int32", "fp32_centered", "fp32"});
    if (!k) return;
    const SatKind kinds[] = {SatKind::Int32, SatKind::Fp32Centered, SatKind::Fp32Naive};
    spec_.storage = StorageSpec{StorageFormat::Fp32, kinds[*k]};
    if (const Value* f = get(b, "format"))
      if (auto fi = choice(f, arg("format", v), {"fp32", "fp16", "unorm16"})) spec_.storage.format = formats[*fi];
  }

  void readBlur(const Value& v, const std::string& what) {
    auto idx = variant(v, what, {"none", "box", "gaussian"});
    if (!idx) return;
    Bound b;
    if (*idx == 0) {
      if (bind(v, {}, b)) spec_.prefilter.blur = BlurKind::None, spec_.prefilter.blurRadius = 0;
      return;
    }
    spec_.prefilter.blur = *idx == 1 ? BlurKind::Box : BlurKind::Gaussian;
    spec_.prefilter.blurRadius = 2;
    if (bind(v, {{"radius", true}}, b))
      if (const Value* r = get(b, "radius"))
        if (auto n = integer(r, arg("radius", v), 1, 32)) spec_.prefilter.blurRadius = *n;
  }

  void readBlocker(const Value& v, const std::string& what) {
    auto idx = variant(v, what, {"none", "search", "moments"});
    if (!idx) return;
    BlockerSpec& bl = spec_.blocker;
    Bound b;
    if (*idx == 0) {
      if (bind(v, {}, b)) bl.kind = BlockerKind::None;
    } else if (*idx == 1) {
      bl.kind = BlockerKind::Search;
      if (!bind(v, {{"taps", true}, {"pattern", false}}, b)) return;
      if (const Value* x = get(b, "taps"))
        if (auto n = integer(x, arg("taps", v), 1, 64)) bl.taps = *n;
      if (const Value* x = get(b, "pattern"))
        if (auto c = choice(x, arg("pattern", v), {"poisson", "grid"}))
          bl.pattern = *c == 0 ? SamplePattern::Poisson : SamplePattern::Grid;
    } else {
      // vssm-yang2010 sec. 5.4: the blocker estimate has its own subdivision; the paper's
      // "mixed" default is uniform m = 5 for the blocker.
      bl.kind = BlockerKind::Moments;
      bl.subdivision = Subdivision::Uniform;
      if (!bind(v, {{"subdivision", true}}, b)) return;
      const Value* sub = get(b, "subdivision");
      if (!sub) return;
      auto si = variant(*sub, arg("subdivision", v), {"uniform", "quadtree", "none"});
      if (!si) return;
      Bound sb;
      if (*si == 2) {
        if (bind(*sub, {}, sb)) bl.subdivision = Subdivision::None;
      } else if (*si == 0) {
        bl.subdivision = Subdivision::Uniform;
        if (bind(*sub, {{"m", true}}, sb))
          if (const Value* x = get(sb, "m"))
            if (auto n = integer(x, arg("m", *sub), 1, 16)) bl.uniformM = *n;
      } else {
        bl.subdivision = Subdivision::Quadtree;
        if (bind(*sub, {{"height", true}}, sb))
          if (const Value* x = get(sb, "height"))
            if (auto n = integer(x, arg("height", *sub), 0, 6)) bl.quadtreeHeight = *n, blockerHeight_ = x;
      }
    }
  }

  void readKernel(const Value& v, const std::string& what) {
    auto idx = variant(v, what, {"fixed", "penumbra", "uniform", "quadtree"});
    if (!idx) return;
    KernelSpec& k = spec_.kernel;
    Bound b;
    std::vector<Param> params;
    if (*idx == 0) params = {{"size", true}};
    if (*idx == 2) params = {{"n", true}};
    if (*idx == 3) params = {{"height", true}, {"traversal", false}};
    if (*idx != 0) params.insert(params.end(), {{"max", false}, {"lit_threshold", false}});
    bind(v, params, b);
    if (*idx == 0) {
      k.size = KernelSize::Fixed, k.subdivision = Subdivision::None;
      const Value* x = get(b, "size");
      if (!x) {
        at(v, DiagId::missingArgument, "fixed", "size");
        return;
      }
      if (auto n = integer(x, arg("size", v), 1, 63)) {
        if (*n % 2 == 0)
          at(*x, DiagId::sizeMustBeOdd, arg("size", v), *n);
        else
          k.fixedTexels = *n;
      }
      return;
    }
    k.size = KernelSize::Penumbra;
    k.subdivision = *idx == 1 ? Subdivision::None : *idx == 2 ? Subdivision::Uniform : Subdivision::Quadtree;
    if (const Value* x = get(b, "n"))
      if (auto n = integer(x, arg("n", v), 1, 32)) k.uniformN = *n;
    if (const Value* x = get(b, "height"))
      if (auto n = integer(x, arg("height", v), 0, 6)) k.quadtreeHeight = *n, kernelHeight_ = x;
    if (const Value* x = get(b, "traversal"))
      if (auto c = choice(x, arg("traversal", v), {"table", "unrolled"}))
        k.traversal = *c == 0 ? QuadtreeTraversal::Table : QuadtreeTraversal::Unrolled;
    if (const Value* x = get(b, "max"))
      if (auto n = number(x, arg("max", v), Range{1, 4096})) k.maxTexels = *n;
    if (const Value* x = get(b, "lit_threshold"))
      if (auto n = number(x, arg("lit_threshold", v), Range{0, 0.5})) k.litThreshold = *n;
  }

  void readSampling(const Value& v, const std::string& what) {
    auto idx = variant(v, what, {"grid", "bilinear", "poisson"});
    if (!idx) return;
    SamplingSpec& s = spec_.sampling;
    Bound b;
    if (*idx < 2) {
      s.pattern = *idx == 0 ? PcfPattern::Grid : PcfPattern::Bilinear;
      if (!bind(v, {{"size", true}}, b)) return;
      const Value* x = get(b, "size");
      if (!x) {
        at(v, DiagId::missingArgument, v.text, "size");
        return;
      }
      if (auto n = squareSize(x, arg("size", v), 1, 16)) s.gridN = *n;
      return;
    }
    s.pattern = PcfPattern::Poisson;
    if (!bind(v, {{"taps", true}, {"rotate", false}}, b)) return;
    if (const Value* x = get(b, "taps"))
      if (auto n = integer(x, arg("taps", v), 1, 64)) s.taps = *n;
    if (const Value* x = get(b, "rotate"))
      if (auto c = choice(x, arg("rotate", v), {"stable", "none"}))
        s.rotation = *c == 0 ? Rotation::Stable : Rotation::None;
  }

  void readBias(const Value& v, const std::string& what) {
    auto idx = variant(v, what, {"constant", "slope", "normal_offset"});
    if (!idx) return;
    BiasSpec& bias = spec_.bias;
    const BiasKind kinds[] = {BiasKind::Constant, BiasKind::SlopeScaled, BiasKind::NormalOffset};
    bias.kind = kinds[*idx];
    const std::string_view first = *idx == 0 ? "value" : *idx == 1 ? "slope" : "offset";
    std::vector<Param> params = {{first, true}};
    if (*idx != 0) params.push_back({"constant", false});
    Bound b;
    if (!bind(v, params, b)) return;
    const Value* x = get(b, first);
    if (!x && *idx != 1) {
      at(v, DiagId::missingArgument, v.text, first);
      return;
    }
    if (*idx == 0) {
      if (auto n = number(x, arg(first, v), Range{0, 1})) bias.constant = *n;
    } else if (*idx == 1) {
      if (x)
        if (auto n = number(x, arg(first, v), Range{0, 10})) bias.slope = *n;
    } else {
      if (auto n = number(x, arg(first, v), Range{0, 10})) bias.normalOffset = *n;
    }
    if (const Value* c = get(b, "constant"))
      if (auto n = number(c, arg("constant", v), Range{0, 1})) bias.constant = *n;
  }

  void readFallback(const Value& v, const std::string& what) {
    auto idx = variant(v, what, {"none", "pcf"});
    if (!idx) return;
    Bound b;
    if (*idx == 0) {
      if (bind(v, {}, b)) spec_.fallback = FallbackSpec{false, 2};
      return;
    }
    spec_.fallback = FallbackSpec{true, 2};
    if (bind(v, {{"size", true}}, b))
      if (const Value* x = get(b, "size"))
        if (auto n = squareSize(x, arg("size", v), 1, 8)) spec_.fallback.n = *n;
  }

  void readContact(const Value& v, const std::string& what) {
    auto idx = variant(v, what, {"none", "pcf"});
    if (!idx) return;
    Bound b;
    if (*idx == 0) {
      if (bind(v, {}, b)) spec_.contact = ContactSpec{false, 3, 0.01};
      return;
    }
    spec_.contact = ContactSpec{true, 3, 0.01};
    if (!bind(v, {{"size", true}, {"epsilon", false}}, b)) return;
    if (const Value* x = get(b, "size"))
      if (auto n = squareSize(x, arg("size", v), 1, 8)) spec_.contact.n = *n;
    if (const Value* x = get(b, "epsilon"))
      if (auto n = number(x, arg("epsilon", v), Range{0, 1, true})) spec_.contact.epsilon = *n;
  }

  void readBleeding(const Value& v, const std::string& what) {
    auto idx = variant(v, what, {"none", "reduce"});
    if (!idx) return;
    Bound b;
    if (*idx == 0) {
      if (bind(v, {}, b)) spec_.moments.bleedingReduction = 0.0;
      return;
    }
    if (!bind(v, {{"amount", true}}, b)) return;
    const Value* x = get(b, "amount");
    if (!x) {
      at(v, DiagId::missingArgument, "reduce", "amount");
      return;
    }
    // linstep(amount, 1, p) divides by (1 - amount): 1 itself is a division by zero.
    if (auto n = number(x, arg("amount", v), Range{0, 1, false, true})) spec_.moments.bleedingReduction = *n;
  }

  // ---- phase 2: defaults that depend on other settings -----------------------------------------
  void normalize() {
    MomentsSpec& m = spec_.moments;
    const bool moments = spec_.representation == Representation::Moments;
    if (!moments) m.layers = 1;
    // Kernel: penumbra-driven when there is a blocker estimate; otherwise a fixed region that
    // matches the PCF sampling (grid/bilinear NxN -> N rounded up to odd, Poisson -> 5, none -> 1).
    if (!kernel_) {
      KernelSpec& k = spec_.kernel;
      k.subdivision = Subdivision::None;
      if (spec_.blocker.kind != BlockerKind::None) {
        k.size = KernelSize::Penumbra;
      } else {
        k.size = KernelSize::Fixed;
        int w = 1;
        if (sampling_ && spec_.sampling.pattern != PcfPattern::Poisson) w = spec_.sampling.gridN | 1;
        if (sampling_ && spec_.sampling.pattern == PcfPattern::Poisson) w = 5;
        k.fixedTexels = w;
      }
    }
    // Sampling (depth representation): a fixed kernel of W texels is sampled W x W; a penumbra
    // kernel with Poisson taps and stable rotation (pcss-blog.txt).
    if (!sampling_ && !moments) {
      if (spec_.kernel.size == KernelSize::Fixed)
        spec_.sampling = SamplingSpec{PcfPattern::Grid, spec_.kernel.fixedTexels, 16, Rotation::Stable};
      else
        spec_.sampling = SamplingSpec{PcfPattern::Poisson, 3, 16, Rotation::Stable};
    }
    // Exponents: the default is the largest safe one for the storage, at most 40 / 5.
    const ExponentLimit limit = warpExponentLimit(spec_.storage, spec_.mapSize);
    const double safe = std::floor(limit.maxExponent * 10.0) / 10.0;
    const bool exponential = moments && (m.warp == Warp::Exp || m.warp == Warp::Evsm2 || m.warp == Warp::Evsm4);
    if (!exponent_ && exponential) m.positiveExponent = std::min(40.0, safe);
    if (!negativeExponent_ && exponential) m.negativeExponent = std::min(5.0, safe);
    // fp16 moments need a larger variance floor (vsm-tutorial: variance = max(variance, 0.0005)).
    if (!minVariance_ && moments && spec_.storage.format == StorageFormat::Fp16 && spec_.storage.sat == SatKind::None)
      m.minVariance = 5e-4;
    // Moment bias: the paper's 3e-5 for 16-bit storage (unorm16 or the 16.16 int32 SAT, both
    // quantized by sec. 4.3); fp32 needs less, 3e-6 (docs/techniques.md: measured in fp32).
    if (!momentBias_ && moments && m.warp == Warp::Msm) m.momentBias = msmDefaultBias(spec_.storage);
    // Splits: layers+1 boundaries in [0,1]. Lloyd starts uniform; the planner refines them with
    // the scene's depth histogram (lauritzen2008 sec. 4.1).
    if (m.split == SplitPlacement::Explicit && explicitOk_) {
      m.splits = explicitSplits_;
    } else {
      m.splits.clear();
      for (int i = 0; i <= m.layers; ++i) m.splits.push_back(static_cast<double>(i) / m.layers);
    }
    if (spec_.prefilter.blur == BlurKind::None) spec_.prefilter.blurRadius = 0;
  }

  // ---- phase 3: combinations -----------------------------------------------------------------
  void combinations() {
    const bool moments = spec_.representation == Representation::Moments;
    const bool sat = spec_.storage.sat != SatKind::None;
    const MomentsSpec& m = spec_.moments;
    const KernelSpec& k = spec_.kernel;
    const BlockerSpec& bl = spec_.blocker;

    if (!moments) {
      if (sat)
        atSetting(storage_, DiagId::satNeedsMoments);
      else if (storage_ && spec_.storage.format != StorageFormat::Fp32)
        atSetting(storage_, DiagId::noEffect, "storage", "the depth representation reads the r32f depth map directly");
      if (bl.kind == BlockerKind::Moments) atSetting(blocker_, DiagId::needsMoments, "'blocker moments'", "average");
      if (spec_.prefilter.blur != BlurKind::None)
        atSetting(blur_, DiagId::noEffect, "blur", "depth is compared per tap; blurring depth does not filter shadows");
      if (spec_.prefilter.mips && mips_)
        atSetting(mips_, DiagId::noEffect, "mips", "depth is compared per tap, not filtered");
      if (bleeding_ && m.bleedingReduction > 0)
        atSetting(bleeding_, DiagId::noEffect, "bleeding", "light bleeding is a moments artifact");
    } else {
      if (bl.kind == BlockerKind::Search) atSetting(blocker_, DiagId::searchOnMoments);
      if (sampling_)
        atSetting(sampling_, DiagId::noEffect, "sampling", "it chooses PCF taps of the depth representation");
    }

    // Summed-area tables (vssm-yang2010 sec. 5-6).
    if (k.subdivision == Subdivision::Quadtree && !sat) atSetting(kernel_, DiagId::quadtreeNeedsSat, "quadtree");
    if (k.subdivision == Subdivision::Uniform && !sat) atSetting(kernel_, DiagId::uniformKernelNeedsSat);
    if (bl.kind == BlockerKind::Moments && !sat && moments) atSetting(blocker_, DiagId::momentBlockerNeedsSat);
    if (sat && moments) {
      if (spec_.storage.format != StorageFormat::Fp32)
        atSetting(storage_, DiagId::satNeedsFp32, spec_.storage.format == StorageFormat::Fp16 ? "fp16" : "unorm16");
      if (m.warp == Warp::PowerCdf) atSetting(storage_, DiagId::powerCdfSat);
      if (spec_.storage.sat == SatKind::Int32 && m.warp == Warp::Evsm4)
        atSetting(storage_, DiagId::negativeMomentsUnrepresentable, "an int32 16.16 SAT");
      if (spec_.storage.sat == SatKind::Int32 && k.size == KernelSize::Penumbra) {
        const double box = k.maxTexels * k.maxTexels;
        if (box > kInt32SatMaxBoxTexels)
          atSetting(kernel_ ? kernel_ : storage_, DiagId::satBoxOverflow, k.maxTexels, box);
      }
      if (spec_.storage.sat == SatKind::Fp32Naive) atSetting(storage_, DiagId::naiveFp32Sat);
      if (spec_.prefilter.blur != BlurKind::None) atSetting(blur_, DiagId::blurOnSat);
      if (spec_.prefilter.mips) atSetting(mips_, DiagId::noEffect, "mips", "SAT box queries replace mip lookups");
    }
    if (moments && !sat && spec_.storage.format == StorageFormat::Unorm16 && m.warp == Warp::Evsm4)
      atSetting(storage_, DiagId::negativeMomentsUnrepresentable, "unorm16");
    if (moments && m.warp == Warp::Msm) msmCombinations();

    // Exponential warps: exp(c) must stay representable (FACTS.md "Precision", precision.h).
    if (moments && (m.warp == Warp::Exp || m.warp == Warp::Evsm2 || m.warp == Warp::Evsm4)) {
      const ExponentLimit limit = warpExponentLimit(spec_.storage, spec_.mapSize);
      auto checkExponent = [&](const Value* given, double c, const char* which) {
        if (!given || c <= limit.maxExponent) return;
        at(*given, DiagId::exponentOverflow, which, given->text, limit.storageName, "c", limit.maxExponent,
           limit.reason);
      };
      checkExponent(exponent_, m.positiveExponent, m.warp == Warp::Evsm4 ? "positive" : "warp");
      if (m.warp == Warp::Evsm4) checkExponent(negativeExponent_, m.negativeExponent, "negative");
    }

    // Kernel sizing needs a blocker estimate; a point light has no penumbra to size.
    if (k.size == KernelSize::Penumbra && bl.kind == BlockerKind::None) {
      const char* kind = k.subdivision == Subdivision::Quadtree  ? "quadtree"
                         : k.subdivision == Subdivision::Uniform ? "uniform"
                                                                 : "penumbra";
      atSetting(kernel_, DiagId::penumbraNeedsBlocker, kind);
    }
    if (spec_.light.shape == LightShape::Point) {
      if (bl.kind != BlockerKind::None)
        atSetting(blocker_, DiagId::pointLightPenumbra, "a blocker estimate");
      else if (k.size == KernelSize::Penumbra)
        atSetting(kernel_, DiagId::pointLightPenumbra, "a penumbra kernel");
    }
    if (spec_.contact.enabled && bl.kind != BlockerKind::Moments)
      atSetting(contact_, DiagId::contactNeedsMomentBlocker);
    if (spec_.fallback.pcf && k.subdivision == Subdivision::None)
      atSetting(fallback_, DiagId::noEffect, "fallback",
                "PCF replaces non-planar leaves of a uniform or quadtree kernel (vssm sec. 5.2)");

    // Layers (lauritzen2008 sec. 3-4).
    if (moments && m.split == SplitPlacement::Explicit && explicitOk_) {
      if (static_cast<int>(explicitSplits_.size()) != m.layers + 1) {
        at(*split_, DiagId::splitCount, m.layers + 1, explicitSplits_.size());
      } else {
        for (size_t i = 0; i < explicitSplits_.size(); ++i) {
          const double s = explicitSplits_[i];
          const Value& v = split_->arguments[i].value;
          if (i == 0 && s != 0.0)
            at(v, DiagId::splitOrder, "start at 0 so every depth falls in a layer", s, i + 1);
          else if (i + 1 == explicitSplits_.size() && s != 1.0)
            at(v, DiagId::splitOrder, "end at 1 so every depth falls in a layer", s, i + 1);
          else if (i > 0 && s <= explicitSplits_[i - 1])
            at(v, DiagId::splitOrder, "increase strictly (each layer needs a depth range)", s, i + 1);
          else
            continue;
          break;
        }
      }
    }
    if (moments && m.split == SplitPlacement::Lloyd && m.layers == 1 && split_)
      at(*split_, DiagId::noEffect, "lloyd", "one layer has no splits to place");
    if (moments && m.layers > 1 && m.overlap > 0) {
      double narrowest = 1.0;
      for (size_t i = 1; i < m.splits.size(); ++i) narrowest = std::min(narrowest, m.splits[i] - m.splits[i - 1]);
      if (m.overlap >= narrowest / 2) atSetting(representation_, DiagId::wideOverlap, m.overlap, narrowest);
    }

    // Dubious but legal.
    if (k.subdivision == Subdivision::Quadtree && k.quadtreeHeight == 0 && kernelHeight_)
      at(*kernelHeight_, DiagId::quadtreeHeightZero);
    if (bl.kind == BlockerKind::Moments && bl.subdivision == Subdivision::Quadtree && bl.quadtreeHeight == 0 &&
        blockerHeight_)
      at(*blockerHeight_, DiagId::quadtreeHeightZero);
    const bool chebyshev = m.warp == Warp::Linear || m.warp == Warp::Evsm2 || m.warp == Warp::Evsm4;
    if (moments && m.bleedingReduction >= 0.5) atSetting(bleeding_, DiagId::strongBleeding, m.bleedingReduction);
    if (moments && !chebyshev && m.warp != Warp::Msm && m.bleedingReduction > 0)
      atSetting(bleeding_, DiagId::noEffect, "bleeding", "only Chebyshev warps (linear, evsm2, evsm4) and msm bleed");
    if (moments && chebyshev && minVariance_ && m.minVariance == 0) at(*minVariance_, DiagId::zeroMinVariance);
    if (moments && spec_.storage.format == StorageFormat::Fp16 && !sat) {
      if (lightSizeGiven_ && spec_.light.size > 0.1) atSetting(light_, DiagId::fp16LargeLight, spec_.light.size);
      if (m.warp == Warp::Linear && minVariance_ && m.minVariance < 1e-4)
        at(*minVariance_, DiagId::fp16MinVariance, m.minVariance);
    }
  }

  // Moment shadow maps (Peters & Klein 2015): what the four moments need from the storage.
  void msmCombinations() {
    const MomentsSpec& m = spec_.moments;
    if (m.layers > 1) atSetting(representation_, DiagId::msmLayers, m.layers);
    if (spec_.storage.sat == SatKind::None && spec_.storage.format == StorageFormat::Fp16)
      atSetting(storage_, DiagId::msmFp16);
    if (spec_.storage.sat == SatKind::Fp32Centered || spec_.storage.sat == SatKind::Fp32Naive) {
      const MsmSatPrecision p = msmFp32SatPrecision(spec_);
      if (p.meanError > m.momentBias)
        atSetting(storage_, DiagId::msmSatPrecision, spec_.mapSize, p.boxTexels, p.meanError, m.momentBias);
    }
    if (momentBias_ && m.momentBias < msmDefaultBias(spec_.storage))
      at(*momentBias_, DiagId::msmSmallBias, m.momentBias, msmDefaultBias(spec_.storage));
  }

  const dsl::FilterDecl& f_;
  dsl::DiagnosticSink& sink_;
  FilterSpec spec_;
  const Setting *light_ = nullptr, *representation_ = nullptr, *storage_ = nullptr, *blur_ = nullptr, *mips_ = nullptr,
                *blocker_ = nullptr, *kernel_ = nullptr, *sampling_ = nullptr, *fallback_ = nullptr,
                *contact_ = nullptr, *bleeding_ = nullptr;
  const Value *exponent_ = nullptr, *negativeExponent_ = nullptr, *minVariance_ = nullptr, *momentBias_ = nullptr,
              *split_ = nullptr, *kernelHeight_ = nullptr, *blockerHeight_ = nullptr;
  bool lightSizeGiven_ = false, explicitOk_ = false;
  int errorsBefore_ = 0;
  std::vector<double> explicitSplits_;
};

}  // namespace

const std::vector<std::string_view>& settingKeywords() { return kSettings; }

FilterSpec check(const dsl::FilterDecl& filter, dsl::DiagnosticSink& sink) { return Checker(filter, sink).run(); }

}  // namespace shadowc::spec
