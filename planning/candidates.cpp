#include "planning/candidates.h"

#include <fmt/core.h>

#include <mutex>
#include <set>

#include "driver/driver.h"
#include "spec/precision.h"
#include "spec/print_filter.h"

namespace shadowc::planning {
namespace {

Candidate depthFixed(std::string name, std::string family, int texels) {
  Candidate c;
  c.name = std::move(name);
  c.family = std::move(family);
  c.fixedTexels = texels;
  return c;
}

Candidate pcss(int pcfTaps) {
  Candidate c;
  c.name = fmt::format("pcss_poisson{}", pcfTaps);
  c.family = "pcss";
  c.blocker = c.penumbraKernel = true;
  c.pcfTaps = pcfTaps;
  return c;
}

// A depth candidate over a sun's cascades (the checker refuses moments and the min-max early out
// with cascades, E0452): the camera's depth range cut into n slices, each with its own map.
Candidate cascaded(Candidate c, int n) {
  c.cascades = n;
  c.name += fmt::format("_cascades{}", n);
  return c;
}

Candidate vssm(bool quadtree, int height, bool fallback, bool contact, bool earlyOut) {
  Candidate c;
  c.family = "vssm";
  c.blocker = c.sat = c.penumbraKernel = true;
  c.quadtree = quadtree;
  c.quadtreeHeight = height;
  c.fallback = fallback;
  c.contact = contact;
  c.earlyOut = earlyOut;
  c.name = quadtree ? fmt::format("vssm_quadtree{}", height) : fmt::format("vssm_uniform{}", c.uniformN);
  if (fallback) c.name += "_fallback";
  if (contact) c.name += "_contact";
  if (earlyOut) c.name += "_early_out";
  return c;
}

std::vector<Candidate> buildCatalog() {
  std::vector<Candidate> v;
  v.push_back(depthFixed("hard", "hard", 1));
  v.push_back(depthFixed("pcf_grid3", "pcf", 3));
  v.push_back(depthFixed("pcf_grid5", "pcf", 5));
  Candidate layered;
  layered.name = "layered_vsm4";
  layered.family = "layered_vsm";
  layered.layers = 4;
  v.push_back(layered);
  v.push_back(pcss(16));
  v.push_back(pcss(32));
  v.push_back(cascaded(depthFixed("pcf_grid3", "pcf", 3), 4));
  v.push_back(cascaded(pcss(16), 4));
  v.push_back(cascaded(pcss(32), 4));
  v.push_back(vssm(false, 0, false, false, false));
  v.push_back(vssm(false, 0, false, true, false));
  v.push_back(vssm(false, 0, true, false, false));
  v.push_back(vssm(true, 2, false, false, false));
  v.push_back(vssm(true, 2, true, false, false));
  v.push_back(vssm(true, 2, false, false, true));
  v.push_back(vssm(true, 2, true, true, false));
  v.push_back(vssm(true, 3, true, true, true));  // everything on, the paper's height 3
  return v;
}

}  // namespace

const char* featureName(Feature f) {
  switch (f) {
    case Feature::BlockerSearch:
      return "blocker search";
    case Feature::Sat:
      return "SAT";
    case Feature::PenumbraKernel:
      return "penumbra kernel";
    case Feature::Quadtree:
      return "quadtree subdivision";
    case Feature::Fallback:
      return "PCF fallback";
    case Feature::Contact:
      return "contact path";
    case Feature::EarlyOut:
      return "min-max early out";
    case Feature::Layers:
      return "layers";
    case Feature::Cascades:
      return "cascades";
    case Feature::SlopeBias:
      return "slope-scaled bias";
  }
  return "?";
}

bool Candidate::has(Feature f) const {
  switch (f) {
    case Feature::BlockerSearch:
      return blocker;
    case Feature::Sat:
      return sat;
    case Feature::PenumbraKernel:
      return penumbraKernel;
    case Feature::Quadtree:
      return quadtree;
    case Feature::Fallback:
      return fallback;
    case Feature::Contact:
      return contact;
    case Feature::EarlyOut:
      return earlyOut;
    case Feature::Layers:
      return layers > 1;
    case Feature::Cascades:
      return cascades > 0;
    case Feature::SlopeBias:
      return family == "hard" || family == "pcf" || family == "pcss";
  }
  return false;
}

const std::vector<Candidate>& candidateCatalog() {
  static const std::vector<Candidate> catalog = buildCatalog();
  return catalog;
}

const Candidate& everythingOn() { return candidateCatalog().back(); }

const Candidate* findCandidate(const std::string& name) {
  for (const Candidate& c : candidateCatalog())
    if (c.name == name) return &c;
  return nullptr;
}

FilterSpec candidateSpec(const Candidate& c, const DescribeOptions& o) {
  FilterSpec s;
  s.name = o.filterName;
  s.resolution = o.resolution;
  s.mapSize = std::max(s.mapSize, o.resolution);
  s.light.shape = LightShape::Rect;
  s.light.sizeFromScene = true;  // the runtime supplies the scene's light width
  if (o.light == LightType::Sun) s.light.type = LightType::Sun, s.light.shape = LightShape::Disk;  // the scene's angle
  if (o.light == LightType::Point) s.light.type = LightType::Point;                                // the scene's radius
  if (c.cascades > 0) {
    s.cascades.count = c.cascades;  // `cascades N` (docs/dsl.md): practical, lambda 0.5, blend 0.1
    s.cascades.split = CascadeSplit::Practical;
  }
  const bool depthFamily = c.family == "hard" || c.family == "pcf" || c.family == "pcss";
  if (depthFamily) {
    s.representation = Representation::Depth;
    if (c.blocker) {
      // pcss-blog: Poisson blocker search, penumbra estimate, Poisson PCF of that width.
      s.blocker.kind = BlockerKind::Search;
      s.blocker.taps = c.searchTaps;
      s.blocker.pattern = SamplePattern::Poisson;
      s.kernel.size = KernelSize::Penumbra;
      s.kernel.maxTexels = 64;
      s.sampling.pattern = PcfPattern::Poisson;
      s.sampling.taps = c.pcfTaps;
      s.sampling.rotation = Rotation::Stable;
    } else {
      s.kernel.size = KernelSize::Fixed;
      s.kernel.fixedTexels = c.fixedTexels;
      s.sampling.pattern = PcfPattern::Grid;
      s.sampling.gridN = c.fixedTexels;
    }
    if (c.cascades > 0) {
      // A depth bias is in normalized depth, the same in every cascade while their texels differ
      // ~8x; a normal offset is in texels of the receiver's own cascade (tests/gpu/cascades_test.cpp).
      s.bias.kind = BiasKind::NormalOffset;
      s.bias.normalOffset = 1.5;
      s.bias.constant = 0.0002;
    } else if (o.slopeBias && o.light == LightType::Point) {
      // A cube face sees the room's walls at grazing angles from inside (point_room: p99 slope
      // 69 degrees): the receiver-plane form follows the slope per tap (Isidoro 2006; pcss_poisson's
      // bias). Measured on point_room, 256^2 / 1024^2, 3x3 PCF: rmse 0.080 vs 0.227 slope-scaled.
      s.bias.kind = BiasKind::ReceiverPlane;
      s.bias.constant = 0.001;
      s.bias.normalOffset = 2;
      s.bias.maxSlope = 50;  // the language's default (docs/dsl.md "bias")
    } else if (o.slopeBias) {
      s.bias.kind = BiasKind::SlopeScaled;  // max(slope (1 - N.L), constant), pcss-blog
      s.bias.slope = 0.005;
      s.bias.constant = 0.001;
    } else {
      s.bias.kind = BiasKind::Constant;
      s.bias.constant = 0.001;
    }
    return s;
  }
  s.representation = Representation::Moments;
  s.moments.warp = Warp::Linear;
  s.moments.layers = c.layers;
  s.moments.split = SplitPlacement::Uniform;
  s.moments.splits.clear();
  for (int i = 0; i <= c.layers; ++i) s.moments.splits.push_back(double(i) / c.layers);
  s.kernel.size = KernelSize::Fixed;
  s.kernel.fixedTexels = 1;
  if (c.family == "layered_vsm") {
    // lauritzen2008 sec. 3-4: uniform splits with a small overlap, box-blurred moments.
    s.moments.overlap = 0.02;
    s.prefilter.blur = BlurKind::Box;
    s.prefilter.blurRadius = 2;
    return s;
  }
  // VSSM (vssm-yang2010): int32 SAT (sec. 6.4), eq. 4 blocker estimate with the paper's mixed
  // scheme (uniform m = 5), uniform or quadtree kernel (sec. 5.2-5.3).
  s.storage.sat = SatKind::Int32;
  s.blocker.kind = BlockerKind::Moments;
  s.blocker.subdivision = Subdivision::Uniform;
  s.blocker.uniformM = 5;
  s.kernel.size = KernelSize::Penumbra;
  // What the int32 SAT serves: kernels up to the whole map (sat.glsl sums wide boxes in pieces).
  s.kernel.maxTexels = spec::kMaxKernelTexels;
  s.kernel.subdivision = c.quadtree ? Subdivision::Quadtree : Subdivision::Uniform;
  s.kernel.quadtreeHeight = c.quadtreeHeight > 0 ? c.quadtreeHeight : s.kernel.quadtreeHeight;
  s.kernel.uniformN = c.uniformN;
  s.fallback.pcf = c.fallback;
  s.fallback.n = 2;
  s.contact.enabled = c.contact;
  s.contact.n = 3;
  s.contact.epsilon = o.contactEpsilon;
  s.earlyOutMinMax = c.earlyOut;
  return s;
}

namespace {

// The setting a feature's comment sits above in printFilter's output.
const char* settingOf(Feature f) {
  switch (f) {
    case Feature::BlockerSearch:
      return "blocker";
    case Feature::Sat:
      return "storage";
    case Feature::PenumbraKernel:
      return "kernel";
    case Feature::Quadtree:
      return "kernel";
    case Feature::Fallback:
      return "fallback";
    case Feature::Contact:
      return "contact";
    case Feature::EarlyOut:
      return "early_out";
    case Feature::Layers:
      return "representation";
    case Feature::Cascades:
      return "cascades";
    case Feature::SlopeBias:
      return "bias";
  }
  return "";
}

}  // namespace

bool candidateAccepted(const Candidate& c, const DescribeOptions& o, std::string* why) {
  // The checker's answer depends on the candidate and the light only; asked once per pair.
  static std::mutex mutex;
  static std::map<std::pair<std::string, int>, std::string> answers;  // "" = accepted
  const auto key = std::make_pair(c.name, int(o.light));
  std::lock_guard<std::mutex> lock(mutex);
  auto it = answers.find(key);
  if (it == answers.end()) {
    DescribeOptions d = o;
    d.featureComments.clear();
    d.header.clear();
    driver::Options opt;
    opt.stopAfter = driver::Stage::Check;
    const driver::Result r = driver::compileSource(printFilter(candidateSpec(c, d)), c.name, opt);
    std::string error;
    if (!r.ok || !r.spec) {
      error = "the checker refused it";
      for (const Diagnostic& diag : r.diagnostics)
        if (diag.severity == Severity::Error) {
          error = diag.code + ": " + diag.message;
          break;
        }
    }
    it = answers.emplace(key, error).first;
  }
  if (why) *why = it->second;
  return it->second.empty();
}

std::string describeCandidate(const Candidate& c, const DescribeOptions& o) {
  const std::string printed = printFilter(candidateSpec(c, o));  // spec/print_filter.h: every argument named
  std::string out;
  std::set<Feature> written;
  for (const std::string& line : o.header) out += line.empty() ? "#\n" : "# " + line + "\n";
  size_t pos = 0;
  while (pos < printed.size()) {
    const size_t eol = printed.find('\n', pos);
    const std::string line = printed.substr(pos, eol == std::string::npos ? std::string::npos : eol - pos);
    pos = eol == std::string::npos ? printed.size() : eol + 1;
    std::string key = line.size() > 4 ? line.substr(4, line.find(' ', 4) - 4) : "";
    if (key == "depth" || key == "moments") key = "representation";
    for (Feature f : kFeatures) {
      auto it = o.featureComments.find(f);
      if (it != o.featureComments.end() && key == settingOf(f)) {
        out += "    # " + it->second + "\n";
        written.insert(f);
      }
    }
    // A comment whose setting the printer leaves out (no `cascades` line on one map) closes the body.
    if (line == "}")
      for (const auto& [f, text] : o.featureComments)
        if (!written.count(f)) out += "    # " + text + "\n";
    out += line + "\n";
  }
  return out;
}

}  // namespace shadowc::planning
