// Internals shared by the case files of the stability suite: the filter library, map makers and
// the generic "run on the GPU, compare with the intent reference" evaluation.
#pragma once

#include <cstdint>
#include <functional>
#include <string>
#include <vector>

#include "validation/stability/crafted_run.h"
#include "validation/stability/intent_reference.h"
#include "validation/stability/stability_suite.h"

namespace shadowc::validation {

// A case with the suite's label. `applies` says which user filters (`--filter F`) fit it; leave
// it empty for fixed demonstrations that run only their own filters.
StabilityCase makeCase(const std::string& name, const std::string& what, std::vector<FilterSpec> filters,
                       std::function<bool(const FilterSpec&)> applies,
                       std::function<CaseResult(SuiteContext&, const FilterSpec&)> run);

// Checked spec of a library filter: `filter NAME {` BODY `}`.
FilterSpec libraryFilter(const std::string& name, const std::string& body);

// Deterministic maps.
uint64_t mix64(uint64_t x);
double hash01(uint64_t seed, uint64_t i);  // in [0, 1)
DepthMap noiseMap(uint32_t size, uint64_t seed, double lo, double hi);
DepthMap checkerMap(uint32_t size, float a, float b);

// Runs the receivers, compares each with the intent reference (closest candidate), counts
// NaN/Inf and out-of-range values. The caller sets bound, reason and naive first. `form`: a
// deliberately wrong reference (siblings).
CaseResult evaluate(SuiteContext& ctx, CaseResult r, const FilterSpec& spec, const DepthMap& map,
                    const std::vector<Receiver>& receivers, const LightFrame& light, ReferenceForm form = {});

// The bound of a filter against the intent reference, by what it computes: fp32 evaluation of the
// same formulas; int32 SATs add the 16.16 quantization of the means (cases_estimator.cpp); PCF
// counts are exact (ties are avoided by the cases' random depths).
CaseResult bounded(const FilterSpec& s);

// Counts non-finite and out-of-range values of `values` into r.
void countValues(CaseResult& r, const std::vector<float>& values, double lo = 0.0, double hi = 1.0);

bool isMoments(const FilterSpec& s);
bool isVssm(const FilterSpec& s);
bool hasSat(const FilterSpec& s);

void addSatCases(std::vector<StabilityCase>& out);
void addEstimatorCases(std::vector<StabilityCase>& out);
void addGeometryCases(std::vector<StabilityCase>& out);
void addNaiveCases(std::vector<StabilityCase>& out);
void addEarlyOutCases(std::vector<StabilityCase>& out);
void addContactCases(std::vector<StabilityCase>& out);
void addMsmCases(std::vector<StabilityCase>& out);
void addCornerCases(std::vector<StabilityCase>& out);
void addLightCases(std::vector<StabilityCase>& out);
void addWeightsCases(std::vector<StabilityCase>& out);

}  // namespace shadowc::validation
