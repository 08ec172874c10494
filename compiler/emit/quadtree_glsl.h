// GLSL for the unrolled quadtree traversal (vssm-yang2010 sec. 5.3, Algorithm 2, `traversal:
// unrolled`). The table walk reads the planner's tables from a buffer (plan/quadtree_tables.h),
// the computed walk needs none: both are loops in templates/lookup/vssm.glsl.
#pragma once

#include <string>
#include <string_view>

namespace shadowc {

// Straight-line GLSL equivalent to the table walk (no loop, no table): a function
//   void <functionName>() { if (<visitFn>(ivec3(0, 0, 1))) { ... } }
// where `bool visitFn(ivec3 node)` classifies an internal node (true = descend) and
// `void leafFn(ivec3 node)` resolves a leaf completely. Nodes are ivec3(ix, iy, 2^level).
std::string emitUnrolledQuadtreeGlsl(int height, std::string_view functionName, std::string_view visitFn,
                                     std::string_view leafFn);

}  // namespace shadowc
