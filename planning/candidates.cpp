#include "planning/candidates.h"

#include <fmt/core.h>

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

std::string describeCandidate(const Candidate& c, const DescribeOptions& o) {
  std::string out;
  for (const std::string& line : o.header) out += line.empty() ? "#\n" : "# " + line + "\n";
  out += fmt::format("filter {} {{\n", o.filterName);
  for (Feature f : kFeatures) {
    auto it = o.featureComments.find(f);
    if (it != o.featureComments.end()) out += "    # " + it->second + "\n";
  }
  auto line = [&](const char* key, const std::string& value) { out += fmt::format("    {:<10} {}\n", key, value); };
  const bool depthFamily = c.family == "hard" || c.family == "pcf" || c.family == "pcss";
  if (depthFamily) {
    out += "    depth\n";
    if (c.blocker) {
      line("blocker", fmt::format("search({}, pattern: poisson)", c.searchTaps));
      line("kernel", "penumbra(max: 64)");
      line("sampling", fmt::format("poisson({}, rotate: stable)", c.pcfTaps));
    } else {
      line("kernel", fmt::format("fixed({})", c.fixedTexels));
    }
    line("bias", o.slopeBias ? "slope(0.005, constant: 0.001)" : "constant(0.001)");
  } else if (c.family == "layered_vsm") {
    // lauritzen2008 sec. 3-4: uniform splits with a small overlap, box-blurred moments.
    line("moments", fmt::format("linear(layers: {}, split: uniform, overlap: 0.02)", c.layers));
    line("blur", "box(radius: 2)");
  } else {
    line("moments", "linear");
    line("storage", "sat(int32)");
    line("blocker", "moments");
    line("kernel", c.quadtree ? fmt::format("quadtree(height: {}, max: 128)", c.quadtreeHeight)
                              : fmt::format("uniform({}, max: 128)", c.uniformN));
    if (c.fallback) line("fallback", "pcf(2x2)");
    if (c.contact) line("contact", fmt::format("pcf(3x3, epsilon: {:g})", o.contactEpsilon));
    if (c.earlyOut) line("early_out", "minmax");
  }
  out += "}\n";
  return out;
}

}  // namespace shadowc::planning
