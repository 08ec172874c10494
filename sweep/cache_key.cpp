#include "sweep/cache_key.h"

#include "emit/content_hash.h"
#include "plan/work_counters.h"
#include "sweep/results_io.h"

namespace shadowc::sweep {

std::string cacheKey(const KeyInputs& in) {
  nlohmann::ordered_json j;
  j["results_version"] = kResultsVersion;  // a new row format invalidates old entries
  j["spec"] = in.spec;
  j["shader"] = in.shader;
  j["emitted"] = in.emitted;
  j["scene_hash"] = in.sceneHash;
  j["screen"] = in.screen;
  j["map"] = in.map;
  j["reference_samples"] = in.referenceSamples;
  if (in.runs.automatic)  // a fixed count keeps the key it always had
    j["runs"] = "auto";
  else
    j["runs"] = in.runs.runs;
  j["warmup"] = in.warmup;
  j["device"] = in.device;
  // Rows without counts keep the key they always had; counted rows name the counters, so a build
  // that counts something new measures its rows again.
  if (in.counters) {
    nlohmann::ordered_json names = nlohmann::ordered_json::array();
    for (const WorkCounter& c : workCounters()) names.push_back(c.name);
    j["counters"] = std::move(names);
  }
  const std::string h = contentHash({EmittedFile{"sweep-row", j.dump()}});
  return h.substr(h.find(':') + 1);
}

}  // namespace shadowc::sweep
