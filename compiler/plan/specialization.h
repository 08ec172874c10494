// Typed specialization values: what the planner decides for one pass's template, before any
// GLSL exists. A Constant sets one SHADOWC_* macro of the template; a Table is data the
// template reads by name (a const array or, for the unrolled quadtree, a generated function).
// Data the shader reads from a buffer (the quadtree's Next/Child tables) is the manifest's
// (Manifest::buffers), not a Table.
// The emitter renders both (emit/specialization_block.h); --print-plan prints them
// (plan/plan_printer.h). Nothing here is GLSL text.
#pragma once

#include <optional>
#include <string>
#include <utility>
#include <variant>
#include <vector>

#include "manifest/manifest.h"  // ImageFormat
#include "plan/template_codes.h"

namespace shadowc {

// A real the template folds in. The value is the one the shader should compute with: the
// prefilter passes store the fp32-rounded value (planner.cpp), the lookup the spec's value.
struct Real {
  double value = 0.0;
  friend bool operator==(const Real&, const Real&) = default;
};

// A float array the template folds in as a macro (SHADOWC_SPLITS, SHADOWC_BLUR_WEIGHTS).
struct RealList {
  std::vector<double> values;
  friend bool operator==(const RealList&, const RealList&) = default;
};

// Integer, boolean (rendered 1/0, read with #if), real, enum code (template_codes.h), image
// format (a storage-image layout qualifier), float array.
using SpecValue = std::variant<long long, bool, Real, EnumCode, ImageFormat, RealList>;

struct Constant {
  std::string name;  // the template macro, SHADOWC_*
  SpecValue value;
};

// `const float <name>[N]` (layer split depths).
struct RealTable {
  std::string name;
  std::string note;  // why the table exists (paper, section), rendered as a comment
  std::vector<double> values;
};

// `const vec2 <name>[N]` (Poisson taps).
struct PointTable {
  std::string name;
  std::string note;
  std::vector<std::pair<double, double>> points;
};

// Algorithm 2 unrolled for one height: `void <function>()` calling `visit` and `leaf`.
struct UnrolledQuadtree {
  int height = 0;
  std::string function, visit, leaf;
};

using Table = std::variant<RealTable, PointTable, UnrolledQuadtree>;

// Everything one template needs, in the order the emitter renders it.
struct Specialization {
  std::vector<Constant> constants;  // rendered `#define name value`, in this order
  std::vector<Table> tables;        // rendered after the constants, in this order
  // Generic shaders only (plan/generic_block.h): the uniform block declared first, and a
  // `#define <macro> shadowc_generic.<name>` per member in place of the constant or table.
  std::optional<ParameterBlock> parameters;
  void add(std::string name, SpecValue value) { constants.push_back({std::move(name), std::move(value)}); }
};

}  // namespace shadowc
