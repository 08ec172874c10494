// The candidate builder: the variants the planner chooses among, each one a point in DESIGN.md's
// space written as an ordinary filter description. The ONE place that writes description text
// (until compiler/spec/print_filter.h's printFilter(FilterSpec) replaces the text building in
// describeCandidate()). Calibration measures exactly these texts.
#pragma once

#include <map>
#include <string>
#include <vector>

namespace shadowc::planning {

// The features a plan keeps or drops, one comment each in the written file.
enum class Feature { BlockerSearch, Sat, PenumbraKernel, Quadtree, Fallback, Contact, EarlyOut, Layers, SlopeBias };
inline constexpr Feature kFeatures[] = {Feature::BlockerSearch, Feature::Sat,      Feature::PenumbraKernel,
                                        Feature::Quadtree,      Feature::Fallback, Feature::Contact,
                                        Feature::EarlyOut,      Feature::Layers,   Feature::SlopeBias};
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
  bool has(Feature f) const;
};

// Every variant, cheapest family first. The last one is "everything on" (VSSM quadtree +
// PCF fallback + contact + min-max early out; VSSM takes one moments layer only).
const std::vector<Candidate>& candidateCatalog();
const Candidate& everythingOn();
const Candidate* findCandidate(const std::string& name);

struct DescribeOptions {
  std::string filterName = "planned";
  bool slopeBias = true;                           // depth families: slope-scaled vs constant bias
  double contactEpsilon = 0.01;                    // normalized depth
  std::vector<std::string> header;                 // comment lines at the top (without '#')
  std::map<Feature, std::string> featureComments;  // one comment per feature (without '#')
};

// The filter description text of a candidate (the checker accepts it; comments included).
std::string describeCandidate(const Candidate& c, const DescribeOptions& options);

}  // namespace shadowc::planning
