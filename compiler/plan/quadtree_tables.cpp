// Stackless quadtree tables (vssm-yang2010 Algorithm 2 / Fig. 5, [Bun05]); see quadtree_tables.h.
#include "plan/quadtree_tables.h"

#include <fmt/format.h>

#include "plan/internal_error.h"

namespace shadowc {

int quadtreeNodeCount(int height) {
  int count = 0;
  for (int level = 0, perLevel = 1; level <= height; ++level, perLevel *= 4) count += perLevel;
  return count;
}

namespace {

// Pre-order build: returns the index of the node created for (level, ix, iy); `next` is the
// node that follows this whole subtree (the caller's next sibling or its own next).
void buildSubtree(QuadtreeTables& t, int level, int ix, int iy) {
  const int index = static_cast<int>(t.nodes.size());
  QuadtreeNode node;
  node.level = level;
  node.ix = ix;
  node.iy = iy;
  node.size = 1.0 / static_cast<double>(1 << level);
  node.offsetX = ix * node.size;
  node.offsetY = iy * node.size;
  t.nodes.push_back(node);
  if (level == t.height) return;
  t.nodes[index].child = index + 1;
  // Children in Z order: (0,0) (1,0) (0,1) (1,1), as in Fig. 5(a).
  std::vector<int> children;
  for (int c = 0; c < 4; ++c) {
    children.push_back(static_cast<int>(t.nodes.size()));
    buildSubtree(t, level + 1, 2 * ix + (c & 1), 2 * iy + (c >> 1));
  }
  for (int c = 0; c < 3; ++c) t.nodes[children[c]].next = children[c + 1];
  // The last child's next is the parent's next, filled in by linkNext below.
}

// next(last child) = next(parent); resolved top-down after the parent's own next is known.
void linkNext(QuadtreeTables& t, int index) {
  const QuadtreeNode& node = t.nodes[index];
  if (node.child < 0) return;
  int c = node.child;
  for (int k = 0; k < 4; ++k) {
    if (k == 3) t.nodes[c].next = t.nodes[index].next;
    linkNext(t, c);
    if (k < 3) c = t.nodes[c].next;
  }
}

}  // namespace

QuadtreeTables buildQuadtreeTables(int height) {
  if (height < 0 || height > 6) throw InternalError(fmt::format("quadtree height {} not in [0, 6]", height));  // E0314
  QuadtreeTables t;
  t.height = height;
  t.nodes.reserve(static_cast<size_t>(quadtreeNodeCount(height)));
  buildSubtree(t, 0, 0, 0);
  t.nodes[0].next = -1;
  linkNext(t, 0);
  return t;
}

BufferDesc quadtreeTableBuffer(const QuadtreeTables& tables) {
  BufferDesc b;
  b.name = kQuadtreeTableBuffer;
  b.components = 4;
  for (const QuadtreeNode& n : tables.nodes)
    b.values.insert(b.values.end(), {n.ix | (n.iy << 16), 1 << n.level, n.child, n.next});
  return b;
}

std::vector<int> walkQuadtreeTables(const QuadtreeTables& tables, const std::function<bool(int)>& descend,
                                    int maxLevel) {
  std::vector<int> visited;
  const int count = static_cast<int>(tables.nodes.size());
  int node = count > 0 ? 0 : -1;
  for (int step = 0; step < count && node >= 0 && node < count; ++step) {
    visited.push_back(node);
    const QuadtreeNode& n = tables.nodes[node];
    const int child = (maxLevel >= 0 && n.level >= maxLevel) ? -1 : n.child;
    node = (descend(node) && child >= 0) ? child : n.next;
  }
  return visited;
}

}  // namespace shadowc
