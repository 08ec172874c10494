#include "validation/stability/stability_suite.h"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <map>
#include <stdexcept>

#include "validation/stability/case_support.h"

namespace shadowc::validation {

StabilityCase makeCase(const std::string& name, const std::string& what, std::vector<FilterSpec> filters,
                       std::function<bool(const FilterSpec&)> applies,
                       std::function<CaseResult(SuiteContext&, const FilterSpec&)> run) {
  StabilityCase c;
  c.name = name;
  c.label = "stability";
  c.what = what;
  c.filters = std::move(filters);
  c.appliesTo = applies ? std::move(applies) : [](const FilterSpec&) { return false; };
  c.run = std::move(run);
  return c;
}

FilterSpec libraryFilter(const std::string& name, const std::string& body) {
  return specFromSource(fmt::format("filter {} {{\n{}\n}}\n", name, body), name);
}

uint64_t mix64(uint64_t x) {  // splitmix64 finalizer
  x += 0x9e3779b97f4a7c15ull;
  x = (x ^ (x >> 30)) * 0xbf58476d1ce4e5b9ull;
  x = (x ^ (x >> 27)) * 0x94d049bb133111ebull;
  return x ^ (x >> 31);
}
double hash01(uint64_t seed, uint64_t i) {
  return double(mix64(seed * 0x100000001b3ull + i) >> 11) / double(1ull << 53);
}

DepthMap noiseMap(uint32_t size, uint64_t seed, double lo, double hi) {
  DepthMap m{size, std::vector<float>(size_t(size) * size)};
  for (size_t i = 0; i < m.depth.size(); ++i) m.depth[i] = float(lo + (hi - lo) * hash01(seed, i));
  return m;
}

DepthMap checkerMap(uint32_t size, float a, float b) {
  DepthMap m{size, std::vector<float>(size_t(size) * size)};
  for (uint32_t y = 0; y < size; ++y)
    for (uint32_t x = 0; x < size; ++x) m.depth[size_t(y) * size + x] = ((x + y) & 1) ? b : a;
  return m;
}

bool isMoments(const FilterSpec& s) { return s.representation == Representation::Moments; }
bool isVssm(const FilterSpec& s) { return isMoments(s) && s.blocker.kind == BlockerKind::Moments; }
bool hasSat(const FilterSpec& s) { return isMoments(s) && s.storage.sat != SatKind::None; }

CaseResult bounded(const FilterSpec& s) {
  CaseResult r;
  if (hasSat(s)) {
    r.bound = 5e-4;
    r.boundReason = "16.16 quantization of the mean moves Chebyshev by ~2e-3 p";
  } else if (isMoments(s)) {
    r.bound = 1e-4;
    r.boundReason = "same formula in fp32: ~1e-7 per moment x condition <= 1e3";
  } else {
    r.bound = 1e-6;
    r.boundReason = "PCF: exact counts, fp32 division";
  }
  return r;
}

void countValues(CaseResult& r, const std::vector<float>& values, double lo, double hi) {
  for (float v : values) {
    ++r.values;
    if (!std::isfinite(v))
      ++r.nonFinite;
    else if (v < lo || v > hi)
      ++r.outOfRange;
  }
}

void settle(CaseResult& r) {
  // A NaN error is a row that compared nothing: it proves nothing either way, naive or not.
  if (std::isnan(r.worstError)) {
    r.pass = false;
    if (r.detail.rfind("nothing compared", 0) != 0)
      r.detail = "nothing compared" + (r.detail.empty() ? std::string() : ": " + r.detail);
    return;
  }
  const bool clean = r.nonFinite == 0 && r.outOfRange == 0 && !(r.worstError > r.bound);
  r.pass = r.naive ? !clean : clean;
}

double worstOutside(const std::vector<float>& values, double lo, double hi) {
  double worst = 0;
  for (float v : values) {
    if (!std::isfinite(v)) return INFINITY;
    worst = std::max({worst, lo - double(v), double(v) - hi});
  }
  return worst;
}

CaseResult evaluate(SuiteContext& ctx, CaseResult r, const FilterSpec& spec, const DepthMap& map,
                    const std::vector<Receiver>& receivers, const LightFrame& light, ReferenceForm form) {
  r.filter = spec.name;
  const CompiledFilter& cf = compileCached(spec, r.naive);
  const CraftedResult run = runCrafted(ctx.vk, cf, map, receivers, light);
  countValues(r, run.visibility);
  const IntentReference reference(spec, map, light, form);
  r.worstError = 0;
  size_t compared = 0;
  for (size_t i = 0; i < receivers.size(); ++i) {
    const std::vector<double> ref = reference(receivers[i]);
    if (ref.empty()) continue;
    ++compared;
    double err = INFINITY;
    for (double v : ref) err = std::min(err, std::fabs(double(run.visibility[i]) - v));
    if (std::isnan(double(run.visibility[i]))) err = INFINITY;
    if (err > r.worstError || (std::isinf(err) && !std::isinf(r.worstError))) {
      r.worstError = err;
      r.detail = fmt::format("worst: receiver {} (u {:.5f}, v {:.5f}, d {:.6g}) GPU {:.7g} vs reference {:.7g}", i,
                             receivers[i].u, receivers[i].v, receivers[i].d, run.visibility[i], ref[0]);
    }
  }
  if (compared == 0) {
    r.worstError = NAN;
    r.detail = intentModels(spec) ? "no receivers" : "the intent reference does not model this filter";
  }
  settle(r);
  return r;
}

std::vector<CaseResult> runCase(SuiteContext& ctx, const StabilityCase& c, const FilterSpec* override) {
  std::vector<CaseResult> out;
  auto runOne = [&](const FilterSpec& spec) {
    try {
      CaseResult r = c.run(ctx, spec);
      r.caseName = c.name;
      if (r.filter.empty()) r.filter = spec.name;
      out.push_back(std::move(r));
    } catch (const std::exception& e) {
      CaseResult r;
      r.caseName = c.name;
      r.filter = spec.name;
      r.worstError = NAN;
      r.detail = fmt::format("error: {}", e.what());
      r.pass = false;
      out.push_back(std::move(r));
    }
  };
  if (override) {
    if (c.appliesTo && c.appliesTo(*override)) runOne(*override);
    return out;
  }
  for (const FilterSpec& spec : c.filters) runOne(spec);
  return out;
}

const std::vector<StabilityCase>& stabilityCases() {
  static const std::vector<StabilityCase> cases = [] {
    std::vector<StabilityCase> out;
    addSatCases(out);
    addCornerCases(out);
    addEstimatorCases(out);
    addGeometryCases(out);
    addNaiveCases(out);
    addEarlyOutCases(out);
    addContactCases(out);
    addMsmCases(out);
    addLightCases(out);
    addWeightsCases(out);
    return out;
  }();
  return cases;
}

namespace {
std::string num(double v) {
  if (std::isnan(v)) return "n/a";
  if (std::isinf(v)) return "inf";
  return fmt::format("{:.3g}", v);
}
}  // namespace

std::string markdownTable(const std::vector<CaseResult>& results) {
  std::string out =
      "| case | filter | worst error | bound | NaN/Inf | out of [0,1] | result |\n"
      "|---|---|---|---|---|---|---|\n";
  for (const CaseResult& r : results)
    out += fmt::format("| {} | {}{} | {} | {} | {} | {} | {} |\n", r.caseName, r.filter, r.naive ? " (naive)" : "",
                       num(r.worstError), num(r.bound), r.nonFinite, r.outOfRange,
                       r.naive ? (r.pass ? "fails as expected" : "UNEXPECTEDLY PASSES") : (r.pass ? "pass" : "FAIL"));
  return out;
}

nlohmann::ordered_json resultsJson(const std::vector<CaseResult>& results) {
  nlohmann::ordered_json cases = nlohmann::ordered_json::array();
  size_t failed = 0;
  for (const CaseResult& r : results) {
    nlohmann::ordered_json j;
    j["case"] = r.caseName;
    j["filter"] = r.filter;
    j["naive"] = r.naive;
    j["worst_error"] =
        std::isfinite(r.worstError) ? nlohmann::ordered_json(r.worstError) : nlohmann::ordered_json(num(r.worstError));
    j["bound"] = r.bound;
    j["bound_reason"] = r.boundReason;
    j["values"] = r.values;
    j["non_finite"] = r.nonFinite;
    j["out_of_range"] = r.outOfRange;
    j["pass"] = r.pass;
    j["detail"] = r.detail;
    failed += r.pass ? 0 : 1;
    cases.push_back(std::move(j));
  }
  nlohmann::ordered_json root;
  root["cases"] = std::move(cases);
  root["failed"] = failed;
  return root;
}

}  // namespace shadowc::validation
