// FilterSpec -> JSON (normalized spec, --print-spec, manifest "spec"). Keys are fixed and in
// declaration order; enum values use the DSL's spelling (docs/dsl.md), so the JSON reads like
// the filter description with every default written out. `location` is left out on purpose:
// it says where the text was, not what the filter is, and would make manifests path-dependent.
#include <cmath>
#include <nlohmann/json.hpp>

#include "spec/load_filter.h"

namespace shadowc {
const char* name(DepthInputFormat v) {
  switch (v) {
    case DepthInputFormat::Linear:
      return "linear";
    case DepthInputFormat::D32:
      return "d32";
    case DepthInputFormat::D24:
      return "d24";
  }
  return "?";
}
const char* name(Warp v) {
  switch (v) {
    case Warp::Linear:
      return "linear";
    case Warp::Exp:
      return "exp";
    case Warp::Evsm2:
      return "evsm2";
    case Warp::Evsm4:
      return "evsm4";
    case Warp::PowerCdf:
      return "power_cdf";
    case Warp::Msm:
      return "msm";
  }
  return "?";
}

namespace {
const char* name(LightShape v) {
  switch (v) {
    case LightShape::Rect:
      return "area";
    case LightShape::Disk:
      return "disk";
    case LightShape::Point:
      return "point";
  }
  return "?";
}
const char* name(Representation v) { return v == Representation::Depth ? "depth" : "moments"; }
const char* name(SplitPlacement v) {
  switch (v) {
    case SplitPlacement::Uniform:
      return "uniform";
    case SplitPlacement::Explicit:
      return "explicit";
    case SplitPlacement::Lloyd:
      return "lloyd";
  }
  return "?";
}
const char* name(StorageFormat v) {
  switch (v) {
    case StorageFormat::Fp32:
      return "fp32";
    case StorageFormat::Fp16:
      return "fp16";
    case StorageFormat::Unorm16:
      return "unorm16";
  }
  return "?";
}
const char* name(SatKind v) {
  switch (v) {
    case SatKind::None:
      return "none";
    case SatKind::Int32:
      return "int32";
    case SatKind::Fp32Centered:
      return "fp32_centered";
    case SatKind::Fp32Naive:
      return "fp32";
  }
  return "?";
}
const char* name(BlurKind v) {
  switch (v) {
    case BlurKind::None:
      return "none";
    case BlurKind::Box:
      return "box";
    case BlurKind::Gaussian:
      return "gaussian";
  }
  return "?";
}
const char* name(BlockerKind v) {
  switch (v) {
    case BlockerKind::None:
      return "none";
    case BlockerKind::Search:
      return "search";
    case BlockerKind::Moments:
      return "moments";
  }
  return "?";
}
const char* name(SamplePattern v) { return v == SamplePattern::Grid ? "grid" : "poisson"; }
const char* name(Subdivision v) {
  switch (v) {
    case Subdivision::None:
      return "none";
    case Subdivision::Uniform:
      return "uniform";
    case Subdivision::Quadtree:
      return "quadtree";
  }
  return "?";
}
const char* name(KernelSize v) { return v == KernelSize::Fixed ? "fixed" : "penumbra"; }
const char* name(QuadtreeTraversal v) {
  return v == QuadtreeTraversal::Table ? "table" : v == QuadtreeTraversal::Computed ? "computed" : "unrolled";
}
const char* name(PcfPattern v) {
  switch (v) {
    case PcfPattern::Grid:
      return "grid";
    case PcfPattern::Bilinear:
      return "bilinear";
    case PcfPattern::Poisson:
      return "poisson";
  }
  return "?";
}
const char* name(Rotation v) { return v == Rotation::Stable ? "stable" : "none"; }
const char* name(BiasKind v) {
  switch (v) {
    case BiasKind::Constant:
      return "constant";
    case BiasKind::SlopeScaled:
      return "slope";
    case BiasKind::NormalOffset:
      return "normal_offset";
    case BiasKind::ReceiverPlane:
      return "receiver_plane";
  }
  return "?";
}
}  // namespace

const char* name(CascadeSplit v) {
  switch (v) {
    case CascadeSplit::Uniform:
      return "uniform";
    case CascadeSplit::Log:
      return "log";
    case CascadeSplit::Practical:
      return "practical";
  }
  return "?";
}

int cascadeGrid(int count) {
  int g = 1;
  while (g * g < count) ++g;
  return g;
}

int lightSampleGrid(int count) {
  int k = 1;
  while (k * k < count) ++k;
  return k;
}

std::vector<std::pair<double, double>> lightSampleOffsets(int count, bool disk) {
  const int k = lightSampleGrid(count);
  std::vector<std::pair<double, double>> out;
  for (int i = 0; i < count; ++i) {
    // The cell centre in [-1, 1]^2.
    const double a = 2.0 * ((i % k) + 0.5) / k - 1.0, b = 2.0 * ((i / k) + 0.5) / k - 1.0;
    if (!disk) {
      out.emplace_back(0.5 * a, 0.5 * b);
      continue;
    }
    // Shirley & Chiu 1997's concentric map: square rings onto disk rings, area-preserving, so every
    // sample still stands for an equal patch of the light.
    double r = 0, phi = 0;
    if (std::abs(a) > std::abs(b))
      r = a, phi = M_PI / 4 * (b / a);
    else if (b != 0)
      r = b, phi = M_PI / 2 - M_PI / 4 * (a / b);
    out.emplace_back(0.5 * r * std::cos(phi), 0.5 * r * std::sin(phi));
  }
  return out;
}

double sunPenumbraSlope(double angleDegrees) { return 2.0 * std::tan(0.5 * angleDegrees * M_PI / 180.0); }

nlohmann::ordered_json specToJson(const FilterSpec& s) {
  using J = nlohmann::ordered_json;
  J j;
  j["name"] = s.name;
  // A spot light keeps the keys it always had (every existing manifest stays byte-identical);
  // the other types say so first and carry their own parameter.
  if (s.light.type == LightType::Sun)
    j["light"] = J{{"type", "sun"}, {"angle_from_scene", s.light.sizeFromScene}, {"angle", s.light.angleDegrees}};
  else if (s.light.type == LightType::Point)
    j["light"] = J{{"type", "point"}, {"radius_from_scene", s.light.sizeFromScene}, {"radius", s.light.size}};
  else
    j["light"] = J{{"shape", name(s.light.shape)}, {"size_from_scene", s.light.sizeFromScene}, {"size", s.light.size}};
  j["representation"] = name(s.representation);
  const MomentsSpec& m = s.moments;
  j["moments"] = J{{"warp", name(m.warp)},
                   {"layers", m.layers},
                   {"split", name(m.split)},
                   {"splits", m.splits},
                   {"overlap", m.overlap},
                   {"positive_exponent", m.positiveExponent},
                   {"negative_exponent", m.negativeExponent},
                   {"min_variance", m.minVariance},
                   {"bleeding_reduction", m.bleedingReduction},
                   {"lloyd_iterations", m.lloydIterations}};
  // Only msm has a moment bias; other warps' manifests stay byte-identical.
  if (m.warp == Warp::Msm) j["moments"]["moment_bias"] = m.momentBias;
  j["storage"] = J{{"format", name(s.storage.format)}, {"sat", name(s.storage.sat)}};
  // Written only when set, so the manifests of texel-corner filters stay byte-identical.
  if (s.storage.fractionalCorners) j["storage"]["corners"] = "bilinear";
  j["prefilter"] =
      J{{"blur", name(s.prefilter.blur)}, {"blur_radius", s.prefilter.blurRadius}, {"mips", s.prefilter.mips}};
  const BlockerSpec& b = s.blocker;
  j["blocker"] = J{{"kind", name(b.kind)},       {"taps", b.taps},
                   {"pattern", name(b.pattern)}, {"subdivision", name(b.subdivision)},
                   {"uniform_m", b.uniformM},    {"quadtree_height", b.quadtreeHeight}};
  const KernelSpec& k = s.kernel;
  j["kernel"] =
      J{{"size", name(k.size)},      {"fixed_texels", k.fixedTexels},       {"subdivision", name(k.subdivision)},
        {"uniform_n", k.uniformN},   {"quadtree_height", k.quadtreeHeight}, {"traversal", name(k.traversal)},
        {"max_texels", k.maxTexels}, {"lit_threshold", k.litThreshold}};
  // Written only when set (Algorithm 1's subdivision of non-planar kernels only), so other
  // manifests stay byte-identical.
  if (b.uniformNonPlanarOnly) j["blocker"]["subdivide"] = "nonplanar";
  if (k.uniformNonPlanarOnly) j["kernel"]["subdivide"] = "nonplanar";
  j["sampling"] = J{{"pattern", name(s.sampling.pattern)},
                    {"grid_n", s.sampling.gridN},
                    {"taps", s.sampling.taps},
                    {"rotation", name(s.sampling.rotation)}};
  j["bias"] = J{{"kind", name(s.bias.kind)},
                {"constant", s.bias.constant},
                {"slope", s.bias.slope},
                {"normal_offset", s.bias.normalOffset}};
  // Written only for that policy, so the manifests of the other policies stay byte-identical.
  if (s.bias.kind == BiasKind::ReceiverPlane) j["bias"]["max_slope"] = s.bias.maxSlope;
  j["fallback"] = J{{"pcf", s.fallback.pcf}, {"n", s.fallback.n}};
  j["contact"] = J{{"enabled", s.contact.enabled}, {"n", s.contact.n}, {"epsilon", s.contact.epsilon}};
  j["early_out_minmax"] = s.earlyOutMinMax;
  j["backface"] = s.backfaceShadowed ? "shadowed" : "filtered";
  // Written only when weighted, so every other manifest stays byte-identical.
  if (s.formFactorWeights) j["weights"] = "form_factor";
  j["map_size"] = s.mapSize;
  if (s.resolution > 0) j["resolution"] = s.resolution;  // only when planned: other manifests unchanged
  // Written only when cascaded, so every other manifest stays byte-identical.
  if (s.cascades.count > 0)
    j["cascades"] = J{{"count", s.cascades.count},
                      {"split", name(s.cascades.split)},
                      {"lambda", s.cascades.lambda},
                      {"blend", s.cascades.blend},
                      {"grid", cascadeGrid(s.cascades.count)}};
  // Written only for a hardware depth input, so every other manifest stays byte-identical.
  if (s.depthInput.format != DepthInputFormat::Linear)
    j["depth_input"] = J{{"format", name(s.depthInput.format)}, {"z", s.depthInput.reversed ? "reverse" : "standard"}};
  // Written only with light samples, so every other manifest stays byte-identical. The offsets
  // are the views an engine renders (docs/integration.md "Light samples").
  if (s.lightSamples > 0) {
    J offsets = J::array();
    for (const auto& [x, y] : lightSampleOffsets(s.lightSamples, s.light.shape == LightShape::Disk))
      offsets.push_back(J::array({x, y}));
    j["light_samples"] = J{{"count", s.lightSamples}, {"grid", lightSampleGrid(s.lightSamples)}, {"offsets", offsets}};
  }
  return j;
}

}  // namespace shadowc
