// Expansion of a sweep description into variants (base filter x parameter values x shader
// kind, each as filter description text) and cases (scene x screen x map), and the
// deterministic job order that shards slice. Same description -> same variants, same order.
#pragma once

#include <cstddef>
#include <cstdint>
#include <string>
#include <utility>
#include <vector>

#include "sweep/sweep_spec.h"

namespace shadowc::sweep {

struct Variant {
  size_t index = 0;
  std::string base;                                         // BaseFilter::name
  std::string source;                                       // where the base text came from
  std::vector<std::pair<std::string, std::string>> params;  // name, value; in the sweep's order
  ShaderKind shader = ShaderKind::Specialized;
  std::string label;  // "pcss_poisson[taps=16]", " (generic)" appended for generic shaders
  std::string text;   // the variant's filter description
};

struct Case {
  size_t index = 0;
  SceneEntry scene;
  uint32_t screen = 0, map = 0;
  std::string label;  // "two_planes 128px map 512"
};

struct Expansion {
  std::vector<Variant> variants;
  std::vector<Case> cases;
  std::vector<std::string> warnings;  // parameters no filter uses
  size_t jobCount() const { return variants.size() * cases.size(); }
};

// Throws SweepSpecError for a placeholder without values or two filters with one name.
Expansion expand(const SweepSpec& spec);

// A deterministic slice of the jobs: job j (= case * variants + variant) belongs to shard
// j mod count. "I/N" with 0 <= I < N.
struct Shard {
  int index = 0, count = 1;
  bool contains(size_t job) const { return int(job % size_t(count)) == index; }
  std::string text() const;
};
Shard parseShard(const std::string& text);  // throws std::invalid_argument with the reason

}  // namespace shadowc::sweep
