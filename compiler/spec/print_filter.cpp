// printFilter: one line per setting, in documentation order (docs/dsl.md), every argument named.
#include "spec/print_filter.h"

#include <fmt/format.h>

#include <string_view>
#include <vector>

namespace shadowc {
namespace {

// Shortest text that reads back as the same double (fmt's default); the lexer parses numbers
// with strtod, so the round trip is exact.
std::string num(double v) { return fmt::format("{}", v); }
std::string size(int n) { return fmt::format("{0}x{0}", n); }

// "name(a, b)" or "name" when there are no arguments.
std::string call(std::string_view name, const std::vector<std::string>& args) {
  if (args.empty()) return std::string(name);
  std::string out = std::string(name) + "(";
  for (size_t i = 0; i < args.size(); ++i) out += (i ? ", " : "") + args[i];
  return out + ")";
}

std::string light(const LightSpec& l) {
  const std::string fromScene = "scene";
  if (l.type == LightType::Sun) return call("sun", {"angle: " + (l.sizeFromScene ? fromScene : num(l.angleDegrees))});
  if (l.type == LightType::Point) return call("point", {"radius: " + (l.sizeFromScene ? fromScene : num(l.size))});
  if (l.shape == LightShape::Point) return "point";
  const char* shape = l.shape == LightShape::Rect ? "area" : "disk";
  return call(shape, {"size: " + (l.sizeFromScene ? std::string("scene") : num(l.size))});
}

std::string split(const MomentsSpec& m) {
  switch (m.split) {
    case SplitPlacement::Uniform:
      return "uniform";
    case SplitPlacement::Lloyd:
      return call("lloyd", {fmt::format("iterations: {}", m.lloydIterations)});
    case SplitPlacement::Explicit: {
      std::vector<std::string> b;
      for (double s : m.splits) b.push_back(num(s));
      return call("explicit", b);
    }
  }
  return "uniform";
}

std::string moments(const MomentsSpec& m) {
  std::vector<std::string> args;
  const char* warp = "linear";
  switch (m.warp) {
    case Warp::Linear:
      warp = "linear";
      break;
    case Warp::Exp:
      warp = "exp";
      break;
    case Warp::Evsm2:
      warp = "evsm2";
      break;
    case Warp::Evsm4:
      warp = "evsm4";
      break;
    case Warp::PowerCdf:
      warp = "power_cdf";
      break;
    case Warp::Msm:
      warp = "msm";
      break;
  }
  if (m.warp == Warp::Exp || m.warp == Warp::Evsm2 || m.warp == Warp::Evsm4)
    args.push_back("exponent: " + num(m.positiveExponent));
  if (m.warp == Warp::Evsm4) args.push_back("negative_exponent: " + num(m.negativeExponent));
  if (m.warp == Warp::Msm) args.push_back("moment_bias: " + num(m.momentBias));
  if (m.warp != Warp::Exp && m.warp != Warp::PowerCdf && m.warp != Warp::Msm)
    args.push_back("min_variance: " + num(m.minVariance));
  args.push_back(fmt::format("layers: {}", m.layers));
  args.push_back("split: " + split(m));
  args.push_back("overlap: " + num(m.overlap));
  return call(warp, args);
}

std::string storage(const StorageSpec& s) {
  const char* formats[] = {"fp32", "fp16", "unorm16"};
  const char* format = formats[static_cast<int>(s.format)];
  // `corners` only when fractional: the printed text of texel-corner filters stays as it was.
  auto sat = [&](const char* kind) {
    std::vector<std::string> args = {std::string("kind: ") + kind, std::string("format: ") + format};
    if (s.fractionalCorners) args.push_back("corners: bilinear");
    return call("sat", args);
  };
  switch (s.sat) {
    case SatKind::None:
      return format;
    case SatKind::Int32:
      return sat("int32");
    case SatKind::Fp32Centered:
      return sat("fp32_centered");
    case SatKind::Fp32Naive:
      return sat("fp32");
  }
  return format;
}

std::string blur(const PrefilterSpec& p) {
  if (p.blur == BlurKind::None) return "none";
  return call(p.blur == BlurKind::Box ? "box" : "gaussian", {fmt::format("radius: {}", p.blurRadius)});
}

std::string subdivision(const BlockerSpec& b) {
  switch (b.subdivision) {
    case Subdivision::None:
      return "none";
    case Subdivision::Uniform:
      // `subdivide` only when not the default, so printed filters stay as they were.
      if (b.uniformNonPlanarOnly) return call("uniform", {fmt::format("m: {}", b.uniformM), "subdivide: nonplanar"});
      return call("uniform", {fmt::format("m: {}", b.uniformM)});
    case Subdivision::Quadtree:
      return call("quadtree", {fmt::format("height: {}", b.quadtreeHeight)});
  }
  return "none";
}

std::string blocker(const BlockerSpec& b) {
  switch (b.kind) {
    case BlockerKind::None:
      return "none";
    case BlockerKind::Search:
      return call("search", {fmt::format("taps: {}", b.taps),
                             std::string("pattern: ") + (b.pattern == SamplePattern::Poisson ? "poisson" : "grid")});
    case BlockerKind::Moments:
      return call("moments", {"subdivision: " + subdivision(b)});
  }
  return "none";
}

std::string kernel(const KernelSpec& k) {
  if (k.size == KernelSize::Fixed) return call("fixed", {fmt::format("size: {}", k.fixedTexels)});
  std::vector<std::string> args;
  const char* form = "penumbra";
  if (k.subdivision == Subdivision::Uniform) form = "uniform", args.push_back(fmt::format("n: {}", k.uniformN));
  if (k.subdivision == Subdivision::Uniform && k.uniformNonPlanarOnly) args.push_back("subdivide: nonplanar");
  if (k.subdivision == Subdivision::Quadtree) {
    form = "quadtree";
    args.push_back(fmt::format("height: {}", k.quadtreeHeight));
    const char* traversal = k.traversal == QuadtreeTraversal::Table      ? "table"
                            : k.traversal == QuadtreeTraversal::Computed ? "computed"
                                                                         : "unrolled";
    args.push_back(std::string("traversal: ") + traversal);
  }
  args.push_back("max: " + num(k.maxTexels));
  args.push_back("lit_threshold: " + num(k.litThreshold));
  return call(form, args);
}

std::string sampling(const SamplingSpec& s) {
  if (s.pattern == PcfPattern::Poisson)
    return call("poisson", {fmt::format("taps: {}", s.taps),
                            std::string("rotate: ") + (s.rotation == Rotation::Stable ? "stable" : "none")});
  return call(s.pattern == PcfPattern::Grid ? "grid" : "bilinear", {"size: " + size(s.gridN)});
}

std::string bias(const BiasSpec& b) {
  switch (b.kind) {
    case BiasKind::Constant:
      return call("constant", {"value: " + num(b.constant)});
    case BiasKind::SlopeScaled:
      return call("slope", {"slope: " + num(b.slope), "constant: " + num(b.constant)});
    case BiasKind::NormalOffset:
      return call("normal_offset", {"offset: " + num(b.normalOffset), "constant: " + num(b.constant)});
    case BiasKind::ReceiverPlane:
      return call("receiver_plane", {"constant: " + num(b.constant), "max_slope: " + num(b.maxSlope),
                                     "normal_offset: " + num(b.normalOffset)});
  }
  return "constant";
}

bool sameSampling(const SamplingSpec& a, const SamplingSpec& b) {
  return a.pattern == b.pattern && a.gridN == b.gridN && a.taps == b.taps && a.rotation == b.rotation;
}

}  // namespace

std::string printFilter(const FilterSpec& s) {
  const bool isMoments = s.representation == Representation::Moments;
  std::vector<std::pair<std::string_view, std::string>> lines;
  lines.emplace_back("light", light(s.light));
  if (isMoments)
    lines.emplace_back("moments", moments(s.moments));
  else
    lines.emplace_back("depth", "");
  lines.emplace_back("storage", storage(s.storage));
  lines.emplace_back("blur", blur(s.prefilter));
  lines.emplace_back("mips", s.prefilter.mips ? "on" : "off");
  lines.emplace_back("blocker", blocker(s.blocker));
  lines.emplace_back("kernel", kernel(s.kernel));
  // With moments, `sampling` has no effect (W0505) and the checker keeps its defaults: written
  // only when the spec differs from them, so that a difference is not lost.
  if (!isMoments || !sameSampling(s.sampling, SamplingSpec{})) lines.emplace_back("sampling", sampling(s.sampling));
  lines.emplace_back("bias", bias(s.bias));
  lines.emplace_back("fallback", s.fallback.pcf ? call("pcf", {"size: " + size(s.fallback.n)}) : "none");
  lines.emplace_back("contact", s.contact.enabled
                                    ? call("pcf", {"size: " + size(s.contact.n), "epsilon: " + num(s.contact.epsilon)})
                                    : "none");
  lines.emplace_back("early_out", s.earlyOutMinMax ? "minmax" : "none");
  lines.emplace_back("bleeding", s.moments.bleedingReduction > 0
                                     ? call("reduce", {"amount: " + num(s.moments.bleedingReduction)})
                                     : "none");
  lines.emplace_back("backface", s.backfaceShadowed ? "shadowed" : "filtered");
  if (s.formFactorWeights) lines.emplace_back("weights", "form_factor");  // absent = uniform, as before
  if (s.depthInput.format != DepthInputFormat::Linear)                    // absent = linear, as before
    lines.emplace_back("depth_input", s.depthInput.reversed ? call(name(s.depthInput.format), {"z: reverse"})
                                                            : std::string(name(s.depthInput.format)));
  lines.emplace_back("map_size", std::to_string(s.mapSize));
  if (s.resolution > 0) lines.emplace_back("resolution", std::to_string(s.resolution));
  if (s.cascades.count > 0) {
    const CascadeSpec& c = s.cascades;
    std::vector<std::string> args = {"count: " + std::to_string(c.count)};
    if (c.split == CascadeSplit::Practical) args.push_back("lambda: " + num(c.lambda));
    args.push_back("blend: " + num(c.blend));
    lines.emplace_back("cascades", call(name(c.split), args));
  }
  if (s.lightSamples > 0) lines.emplace_back("light_samples", std::to_string(s.lightSamples));

  std::string out = fmt::format("filter {} {{\n", s.name);
  for (const auto& [keyword, value] : lines)
    out += value.empty() ? fmt::format("    {}\n", keyword) : fmt::format("    {:<10} {}\n", keyword, value);
  return out + "}\n";
}

}  // namespace shadowc
