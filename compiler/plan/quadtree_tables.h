// Stackless quadtree traversal tables for adaptive kernel subdivision (vssm-yang2010 sec. 5.3,
// Algorithm 2, Fig. 5; the linear traversal of [Bun05]).
//
// A full quadtree of height H over the filter kernel: the root (level 0) is the whole kernel,
// leaves are at level H (4^H of them). Nodes are numbered in pre-order. Each node carries
//   child: index of its first child (always node + 1), -1 for a leaf;
//   next:  the node visited once this node's subtree is finished or skipped (the next sibling,
//          else the parent's next), -1 for Null (end of traversal).
// A GPU walk is then `node = descend && child >= 0 ? child : next` with no stack.
//
// Because next() does not depend on what lies below a node, the tables of height H also walk
// every smaller height h: treat nodes at level h as leaves (child = -1). vssm.glsl uses that to
// share one table between the blocker and the visibility traversals.
//
// `traversal: table` reads these tables from a read-only storage buffer the manifest carries
// (quadtreeTableBuffer); a dynamically indexed const array would be an if-ladder per read in
// lavapipe, a buffer read is one load.
#pragma once

#include <cstdint>
#include <functional>
#include <vector>

#include "manifest/manifest.h"

namespace shadowc {

struct QuadtreeNode {
  int level = 0;         // 0 = root
  int ix = 0, iy = 0;    // cell index within the 2^level x 2^level grid of that level
  double offsetX = 0.0;  // sub-kernel rectangle, in units of the root kernel
  double offsetY = 0.0;
  double size = 1.0;  // 2^-level
  int child = -1;     // first child, -1 for a leaf
  int next = -1;      // -1 = Null
};

struct QuadtreeTables {
  int height = 0;
  std::vector<QuadtreeNode> nodes;  // pre-order
};

// Number of nodes of a full quadtree of height H: (4^(H+1) - 1) / 3.
int quadtreeNodeCount(int height);

// Builds the tables; height in [0, 6] (the checker enforces 1..5, E0314; InternalError otherwise).
QuadtreeTables buildQuadtreeTables(int height);

// The manifest buffer (and shade-pass binding name) holding the tables for the shader.
inline constexpr const char* kQuadtreeTableBuffer = "quadtree_table";

// The tables as the shader reads them: one ivec4 per node in pre-order,
//   (ix | iy << 16, 2^level, child, next)   (ix, iy < 2^5 <= 2^16 for the checker's heights).
BufferDesc quadtreeTableBuffer(const QuadtreeTables& tables);

// The walk the GPU does (vssm.glsl): returns the visited node indices in order. `descend(i)` is
// Algorithm 2's "not accepted" decision (neither fully lit nor a normal sub-kernel); a leaf that
// is not accepted is resolved in place (PCF fallback) and the walk goes on with next.
// `maxLevel` < 0 means the full height; otherwise nodes at that level act as leaves.
// The walk stops after nodes.size() steps even if the tables are broken (as the GLSL loop does).
std::vector<int> walkQuadtreeTables(const QuadtreeTables& tables, const std::function<bool(int)>& descend,
                                    int maxLevel = -1);

}  // namespace shadowc
