// Checker phase 1, reading settings: each setting's value and arguments, typed and
// range-checked (E03xx), unknown names with an edit-distance suggestion, duplicates with a note
// at the first one. Nothing here depends on another setting (normalize.cpp and
// combination_rules.cpp do that), so the order of settings in a file never matters.
#include "spec/read_settings.h"

#include <algorithm>
#include <cmath>
#include <map>
#include <optional>

#include "spec/precision.h"
#include "spec/value_reader.h"

namespace shadowc::spec {
namespace {

using dsl::Argument;
using dsl::DiagId;
using dsl::Setting;
using dsl::Value;

const Names kSettings = {"light",    "depth",    "moments",  "storage",    "blur",     "mips",          "blocker",
                         "kernel",   "sampling", "bias",     "fallback",   "contact",  "early_out",     "backface",
                         "bleeding", "weights",  "map_size", "resolution", "cascades", "light_samples", "depth_input"};

class SettingsReader : ValueReader {
 public:
  SettingsReader(const dsl::FilterDecl& f, dsl::DiagnosticSink& sink) : ValueReader(sink), f_(f) {}

  SettingsRead run() {
    out_.spec.name = f_.name;
    out_.spec.location = SourceLocation{sink_.file(), f_.line, f_.column};
    std::map<std::string_view, const Setting*> seen;
    for (const Setting& s : f_.settings) {
      if (sink_.stopped()) break;
      auto known = std::find(kSettings.begin(), kSettings.end(), s.keyword);
      if (known == kSettings.end()) {
        sink_.report(DiagId::unknownSetting, s.line, s.column, static_cast<int>(s.keyword.size()), s.keyword);
        sink_.suggest(support::closestMatch(s.keyword, kSettings));
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
    return std::move(out_);
  }

 private:
  // ---- settings ----------------------------------------------------------------------------------
  void read(const Setting& s) {
    const Value& v = s.value;
    const std::string what = "'" + s.keyword + "'";
    if (s.keyword == "light")
      out_.light = &s, readLight(v, what);
    else if (s.keyword == "depth")
      readDepth(s);
    else if (s.keyword == "moments")
      out_.representation = &s, readMoments(v, what);
    else if (s.keyword == "storage")
      out_.storage = &s, readStorage(v, what);
    else if (s.keyword == "blur")
      out_.blur = &s, readBlur(v, what);
    else if (s.keyword == "mips") {
      out_.mips = &s;
      if (auto c = choice(&v, what, {"off", "on"})) out_.spec.prefilter.mips = *c == 1;
    } else if (s.keyword == "blocker")
      out_.blocker = &s, readBlocker(v, what);
    else if (s.keyword == "kernel")
      out_.kernel = &s, readKernel(v, what);
    else if (s.keyword == "sampling")
      out_.sampling = &s, readSampling(v, what);
    else if (s.keyword == "bias")
      out_.bias = &s, readBias(v, what);
    else if (s.keyword == "fallback")
      out_.fallback = &s, readFallback(v, what);
    else if (s.keyword == "contact")
      out_.contact = &s, readContact(v, what);
    else if (s.keyword == "early_out") {
      if (auto c = choice(&v, what, {"none", "minmax"})) out_.spec.earlyOutMinMax = *c == 1;
    } else if (s.keyword == "backface") {
      if (auto c = choice(&v, what, {"shadowed", "filtered"})) out_.spec.backfaceShadowed = *c == 0;
    } else if (s.keyword == "bleeding")
      out_.bleeding = &s, readBleeding(v, what);
    else if (s.keyword == "weights") {
      out_.weights = &s;
      if (auto c = choice(&v, what, {"uniform", "form_factor"})) out_.spec.formFactorWeights = *c == 1;
    } else if (s.keyword == "cascades")
      readCascades(s);
    else if (s.keyword == "light_samples")
      readLightSamples(s);
    else if (s.keyword == "depth_input")
      readDepthInput(v, what);
    else if (s.keyword == "map_size") {
      out_.mapSize = &s;
      if (auto n = integer(&v, what, 16, 16384)) out_.spec.mapSize = *n;
    } else if (s.keyword == "resolution") {
      out_.resolution = &s;
      if (auto n = integer(&v, what, 16, 16384)) out_.spec.resolution = *n;
    }
  }

  // `light`: the projection (spot / sun / point) and the light's size (docs/dsl.md "light").
  // area / disk / bare point are today's spot light, spelled as always; `spot(...)` is the same
  // light with its type written out; both give the same FilterSpec, so the same output.
  void readLight(const Value& v, const std::string& what) {
    auto idx = variant(v, what, {"area", "disk", "point", "spot", "sun"});
    if (!idx) return;
    LightSpec& l = out_.spec.light;
    Bound b;
    if (*idx == 2 && !v.hasArguments) {
      l = LightSpec{LightShape::Point, false, 0.0};  // infinitesimal, in a spot frustum: hard shadows
      return;
    }
    if (*idx == 2) {  // omnidirectional sphere light (cube maps); refused in light_rules.cpp
      l.type = LightType::Point;
      if (!bind(v, {{"radius", true}}, b)) return;
      if (auto r = numberOrScene(get(b, "radius"), arg("radius", v), Range{0, 1e4}))
        l.sizeFromScene = r->fromScene, l.size = r->value;
      return;
    }
    if (*idx == 4) {
      // Angular diameter in degrees: the sun is about 0.53; past 45 the orthographic penumbra
      // 2 tan(angle / 2) stops being a small-cone estimate.
      l.type = LightType::Sun;
      l.shape = LightShape::Disk;
      if (!bind(v, {{"angle", true}}, b)) return;
      if (auto a = numberOrScene(get(b, "angle"), arg("angle", v), Range{0, 45, true}))
        l.sizeFromScene = a->fromScene, l.angleDegrees = a->value, out_.lightSizeGiven = !a->fromScene;
      return;
    }
    const Value* shape = nullptr;
    if (*idx == 3) {
      if (!bind(v, {{"shape", true}, {"size", false}}, b)) return;
      shape = get(b, "shape");
      if (shape) {
        auto s = choice(shape, arg("shape", v), {"area", "disk", "point"});
        if (!s) return;
        if (*s == 2) {
          if (get(b, "size")) at(*get(b, "size"), DiagId::takesNoArguments, "spot(shape: point)");
          l = LightSpec{LightShape::Point, false, 0.0};
          return;
        }
        l.shape = *s == 0 ? LightShape::Rect : LightShape::Disk;
      } else {
        l.shape = LightShape::Rect;
      }
    } else {
      l.shape = *idx == 0 ? LightShape::Rect : LightShape::Disk;
      if (!bind(v, {{"size", true}}, b)) return;
    }
    if (auto s = numberOrScene(get(b, "size"), arg("size", v), Range{0, 1e4, true})) {
      l.sizeFromScene = s->fromScene, l.size = s->value;
      out_.lightSizeGiven = !s->fromScene;
    }
  }

  // `depth_input linear | d32 | d24 | d32(z: reverse) | d24(z: standard)` (docs/dsl.md
  // "depth_input"): the engine's depth attachment as the filter's input.
  void readDepthInput(const Value& v, const std::string& what) {
    auto idx = variant(v, what, {"linear", "d32", "d24"});
    if (!idx) return;
    Bound b;
    if (*idx == 0) {
      if (bind(v, {}, b)) out_.spec.depthInput = DepthInputSpec{};
      return;
    }
    DepthInputSpec d;
    d.format = *idx == 1 ? DepthInputFormat::D32 : DepthInputFormat::D24;
    if (!bind(v, {{"z", false}}, b)) return;
    if (const Value* z = get(b, "z")) {
      auto c = choice(z, arg("z", v), {"standard", "reverse"});
      if (!c) return;
      d.reversed = *c == 1;
    }
    out_.spec.depthInput = d;
  }

  // `cascades N` (practical split, lambda 0.5, blend 0.1) or `cascades SCHEME(count: N, ...)` with
  // SCHEME uniform / log / practical (docs/dsl.md "cascades"). 8 is the most an engine uses
  // (Unreal's limit is 16 but its default 4); more tiles than a 3x3 atlas would not fit it.
  void readCascades(const Setting& s) {
    out_.cascades = &s;
    const Value& v = s.value;
    const std::string what = "'cascades'";
    const char* countRange = "in [1, 8] (one orthographic map per camera-depth slice, tiles of one atlas)";
    CascadeSpec c;
    if (v.kind == Value::Kind::Number) {
      if (auto n = integer(&v, what, 1, 8, countRange)) c.count = *n;
      out_.spec.cascades = c;
      return;
    }
    auto idx = variant(v, what, {"uniform", "log", "practical"});
    if (!idx) return;
    const CascadeSplit schemes[] = {CascadeSplit::Uniform, CascadeSplit::Log, CascadeSplit::Practical};
    c.split = schemes[*idx];
    std::vector<Param> params = {{"count", true}};
    if (c.split == CascadeSplit::Practical) params.push_back({"lambda", false});
    params.push_back({"blend", false});
    Bound b;
    if (!bind(v, params, b)) return;
    const Value* count = get(b, "count");
    if (!count) {
      at(v, DiagId::missingArgument, v.text, "count (1..8)");
      return;
    }
    auto n = integer(count, arg("count", v), 1, 8, countRange);
    if (!n) return;
    c.count = *n;
    if (const Value* x = get(b, "lambda")) {
      if (auto l = number(x, arg("lambda", v), Range{0, 1})) c.lambda = *l;
    }
    // Past half a cascade the band of one border would reach the previous one.
    if (const Value* x = get(b, "blend")) {
      if (auto l = number(x, arg("blend", v), Range{0, 0.5})) c.blend = *l;
    }
    out_.spec.cascades = c;
  }

  // `light_samples N`: N = k^2 light views, the centres of a k x k grid of equal light patches
  // (docs/dsl.md "light_samples"); 16 x 16 is the reference's own count.
  void readLightSamples(const Setting& s) {
    out_.lightSamples = &s;
    auto n = integer(&s.value, "'light_samples'", 1, kMaxLightSamples,
                     "in [1, 256] (k x k views of the light, tiles of one atlas)");
    if (!n) return;
    const int k = lightSampleGrid(*n);
    if (k * k != *n) {
      at(s.value, DiagId::lightSamplesNotSquare, *n, (k - 1) * (k - 1), k * k);
      return;
    }
    out_.spec.lightSamples = *n;
  }

  void readDepth(const Setting& s) {
    out_.representation = &s;
    if (s.hasValue) at(s.value, DiagId::takesNoArguments, s.keyword);
    out_.spec.representation = Representation::Depth;
  }

  void readMoments(const Value& v, const std::string& what) {
    auto idx = variant(v, what, {"linear", "exp", "evsm2", "evsm4", "power_cdf", "msm"});
    if (!idx) return;
    out_.spec.representation = Representation::Moments;
    const Warp warps[] = {Warp::Linear, Warp::Exp, Warp::Evsm2, Warp::Evsm4, Warp::PowerCdf, Warp::Msm};
    MomentsSpec& m = out_.spec.moments;
    m.warp = warps[*idx];
    std::vector<Param> params;
    if (m.warp == Warp::Exp || m.warp == Warp::Evsm2 || m.warp == Warp::Evsm4) params.push_back({"exponent", true});
    if (m.warp == Warp::Evsm4) params.push_back({"negative_exponent", true});
    if (m.warp == Warp::Msm) params.push_back({"moment_bias", true});  // msm has a bias, not a variance floor
    if (m.warp != Warp::Exp && m.warp != Warp::PowerCdf && m.warp != Warp::Msm)
      params.push_back({"min_variance", false});
    for (std::string_view p : {"layers", "split", "overlap"}) params.push_back({p, false});
    Bound b;
    bind(v, params, b);
    if (const Value* x = get(b, "layers")) {
      // 0 layers would store nothing; 16 layers of rg32f is already 128 bytes per texel.
      if (auto n =
              integer(x, arg("layers", v), 1, 16, "at least 1 (a moments map has one layer or more) and at most 16"))
        m.layers = *n, out_.layers = x;
    }
    if (const Value* x = get(b, "overlap")) {
      if (auto n = number(x, arg("overlap", v), Range{0, 0.25})) m.overlap = *n;
    }
    if (const Value* x = get(b, "exponent")) {
      if (auto n = number(x, arg("exponent", v), Range{0, 100, true})) m.positiveExponent = *n, out_.exponent = x;
    }
    if (const Value* x = get(b, "negative_exponent")) {
      if (auto n = number(x, arg("negative_exponent", v), Range{0, 100, true}))
        m.negativeExponent = *n, out_.negativeExponent = x;
    }
    if (const Value* x = get(b, "min_variance")) {
      if (auto n = number(x, arg("min_variance", v), Range{0, 1})) m.minVariance = *n, out_.minVariance = x;
    }
    if (const Value* x = get(b, "moment_bias")) {
      // 0 would leave the Hankel matrix of a single depth singular (Algorithm 3 divides by it).
      if (auto n = number(x, arg("moment_bias", v), Range{0, 0.01, true})) m.momentBias = *n, out_.momentBias = x;
    }
    if (const Value* x = get(b, "split")) readSplit(*x, arg("split", v));
  }

  void readSplit(const Value& v, const std::string& what) {
    auto idx = variant(v, what, {"uniform", "explicit", "lloyd"});
    if (!idx) return;
    MomentsSpec& m = out_.spec.moments;
    out_.split = &v;
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
      out_.explicitSplits.clear();
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
        out_.explicitSplits.push_back(*n);
      }
      out_.explicitOk = true;
    }
  }

