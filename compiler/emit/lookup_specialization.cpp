// FilterSpec -> #defines + generated GLSL for the lookup templates (templates/lookup/, shade.comp).
// Every knob the lookup reads becomes a folded constant; tables (Poisson taps, quadtree
// Next/Child, the unrolled traversal, layer splits) are generated here deterministically.
#include "emit/lookup_specialization.h"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <stdexcept>

#include "emit/poisson_disk.h"
#include "emit/quadtree_tables.h"
#include "emit/template_codes.h"

namespace shadowc {

namespace {

// Shortest round-trip-safe float literal: fixed "%.9g" keeps the bytes deterministic and the
// value exact to fp32; always carries a '.' or 'e' so GLSL reads it as float.
std::string glslFloat(double v) {
  if (!std::isfinite(v)) throw std::invalid_argument("non-finite constant in filter spec");
  std::string s = fmt::format("{:.9g}", v);
  if (s.find_first_of(".eEn") == std::string::npos) s += ".0";
  return s;
}

int technique(const FilterSpec& s) {
  // Values mirror templates/lookup/shadowc_lookup.glsl SHADOWC_TECHNIQUE_*.
  if (s.representation == Representation::Depth) return s.blocker.kind == BlockerKind::Search ? 1 : 0;
  return s.blocker.kind == BlockerKind::Moments ? 3 : 2;
}

int subdivisionValue(Subdivision s) {
  switch (s) {
    case Subdivision::None:
      return 0;
    case Subdivision::Uniform:
      return 1;
    case Subdivision::Quadtree:
      return 2;
  }
  return 0;
}

std::string poissonArray(std::string_view name, int count, uint64_t seed) {
  const std::vector<std::pair<double, double>> taps = poissonDisk(count, seed);
  std::string out =
      fmt::format("// {} Poisson-disk taps in the unit disk (best candidate, seed {}; pcss-blog.txt)\n", count, seed);
  out += fmt::format("const vec2 {}[{}] = vec2[](", name, count);
  for (size_t i = 0; i < taps.size(); ++i)
    out += fmt::format("{}vec2({}, {})", i ? ", " : "", glslFloat(taps[i].first), glslFloat(taps[i].second));
  out += ");\n";
  return out;
}

void check(bool ok, const std::string& message) {
  if (!ok) throw std::invalid_argument("lookup specialization: " + message);
}

}  // namespace

LookupSpecialization specializeLookup(const FilterSpec& s) {
  LookupSpecialization out;
  auto def = [&](const std::string& name, const std::string& value) { out.defines.emplace_back(name, value); };
  auto defInt = [&](const std::string& name, long long v) { def(name, std::to_string(v)); };
  auto defFloat = [&](const std::string& name, double v) { def(name, glslFloat(v)); };

  const int tech = technique(s);
  const bool moments = s.representation == Representation::Moments;
  const bool vssm = tech == 3;
  const int layers = moments ? s.moments.layers : 1;

  check(layers >= 1, "layers must be >= 1");
  check(!vssm || s.moments.warp == Warp::Linear, "the VSSM blocker estimate (eq. 4) needs the linear warp");
  check(moments || s.blocker.kind != BlockerKind::Moments,
        "the moments blocker estimate needs a moments representation");
  check(!vssm || layers == 1, "the VSSM path works on a single (unlayered) moments map");
  check(!(moments && s.moments.warp == Warp::PowerCdf && s.storage.sat != SatKind::None),
        "power_cdf stores min/max, which a summed-area table cannot sum");

  // ---- technique and resources -----------------------------------------------------------
  defInt("SHADOWC_TECHNIQUE", tech);
  defInt("SHADOWC_HAS_MOMENTS", moments ? 1 : 0);
  defInt("SHADOWC_HAS_SAT", moments && s.storage.sat != SatKind::None ? 1 : 0);
  defInt("SHADOWC_HAS_MINMAX", s.earlyOutMinMax ? 1 : 0);
  const bool splitsTexture = moments && layers > 1 && s.moments.split == SplitPlacement::Lloyd;
  defInt("SHADOWC_HAS_SPLITS_TEXTURE", splitsTexture ? 1 : 0);

  // ---- light ------------------------------------------------------------------------------
  if (!s.light.sizeFromScene) defFloat("SHADOWC_LIGHT_WIDTH", s.light.shape == LightShape::Point ? 0.0 : s.light.size);

  // ---- bias (pcss-blog.txt slope-scaled form) ---------------------------------------------
  defInt("SHADOWC_BIAS_KIND", static_cast<int>(s.bias.kind));
  defFloat("SHADOWC_BIAS_CONSTANT", s.bias.constant);
  defFloat("SHADOWC_BIAS_SLOPE", s.bias.slope);
  defFloat("SHADOWC_NORMAL_OFFSET", s.bias.normalOffset);

  // ---- kernel -----------------------------------------------------------------------------
  defInt("SHADOWC_KERNEL_PENUMBRA", s.kernel.size == KernelSize::Penumbra ? 1 : 0);
  defFloat("SHADOWC_KERNEL_FIXED_TEXELS", std::max(1, s.kernel.fixedTexels));
  // An int32 SAT box sum must fit in 32 bits: 255^2 texels * 65536 < 2^32 (sat.glsl, FACTS.md).
  const bool int32Sat = moments && s.storage.sat == SatKind::Int32;
  defFloat("SHADOWC_KERNEL_MAX_TEXELS", std::clamp(s.kernel.maxTexels, 1.0, int32Sat ? 255.0 : 1e6));
  defInt("SHADOWC_KERNEL_SUBDIVISION", subdivisionValue(s.kernel.subdivision));
  defInt("SHADOWC_KERNEL_N", std::max(1, s.kernel.uniformN));
  defInt("SHADOWC_KERNEL_HEIGHT", s.kernel.quadtreeHeight);
  defInt("SHADOWC_QUADTREE_UNROLLED", s.kernel.traversal == QuadtreeTraversal::Unrolled ? 1 : 0);
  defFloat("SHADOWC_LIT_THRESHOLD", s.kernel.litThreshold);

  // ---- PCF sampling (depth representation, fallback and contact paths) --------------------
  defInt("SHADOWC_PCF_PATTERN", static_cast<int>(s.sampling.pattern));
  defInt("SHADOWC_PCF_N", std::max(1, s.sampling.gridN));
  defInt("SHADOWC_PCF_TAPS", std::max(1, s.sampling.taps));
  defInt("SHADOWC_ROTATION_STABLE", s.sampling.rotation == Rotation::Stable ? 1 : 0);

  // ---- blocker ----------------------------------------------------------------------------
  defInt("SHADOWC_BLOCKER_KIND", static_cast<int>(s.blocker.kind));
  defInt("SHADOWC_BLOCKER_TAPS", std::max(1, s.blocker.taps));
  defInt("SHADOWC_BLOCKER_PATTERN", static_cast<int>(s.blocker.pattern));
  defInt("SHADOWC_BLOCKER_GRID_N", std::max(1, static_cast<int>(std::lround(std::sqrt(std::max(1, s.blocker.taps))))));
  defInt("SHADOWC_BLOCKER_SUBDIVISION", subdivisionValue(s.blocker.subdivision));
  defInt("SHADOWC_BLOCKER_M", std::max(1, s.blocker.uniformM));
  defInt("SHADOWC_BLOCKER_HEIGHT", s.blocker.quadtreeHeight);

  // ---- moments ----------------------------------------------------------------------------
  if (moments) {
    defInt("SHADOWC_WARP", warpDefineValue(s.moments.warp));
    defInt("SHADOWC_SAT_KIND", satKindDefineValue(s.storage.sat));
    defInt("SHADOWC_MIPS", s.prefilter.mips ? 1 : 0);
    defFloat("SHADOWC_EXP_POSITIVE", s.moments.positiveExponent);
    defFloat("SHADOWC_EXP_NEGATIVE", s.moments.negativeExponent);
    defFloat("SHADOWC_MIN_VARIANCE", std::max(0.0, s.moments.minVariance));
    // linstep(a, 1, p) divides by 1 - a (vsm-tutorial, lauritzen2008): keep a < 1.
    defFloat("SHADOWC_BLEEDING", std::clamp(s.moments.bleedingReduction, 0.0, 0.999));
    defInt("SHADOWC_BLEEDING_ON", s.moments.bleedingReduction > 0.0 ? 1 : 0);
    defInt("SHADOWC_LAYERS", layers);
    defFloat("SHADOWC_OVERLAP", std::max(0.0, s.moments.overlap));
    defInt("SHADOWC_LAYER_BLEND", layers > 1 && s.moments.overlap > 0.0 ? 1 : 0);
    if (layers > 1 && !splitsTexture) {
      const std::vector<double>& splits = s.moments.splits;  // layers+1 after normalization
      out.generatedCode += "// Layer split depths s_0..s_N (lauritzen2008 sec. 3.4)\n";
      out.generatedCode += fmt::format("const float shadowc_splitTable[{}] = float[](", layers + 1);
      for (size_t i = 0; i < splits.size(); ++i) out.generatedCode += (i ? ", " : "") + glslFloat(splits[i]);
      out.generatedCode += ");\n";
    }
  }

  // ---- extras -----------------------------------------------------------------------------
  defInt("SHADOWC_FALLBACK_PCF", s.fallback.pcf ? 1 : 0);
  defInt("SHADOWC_FALLBACK_N", std::max(1, s.fallback.n));
  defInt("SHADOWC_CONTACT", s.contact.enabled ? 1 : 0);
  defInt("SHADOWC_CONTACT_N", std::max(1, s.contact.n));
  defFloat("SHADOWC_CONTACT_EPSILON", s.contact.epsilon);
  defInt("SHADOWC_EARLY_OUT", s.earlyOutMinMax ? 1 : 0);
  // The early out must cover the blur footprint too (shadowc_lookup.glsl, shadowc_influenceRect).
  if (s.earlyOutMinMax && moments && s.prefilter.blur != BlurKind::None && s.prefilter.blurRadius > 0)
    defInt("SHADOWC_EARLY_OUT_GROW", s.prefilter.blurRadius);
  // Stability-suite demonstration only (FilterSpec::naiveUnguarded; validation/).
  if (s.naiveUnguarded) defInt("SHADOWC_NAIVE_UNGUARDED", 1);

  // ---- generated tables -------------------------------------------------------------------
  const bool depthPoisson = (tech == 0 || tech == 1) && s.sampling.pattern == PcfPattern::Poisson;
  if (depthPoisson) {
    out.generatedCode += poissonArray("shadowc_poissonPcf", std::max(1, s.sampling.taps), 0x5eed0001u);
    defInt("SHADOWC_HAS_POISSON_PCF", 1);
  }
  const bool searches = tech == 1 || (tech == 2 && s.blocker.kind == BlockerKind::Search);
  if (searches && s.blocker.pattern == SamplePattern::Poisson) {
    out.generatedCode += poissonArray("shadowc_poissonBlocker", std::max(1, s.blocker.taps), 0x5eed0002u);
    defInt("SHADOWC_HAS_POISSON_BLOCKER", 1);
  }
  if (vssm) {
    const bool kernelQt = s.kernel.subdivision == Subdivision::Quadtree;
    const bool blockerQt = s.blocker.subdivision == Subdivision::Quadtree;
    if (kernelQt) check(s.kernel.quadtreeHeight >= 1 && s.kernel.quadtreeHeight <= 5, "quadtree height must be 1..5");
    if (blockerQt)
      check(s.blocker.quadtreeHeight >= 1 && s.blocker.quadtreeHeight <= 5, "quadtree height must be 1..5");
    if (kernelQt || blockerQt) {
      if (s.kernel.traversal == QuadtreeTraversal::Unrolled) {
        if (kernelQt)
          out.generatedCode += emitUnrolledQuadtreeGlsl(s.kernel.quadtreeHeight, "shadowc_qtUnrolledKernel",
                                                        "shadowc_qtVisit", "shadowc_qtLeaf");
        if (blockerQt)
          out.generatedCode += emitUnrolledQuadtreeGlsl(s.blocker.quadtreeHeight, "shadowc_qtUnrolledBlocker",
                                                        "shadowc_qtVisit", "shadowc_qtLeaf");
      } else {
        // One table of the larger height serves both walks (next() does not depend on depth).
        const int h = std::max(kernelQt ? s.kernel.quadtreeHeight : 0, blockerQt ? s.blocker.quadtreeHeight : 0);
        const QuadtreeTables t = buildQuadtreeTables(h);
        out.generatedCode += emitQuadtreeTablesGlsl(t, "shadowc_qt");
        defInt("SHADOWC_QT_NODES", static_cast<long long>(t.nodes.size()));
      }
    }
  }
  return out;
}

std::string specializationBlock(const LookupSpecialization& s, int markerLine) {
  std::string out = "// shadowc specialization (generated)\n";
  for (const auto& [name, value] : s.defines) out += fmt::format("#define {} {}\n", name, value);
  out += s.generatedCode;
  out += fmt::format("#line {}\n", markerLine + 1);
  return out;
}

std::string insertSpecialization(const std::string& templateText, const LookupSpecialization& s) {
  const size_t pos = templateText.find(kSpecializeMarker);
  if (pos == std::string::npos) return templateText;
  const size_t lineStart = templateText.rfind('\n', pos) == std::string::npos ? 0 : templateText.rfind('\n', pos) + 1;
  size_t lineEnd = templateText.find('\n', pos);
  lineEnd = lineEnd == std::string::npos ? templateText.size() : lineEnd + 1;
  const int markerLine = 1 + static_cast<int>(std::count(templateText.begin(), templateText.begin() + pos, '\n'));
  return templateText.substr(0, lineStart) + specializationBlock(s, markerLine) + templateText.substr(lineEnd);
}

}  // namespace shadowc
