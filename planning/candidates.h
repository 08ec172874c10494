// The candidate builder: the variants the planner chooses among, each one a point in the filter
// space (docs/dsl.md) built as a FilterSpec (candidateSpec) and written as an ordinary filter description by
// the one spec printer (spec/print_filter.h) with the plan's comments. Calibration and
// confirmation compile exactly these specs (driver::compileSpec).
#pragma once

#include <map>
#include <string>
#include <vector>

#include "spec/filter_spec.h"

namespace shadowc::planning {

// The features a plan keeps or drops, one comment each in the written file.
enum class Feature {
  BlockerSearch,
  Sat,
  PenumbraKernel,
  Quadtree,
  Fallback,
  Contact,
  EarlyOut,
  Layers,
  Cascades,
  SlopeBias
};
inline constexpr Feature kFeatures[] = {
    Feature::BlockerSearch, Feature::Sat,      Feature::PenumbraKernel, Feature::Quadtree, Feature::Fallback,
    Feature::Contact,       Feature::EarlyOut, Feature::Layers,         Feature::Cascades, Feature::SlopeBias};
const char* featureName(Feature f);  // "blocker search", "SAT", ...

struct Candidate {
  std::string name;    // "pcss_poisson32", "vssm_quadtree2_fallback", ...
  std::string family;  // hard, pcf, layered_vsm, pcss, vssm
  bool blocker = false, sat = false, penumbraKernel = false, quadtree = false, fallback = false, contact = false,
       earlyOut = false;
  int layers = 1;
  int fixedTexels = 1;     // fixed kernels
  int searchTaps = 16;     // pcss blocker search
  int pcfTaps = 16;        // pcss Poisson PCF taps
  int uniformN = 4;        // vssm uniform kernel
  int quadtreeHeight = 2;  // vssm quadtree kernel
  int cascades = 0;        // a sun's cascades (practical split, lambda 0.5, blend 0.1); 0 = one map
  bool has(Feature f) const;
};

// Every variant, cheapest family first. The last one is "everything on" (VSSM quadtree +
// PCF fallback + contact + min-max early out; VSSM takes one moments layer only). Not every one
// serves every light: which do is the checker's call (candidateAccepted).
const std::vector<Candidate>& candidateCatalog();
const Candidate& everythingOn();
const Candidate* findCandidate(const std::string& name);

struct DescribeOptions {
  std::string filterName = "planned";
  bool slopeBias = true;         // depth families: slope-scaled vs constant bias
  double contactEpsilon = 0.01;  // normalized depth
  // The scenes' light: `light area(size: scene)`, `light sun(angle: scene)` or
  // `light point(radius: scene)` (a filter reads its map through its light's projection).
  LightType light = LightType::Spot;
  // The map side the filter is planned for (`resolution`, docs/dsl.md), 0 = none; map_size follows it.
  int resolution = 0;
  std::vector<std::string> header;                 // comment lines at the top (without '#')
  std::map<Feature, std::string> featureComments;  // one comment per feature (without '#')
};

FilterSpec candidateSpec(const Candidate& c, const DescribeOptions& options);
// Whether the checker accepts the candidate for options.light (e.g. E0450: no SAT, min-max early
// out or subdivided kernel on a point light's cube atlas; E0453: cascades only for a sun); on
// false, `why` gets its first error ("E0450: ...").
bool candidateAccepted(const Candidate& c, const DescribeOptions& options, std::string* why = nullptr);
// printFilter(candidateSpec(...)) with the header and one comment above the setting of each
// feature (the checker accepts it).
std::string describeCandidate(const Candidate& c, const DescribeOptions& options);

}  // namespace shadowc::planning
