// The shade pass's plan: FilterSpec -> every typed value that specializes
// templates/shade.comp and the includable lookup (templates/lookup/shadowc_lookup.glsl). Every
// knob the lookup reads becomes a folded constant; tables (Poisson taps, quadtree Next/Child or
// the unrolled traversal, layer splits) are generated here deterministically.
#pragma once

#include <cstdint>

#include "plan/specialization.h"
#include "spec/filter_spec.h"

namespace shadowc {

// The height of the Next/Child tables that `traversal: table` reads (the taller of the kernel's
// and the blocker's quadtree; plan/quadtree_tables.h), or 0 when the shade pass reads none. The
// planner puts them in the manifest's buffer kQuadtreeTableBuffer, bound at kQuadtreeTableBinding.
int quadtreeTableHeight(const FilterSpec& spec);
inline constexpr uint32_t kQuadtreeTableBinding = 10;  // after the generic shader's block at 9

// Throws std::invalid_argument for a spec the lookup cannot specialize (the checker's rules
// are meant to make that unreachable; tests/dsl/precondition_cli_test.cpp).
Specialization planShadeSpecialization(const FilterSpec& spec);

}  // namespace shadowc