  void readStorage(const Value& v, const std::string& what) {
    auto idx = variant(v, what, {"fp32", "fp16", "unorm16", "sat"});
    if (!idx) return;
    Bound b;
    const StorageFormat formats[] = {StorageFormat::Fp32, StorageFormat::Fp16, StorageFormat::Unorm16};
    if (*idx < 3) {
      if (bind(v, {}, b)) out_.spec.storage = StorageSpec{formats[*idx], SatKind::None};
      return;
    }
    if (!bind(v, {{"kind", true}, {"format", false}, {"corners", false}}, b)) return;
    const Value* kind = get(b, "kind");
    if (!kind) {
      at(v, DiagId::missingArgument, "sat", "kind (int32, fp32_centered or fp32)");
      return;
    }
    auto k = choice(kind, arg("kind", v), {"int32", "fp32_centered", "fp32"});
    if (!k) return;
    const SatKind kinds[] = {SatKind::Int32, SatKind::Fp32Centered, SatKind::Fp32Naive};
    out_.spec.storage = StorageSpec{StorageFormat::Fp32, kinds[*k]};
    if (const Value* f = get(b, "format"))
      if (auto fi = choice(f, arg("format", v), {"fp32", "fp16", "unorm16"})) out_.spec.storage.format = formats[*fi];
    if (const Value* c = get(b, "corners"))
      if (auto ci = choice(c, arg("corners", v), {"texel", "bilinear"})) out_.spec.storage.fractionalCorners = *ci == 1;
  }

