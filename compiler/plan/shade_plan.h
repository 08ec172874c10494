// The shade pass's plan: FilterSpec -> every typed value that specializes
// templates/shade.comp and the includable lookup (templates/lookup/shadowc_lookup.glsl). Every
// knob the lookup reads becomes a folded constant; tables (Poisson taps, quadtree Next/Child or
// the unrolled traversal, layer splits) are generated here deterministically.
#pragma once

#include "plan/specialization.h"
#include "spec/filter_spec.h"

namespace shadowc {

// Throws std::invalid_argument for a spec the lookup cannot specialize (the checker's rules
// are meant to make that unreachable; tests/dsl/precondition_cli_test.cpp).
Specialization planShadeSpecialization(const FilterSpec& spec);

}  // namespace shadowc
