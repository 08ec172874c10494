// GLSL for the quadtree traversal (vssm-yang2010 sec. 5.3, Algorithm 2): the planner decides
// the tables (plan/quadtree_tables.h); these render them.
#pragma once

#include <string>
#include <string_view>

#include "plan/quadtree_tables.h"

namespace shadowc {

// GLSL const arrays: `const ivec3 <prefix>Node[N]` (ix, iy, 2^level), `const int <prefix>Child[N]`,
// `const int <prefix>Next[N]`; the node count macro is a planner Constant (SHADOWC_QT_NODES).
std::string emitQuadtreeTablesGlsl(const QuadtreeTables& tables, std::string_view prefix);

// Straight-line GLSL equivalent to the table walk (no loop, no table): a function
//   void <functionName>() { if (<visitFn>(ivec3(0, 0, 1))) { ... } }
// where `bool visitFn(ivec3 node)` classifies an internal node (true = descend) and
// `void leafFn(ivec3 node)` resolves a leaf completely. Nodes are ivec3(ix, iy, 2^level).
std::string emitUnrolledQuadtreeGlsl(int height, std::string_view functionName, std::string_view visitFn,
                                     std::string_view leafFn);

}  // namespace shadowc
