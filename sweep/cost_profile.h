// Device cost profiles (docs/cost.md): a frame's time predicted from work that does not move
// with load. A pass over the map costs a fixed time plus a time per map texel (each prefilter
// pass does a fixed amount of work per texel, set when the filter is compiled); the shade pass
// costs a fixed time plus a time per screen pixel plus a time per unit of each work counter
// (docs/manifest.md "Work counters": exact, the same on every device). The coefficients are
// fitted per device, by non-negative least squares on relative error, from the per-pass medians
// and counts of a calibration sweep (`shadowc cost-profile`), and stored as JSON.
#pragma once

#include <cstdint>
#include <filesystem>
#include <map>
#include <optional>
#include <string>
#include <vector>

#include "runtime/harness/work_counts.h"
#include "sweep/sweep_row.h"

namespace shadowc::sweep {

// What a profile reads of one measured row: its sizes, its passes' medians and its counts. Read
// from a full results.json or from trimmed rows (bench/results/) alike.
struct CostSample {
  std::string variant, caseLabel, scene, device;
  uint32_t screen = 0, map = 0;
  std::vector<PassTime> passes;
  double totalMs = 0;
  std::optional<rt::WorkCounts> work;
  // Moment channels stored per map texel, times the layers (the spec's warp and layer count:
  // 2 for VSM, 4 for 4MSM, 8 for two VSM layers); 0 when the row has no spec. A prefilter pass
  // that writes or reads the moments does work in proportion.
  double momentChannels = 0;
};
CostSample costSample(const Row& row);
// A spec JSON's moment channels times its layers (CostSample::momentChannels); 0 without moments.
double momentChannelsOfSpec(const nlohmann::json& spec);
// The rows of a results.json (`rows[]`: variant, case, scene, screen, map, passes, total_ms and,
// when counted, work); throws std::runtime_error naming the file and the field.
std::vector<CostSample> readCostSamples(const std::filesystem::path& resultsJson);
// Gives every sample without counts the counts of the sample of the same variant and case in
// `counted` (counts are the same on every device, so a counted run elsewhere serves); returns
// how many still have none. The moment channels come with the counts when a sample has none.
size_t attachCounts(std::vector<CostSample>& samples, const std::vector<CostSample>& counted);

struct PassCost {
  double fixedMs = 0, msPerMtexel = 0, msPerMchannel = 0;  // ms per million texel-channels
  size_t samples = 0;                                      // how many pass medians it was fitted on
};
struct ShadeCost {
  double fixedMs = 0, msPerMpixel = 0;
  std::map<std::string, double> msPerMcount;  // counter field -> ms per million counts
  size_t samples = 0;
};

struct CostProfile {
  std::string device;       // what it was fitted on ("llvmpipe (LLVM 15.0.6, 256 bits)")
  std::string generatedBy;  // the command that wrote it
  ShadeCost shade;
  std::map<std::string, PassCost> passes;  // prefilter passes by name (moments, sat_rows, ...)
  std::map<std::string, PassCost> kinds;   // by kind: a pass whose name was not fitted

  // The predicted median of one pass of `sample`; nullopt when the profile cannot price it (a
  // shade pass without counts, a prefilter pass of a kind it never saw).
  std::optional<double> passMs(const PassTime& pass, const CostSample& sample) const;
  // The frame: the sum over the sample's passes; nullopt when one of them has no price.
  std::optional<double> frameMs(const CostSample& sample) const;
};

// Fits a profile to the samples (those with counts; at least one shade pass needed). Deterministic.
CostProfile fitCostProfile(const std::vector<CostSample>& samples, const std::string& device,
                           const std::string& command);

// How well `profile` predicts the frames of `samples`: over those it prices, the median and the
// largest |ln(predicted / measured)|, and how many fall within `ratio` either way.
struct FitQuality {
  size_t priced = 0, unpriced = 0, within = 0;
  double medianAbsLog = 0, maxAbsLog = 0;
  std::string worst;  // "variant on case: predicted x ms, measured y ms"
};
FitQuality assessFit(const CostProfile& profile, const std::vector<CostSample>& samples, double ratio = 1.5);

std::string costProfileToJson(const CostProfile& profile);
CostProfile parseCostProfile(const std::string& jsonText, const std::string& label);
CostProfile loadCostProfile(const std::filesystem::path& file);
// The profiles built into shadowc (samples/cost/*.json), by name: "lavapipe", "h200".
std::vector<std::string> builtInCostProfiles();
// `--cost-profile ARG`: a file when ARG has a '/', ends in ".json" or names a file here, else
// the built-in profile of that name; anything else is one message listing the built-in names.
CostProfile resolveCostProfile(const std::string& arg);

}  // namespace shadowc::sweep
