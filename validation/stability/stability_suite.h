// The numerical stability suite (docs/stability.md): hard cases for every filter they
// apply to, each asserting no NaN/Inf, every value in [0, 1] and an error against an exact
// double-precision reference within a bound written next to the case with its reason; plus
// the naive forms (plain fp32 SAT, unclamped EVSM exponent, unguarded 1/(1 - P) in the VSSM
// blocker estimate) shown failing on the very case where ours passes.
#pragma once

#include <functional>
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "spec/filter_spec.h"

namespace shadowc::rt {
class VulkanContext;
}

namespace shadowc::validation {

struct CaseResult {
  std::string caseName, filter;
  double worstError = 0;  // NaN: nothing was compared (the row fails)
  double bound = 0;
  std::string boundReason;
  uint64_t values = 0, nonFinite = 0, outOfRange = 0;
  // A naive or known-weak form: the row passes when the form FAILS the bound (shown failing where
  // ours passes). There is no way to excuse a row: every other row passes or fails.
  bool naive = false;
  bool pass = false;
  std::string detail;  // worst receiver, per-kernel errors, or why it failed
};

struct SuiteContext {
  rt::VulkanContext& vk;
};

struct StabilityCase {
  std::string name;
  std::string label;  // "stability" or "stability_large" (ctest label of its gtest case)
  std::string what;   // one line for the report
  // Filters the case runs by default: (name, spec). Specs may bypass the checker (naive forms).
  std::vector<FilterSpec> filters;
  // Whether a user filter (`shadowc stability --filter F`) fits the case.
  std::function<bool(const FilterSpec&)> appliesTo;
  std::function<CaseResult(SuiteContext&, const FilterSpec&)> run;
};

const std::vector<StabilityCase>& stabilityCases();

// Runs a case on its own filters, or on `override` when it applies (else nothing).
std::vector<CaseResult> runCase(SuiteContext& ctx, const StabilityCase& c, const FilterSpec* override = nullptr);

// Finishes a result: pass = finite, in range and within bound (inverted for naive rows); a row
// whose worst error is NaN compared nothing and fails, naive or not.
void settle(CaseResult& r);

// The largest distance of a value outside [lo, hi] (0 when all lie inside, infinite when one is
// not finite): the measured error of a row checked against a range rather than a reference.
double worstOutside(const std::vector<float>& values, double lo = 0.0, double hi = 1.0);

// Report: the Markdown table and JSON of the results.
std::string markdownTable(const std::vector<CaseResult>& results);
nlohmann::ordered_json resultsJson(const std::vector<CaseResult>& results);

// Randomized filters (docs/dsl.md ranges) as DSL text, seeded; each compiled and run on a
// random map must give valid SPIR-V and finite values in [0, 1].
std::string randomFilterSource(uint64_t seed, int index);
CaseResult runRandomFilter(SuiteContext& ctx, uint64_t seed, int index);

}  // namespace shadowc::validation