  void readBlur(const Value& v, const std::string& what) {
    auto idx = variant(v, what, {"none", "box", "gaussian"});
    if (!idx) return;
    Bound b;
    if (*idx == 0) {
      if (bind(v, {}, b)) out_.spec.prefilter.blur = BlurKind::None, out_.spec.prefilter.blurRadius = 0;
      return;
    }
    out_.spec.prefilter.blur = *idx == 1 ? BlurKind::Box : BlurKind::Gaussian;
    out_.spec.prefilter.blurRadius = 2;
    if (bind(v, {{"radius", true}}, b))
      if (const Value* r = get(b, "radius"))
        if (auto n = integer(r, arg("radius", v), 1, 32)) out_.spec.prefilter.blurRadius = *n;
  }

  void readBlocker(const Value& v, const std::string& what) {
    auto idx = variant(v, what, {"none", "search", "moments"});
    if (!idx) return;
    BlockerSpec& bl = out_.spec.blocker;
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
        if (bind(*sub, {{"m", true}, {"subdivide", false}}, sb)) {
          if (const Value* x = get(sb, "m"))
            if (auto n = integer(x, arg("m", *sub), 1, kMaxUniformM)) bl.uniformM = *n;
          if (const Value* x = get(sb, "subdivide"))
            if (auto c = choice(x, arg("subdivide", *sub), {"always", "nonplanar"})) bl.uniformNonPlanarOnly = *c == 1;
        }
      } else {
        bl.subdivision = Subdivision::Quadtree;
        if (bind(*sub, {{"height", true}}, sb))
          if (const Value* x = get(sb, "height"))
            if (auto n = quadtreeHeight(x, arg("height", *sub))) bl.quadtreeHeight = *n;
      }
    }
  }

  void readKernel(const Value& v, const std::string& what) {
    auto idx = variant(v, what, {"fixed", "penumbra", "uniform", "quadtree"});
    if (!idx) return;
    KernelSpec& k = out_.spec.kernel;
    Bound b;
    std::vector<Param> params;
    if (*idx == 0) params = {{"size", true}};
    if (*idx == 2) params = {{"n", true}, {"subdivide", false}};
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
      if (auto n = integer(x, arg("n", v), 1, kMaxUniformN)) k.uniformN = *n;
    if (const Value* x = get(b, "subdivide"))
      if (auto c = choice(x, arg("subdivide", v), {"always", "nonplanar"})) k.uniformNonPlanarOnly = *c == 1;
    if (const Value* x = get(b, "height"))
      if (auto n = quadtreeHeight(x, arg("height", v))) k.quadtreeHeight = *n;
    if (const Value* x = get(b, "traversal"))
      if (auto c = choice(x, arg("traversal", v), {"table", "computed", "unrolled"}))
        k.traversal = static_cast<QuadtreeTraversal>(*c);  // the enum's order
    if (const Value* x = get(b, "max"))
      if (auto n = number(x, arg("max", v), Range{1, kMaxKernelTexels})) k.maxTexels = *n, out_.kernelMax = x;
    if (const Value* x = get(b, "lit_threshold"))
      if (auto n = number(x, arg("lit_threshold", v), Range{0, 0.5})) k.litThreshold = *n;
  }

  void readSampling(const Value& v, const std::string& what) {
    auto idx = variant(v, what, {"grid", "bilinear", "poisson"});
    if (!idx) return;
    SamplingSpec& s = out_.spec.sampling;
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
    auto idx = variant(v, what, {"constant", "slope", "normal_offset", "receiver_plane"});
    if (!idx) return;
    BiasSpec& bias = out_.spec.bias;
    const BiasKind kinds[] = {BiasKind::Constant, BiasKind::SlopeScaled, BiasKind::NormalOffset,
                              BiasKind::ReceiverPlane};
    bias.kind = kinds[*idx];
    Bound b;
    if (*idx == 3) {  // receiver_plane(constant: B, max_slope: S, normal_offset: O): all optional
      // The one default, BiasSpec's (filter_spec.h says why 50).
      bias.maxSlope = BiasSpec{}.maxSlope;
      if (!bind(v, {{"constant", false}, {"max_slope", false}, {"normal_offset", false}}, b)) return;
      if (const Value* x = get(b, "max_slope"))
        if (auto n = number(x, arg("max_slope", v), Range{0, 1000, true})) bias.maxSlope = *n;
      if (const Value* x = get(b, "normal_offset"))
        if (auto n = number(x, arg("normal_offset", v), Range{0, 10})) bias.normalOffset = *n;
    } else {
      const std::string_view first = *idx == 0 ? "value" : *idx == 1 ? "slope" : "offset";
      std::vector<Param> params = {{first, true}};
      if (*idx != 0) params.push_back({"constant", false});
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
    }
    if (const Value* c = get(b, "constant"))
      if (auto n = number(c, arg("constant", v), Range{0, 1})) bias.constant = *n;
  }

  void readFallback(const Value& v, const std::string& what) {
    auto idx = variant(v, what, {"none", "pcf"});
    if (!idx) return;
    Bound b;
    if (*idx == 0) {
      if (bind(v, {}, b)) out_.spec.fallback = FallbackSpec{false, 2};
      return;
    }
    out_.spec.fallback = FallbackSpec{true, 2};
    if (bind(v, {{"size", true}}, b))
      if (const Value* x = get(b, "size"))
        if (auto n = squareSize(x, arg("size", v), 1, 8)) out_.spec.fallback.n = *n;
  }

  void readContact(const Value& v, const std::string& what) {
    auto idx = variant(v, what, {"none", "pcf"});
    if (!idx) return;
    Bound b;
    if (*idx == 0) {
      if (bind(v, {}, b)) out_.spec.contact = ContactSpec{false, 3, 0.01};
      return;
    }
    out_.spec.contact = ContactSpec{true, 3, 0.01};
    if (!bind(v, {{"size", true}, {"epsilon", false}}, b)) return;
    if (const Value* x = get(b, "size"))
      if (auto n = squareSize(x, arg("size", v), 1, 8)) out_.spec.contact.n = *n;
    if (const Value* x = get(b, "epsilon"))
      if (auto n = number(x, arg("epsilon", v), Range{0, 1, true})) out_.spec.contact.epsilon = *n;
  }

  void readBleeding(const Value& v, const std::string& what) {
    auto idx = variant(v, what, {"none", "reduce"});
    if (!idx) return;
    Bound b;
    if (*idx == 0) {
      if (bind(v, {}, b)) out_.spec.moments.bleedingReduction = 0.0;
      return;
    }
    if (!bind(v, {{"amount", true}}, b)) return;
    const Value* x = get(b, "amount");
    if (!x) {
      at(v, DiagId::missingArgument, "reduce", "amount");
      return;
    }
    // linstep(amount, 1, p) divides by (1 - amount): 1 itself is a division by zero.
    if (auto n = number(x, arg("amount", v), Range{0, 1, false, true})) out_.spec.moments.bleedingReduction = *n;
  }

  const dsl::FilterDecl& f_;
  SettingsRead out_;
};

}  // namespace

const std::vector<std::string_view>& settingKeywords() { return kSettings; }

SettingsRead readSettings(const dsl::FilterDecl& filter, dsl::DiagnosticSink& sink) {
  return SettingsReader(filter, sink).run();
}

}  // namespace shadowc::spec
