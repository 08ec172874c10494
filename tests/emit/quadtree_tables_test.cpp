// The stackless Next/Child tables (vssm-yang2010 Algorithm 2, Fig. 5) must visit exactly the
// nodes a recursive quadtree traversal visits, in the same order, for every pattern of
// descend/accept decisions. The reference identifies nodes by (level, ix, iy), never by table
// index, so a wrong numbering cannot hide. The unrolled GLSL is checked by interpreting it.
#include "plan/quadtree_tables.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <bit>
#include <cstdint>
#include <random>
#include <regex>
#include <sstream>
#include <string>
#include <tuple>
#include <vector>

#include "emit/quadtree_glsl.h"
#include "plan/internal_error.h"

namespace shadowc {
namespace {

using Cell = std::tuple<int, int, int>;  // level, ix, iy

// Canonical bit of a node for decision patterns: level-order index, independent of the tables.
int levelOrderIndex(int level, int ix, int iy) {
  int base = 0;
  for (int l = 0; l < level; ++l) base += 1 << (2 * l);
  return base + iy * (1 << level) + ix;
}

using Decide = std::function<bool(int level, int ix, int iy)>;

// Textbook recursive traversal: visit, and descend into the 4 children (Z order) when the node
// is not accepted and is not a leaf.
void recursiveWalk(int height, int level, int ix, int iy, const Decide& descend, std::vector<Cell>& out) {
  out.emplace_back(level, ix, iy);
  if (level == height || !descend(level, ix, iy)) return;
  for (int c = 0; c < 4; ++c) recursiveWalk(height, level + 1, 2 * ix + (c & 1), 2 * iy + (c >> 1), descend, out);
}

std::vector<Cell> tableWalk(const QuadtreeTables& t, const Decide& descend, int maxLevel = -1) {
  std::vector<Cell> out;
  for (int i : walkQuadtreeTables(
           t, [&](int n) { return descend(t.nodes[n].level, t.nodes[n].ix, t.nodes[n].iy); }, maxLevel))
    out.emplace_back(t.nodes[i].level, t.nodes[i].ix, t.nodes[i].iy);
  return out;
}

Decide fromBits(uint64_t bits) {
  return [bits](int l, int x, int y) { return ((bits >> levelOrderIndex(l, x, y)) & 1u) != 0; };
}

Decide fromRandom(std::mt19937_64& rng, int nodes, double pDescend) {
  auto bits = std::make_shared<std::vector<bool>>();
  std::bernoulli_distribution coin(pDescend);
  for (int i = 0; i < nodes; ++i) bits->push_back(coin(rng));
  return [bits](int l, int x, int y) { return (*bits)[static_cast<size_t>(levelOrderIndex(l, x, y))]; };
}

TEST(QuadtreeTables, NodeCountsAndShape) {
  EXPECT_EQ(quadtreeNodeCount(0), 1);
  EXPECT_EQ(quadtreeNodeCount(3), 85);
  for (int h = 0; h <= 4; ++h) {
    const QuadtreeTables t = buildQuadtreeTables(h);
    ASSERT_EQ(static_cast<int>(t.nodes.size()), quadtreeNodeCount(h));
    int leaves = 0;
    for (size_t i = 0; i < t.nodes.size(); ++i) {
      const QuadtreeNode& n = t.nodes[i];
      EXPECT_DOUBLE_EQ(n.size, 1.0 / (1 << n.level));
      EXPECT_DOUBLE_EQ(n.offsetX, n.ix * n.size);
      EXPECT_DOUBLE_EQ(n.offsetY, n.iy * n.size);
      if (n.level == h) {
        ++leaves;
        EXPECT_EQ(n.child, -1);
      } else {
        EXPECT_EQ(n.child, static_cast<int>(i) + 1);  // pre-order: first child follows
      }
      EXPECT_TRUE(n.next == -1 || n.next > static_cast<int>(i)) << "next must move forward";
    }
    EXPECT_EQ(leaves, 1 << (2 * h));
    EXPECT_EQ(t.nodes[0].next, -1);
  }
  EXPECT_THROW(buildQuadtreeTables(7), InternalError);
}

// Exhaustive over every behaviour. A Next/Child walk is stackless: where it goes from a node is a
// function of that node and the one answer asked there, nothing earlier. Every pattern of the
// interior nodes' bits (the first quadtreeNodeCount(h - 1) in level order) gives every set of
// visited nodes, and with the leaves all answering "no" and all "yes" each visited leaf is asked
// both ways under each of them: every (node, answer) step the walk can take, which is what the
// 2^21 patterns over all nodes of height 2 covered, in 2^5 x 2 walks.
TEST(QuadtreeTables, ExhaustiveDecisionPatternsMatchRecursionForHeights1And2) {
  for (int h = 1; h <= 2; ++h) {
    const QuadtreeTables t = buildQuadtreeTables(h);
    const int interior = quadtreeNodeCount(h - 1), nodes = quadtreeNodeCount(h);  // 1 of 5, 5 of 21
    const uint64_t leaves = ((uint64_t{1} << nodes) - 1) & ~((uint64_t{1} << interior) - 1);
    uint64_t checked = 0;
    for (uint64_t inner = 0; inner < (uint64_t{1} << interior); ++inner)
      for (const uint64_t bits : {inner, inner | leaves}) {
        const Decide d = fromBits(bits);
        std::vector<Cell> expected;
        recursiveWalk(h, 0, 0, 0, d, expected);
        if (tableWalk(t, d) != expected) {
          ADD_FAILURE() << "height " << h << " pattern " << bits << ": table walk differs";
          return;
        }
        ++checked;
      }
    EXPECT_EQ(checked, uint64_t{2} << interior);
  }
}

TEST(QuadtreeTables, RandomDecisionPatternsMatchRecursionForHeights3And4) {
  std::mt19937_64 rng(20100101);
  for (int h = 3; h <= 4; ++h) {
    const QuadtreeTables t = buildQuadtreeTables(h);
    for (double p : {0.1, 0.5, 0.9, 1.0}) {
      for (int trial = 0; trial < 2000; ++trial) {
        const Decide d = fromRandom(rng, quadtreeNodeCount(h), p);
        std::vector<Cell> expected;
        recursiveWalk(h, 0, 0, 0, d, expected);
        ASSERT_EQ(tableWalk(t, d), expected) << "height " << h << " p " << p << " trial " << trial;
      }
    }
  }
}

TEST(QuadtreeTables, TallerTablesWalkShorterTreesWithALevelLimit) {
  // vssm.glsl shares one table between the blocker (height hb) and kernel (height hk) walks.
  std::mt19937_64 rng(7);
  const QuadtreeTables t = buildQuadtreeTables(4);
  for (int h = 1; h <= 3; ++h)
    for (int trial = 0; trial < 500; ++trial) {
      const Decide d = fromRandom(rng, quadtreeNodeCount(4), 0.7);
      std::vector<Cell> expected;
      recursiveWalk(h, 0, 0, 0, d, expected);
      ASSERT_EQ(tableWalk(t, d, h), expected) << "height " << h;
    }
}

TEST(QuadtreeTables, BrokenNextPointerIsDetectedByTheSameComparison) {
  // Sibling of the tests above: proves the comparison can fail. Point one node's Next at the
  // node after its real target (skips a subtree); some decision pattern must expose it.
  for (int h = 2; h <= 3; ++h) {
    QuadtreeTables broken = buildQuadtreeTables(h);
    QuadtreeNode& victim = broken.nodes[2];  // level-2 node (or a leaf for h = 2)
    ASSERT_GE(victim.next, 0);
    victim.next += 1;
    std::mt19937_64 rng(99);
    bool detected = false;
    for (int trial = 0; trial < 200 && !detected; ++trial) {
      const Decide d = fromRandom(rng, quadtreeNodeCount(h), 0.8);
      std::vector<Cell> expected;
      recursiveWalk(h, 0, 0, 0, d, expected);
      detected = tableWalk(broken, d) != expected;
    }
    EXPECT_TRUE(detected) << "height " << h;
  }
  // A broken Child pointer too.
  QuadtreeTables broken = buildQuadtreeTables(2);
  broken.nodes[1].child = 7;
  std::vector<Cell> expected;
  recursiveWalk(2, 0, 0, 0, fromBits(~uint64_t{0}), expected);
  EXPECT_NE(tableWalk(broken, fromBits(~uint64_t{0})), expected);
}

// Interprets the unrolled GLSL: `if (visit(ivec3(x, y, den))) {`, `leaf(ivec3(x, y, den));`, `}`.
std::vector<Cell> interpretUnrolled(const std::string& code, const Decide& descend) {
  std::vector<Cell> out;
  std::istringstream in(code);
  std::string line;
  const std::regex visitRe(R"(if \(visit\(ivec3\((\d+), (\d+), (\d+)\)\)\) \{)");
  const std::regex leafRe(R"(leaf\(ivec3\((\d+), (\d+), (\d+)\)\);)");
  int skipDepth = 0;  // > 0 while inside an if whose condition was false
  bool inBody = false;
  auto levelOf = [](int den) {
    int l = 0;
    while ((1 << l) < den) ++l;
    return l;
  };
  while (std::getline(in, line)) {
    if (line.rfind("void walk()", 0) == 0) {
      inBody = true;
      continue;
    }
    if (!inBody) continue;
    if (line == "}") break;  // end of function
    std::smatch m;
    if (std::regex_search(line, m, visitRe)) {
      if (skipDepth > 0) {
        ++skipDepth;
        continue;
      }
      const int l = levelOf(std::stoi(m[3])), x = std::stoi(m[1]), y = std::stoi(m[2]);
      out.emplace_back(l, x, y);
      if (!descend(l, x, y)) skipDepth = 1;
    } else if (std::regex_search(line, m, leafRe)) {
      if (skipDepth == 0) out.emplace_back(levelOf(std::stoi(m[3])), std::stoi(m[1]), std::stoi(m[2]));
    } else if (line.find('}') != std::string::npos) {
      if (skipDepth > 0) --skipDepth;
    } else {
      ADD_FAILURE() << "unexpected line in unrolled code: " << line;
    }
  }
  return out;
}

TEST(QuadtreeTables, UnrolledCodeIsStraightLineAndEquivalentToTheWalk) {
  std::mt19937_64 rng(3);
  for (int h = 1; h <= 4; ++h) {
    const std::string code = emitUnrolledQuadtreeGlsl(h, "walk", "visit", "leaf");
    std::string codeOnly;  // without // comments
    std::istringstream lines(code);
    for (std::string l; std::getline(lines, l);) codeOnly += l.substr(0, l.find("//")) + "\n";
    EXPECT_EQ(codeOnly.find("for"), std::string::npos);
    EXPECT_EQ(codeOnly.find("while"), std::string::npos);
    EXPECT_EQ(codeOnly.find("Next"), std::string::npos);
    EXPECT_NE(codeOnly.find("if (visit("), std::string::npos);
    const QuadtreeTables t = buildQuadtreeTables(h);
    for (int trial = 0; trial < 300; ++trial) {
      const Decide d = fromRandom(rng, quadtreeNodeCount(h), trial % 2 ? 0.5 : 0.9);
      ASSERT_EQ(interpretUnrolled(code, d), tableWalk(t, d)) << "height " << h;
    }
  }
  // The checker bounds the height (E0314); past it, a height out of range is a shadowc bug.
  EXPECT_THROW(emitUnrolledQuadtreeGlsl(7, "walk", "visit", "leaf"), InternalError);
}

// The manifest buffer `traversal: table` reads: one (ix | iy << 16, 2^level, child, next) per
// node, in the tables' order, so that the shader's walk is walkQuadtreeTables.
TEST(QuadtreeTables, BufferHoldsEveryNodeAsTheShaderReadsIt) {
  for (int h = 1; h <= 5; ++h) {
    const QuadtreeTables t = buildQuadtreeTables(h);
    const BufferDesc b = quadtreeTableBuffer(t);
    EXPECT_EQ(b.name, kQuadtreeTableBuffer);
    ASSERT_EQ(b.components, 4u);
    ASSERT_EQ(b.values.size(), 4 * t.nodes.size()) << "height " << h;
    for (size_t i = 0; i < t.nodes.size(); ++i) {
      const QuadtreeNode& q = t.nodes[i];
      const int32_t* v = &b.values[4 * i];
      // The shader's unpacking (vssm.glsl shadowc_qtTableWalk): ix = x & 0xffff, iy = x >> 16.
      EXPECT_EQ(std::make_tuple(v[0] & 0xffff, v[0] >> 16, v[1], v[2], v[3]),
                std::make_tuple(q.ix, q.iy, 1 << q.level, q.child, q.next))
          << "height " << h << " node " << i;
    }
  }
  // Height 2 in full, as docs/manifest.md "Buffers" prints the start of it.
  const BufferDesc b = quadtreeTableBuffer(buildQuadtreeTables(2));
  EXPECT_EQ(std::vector<int32_t>(b.values.begin(), b.values.begin() + 16),
            (std::vector<int32_t>{0, 1, 1, -1, 0, 2, 2, 6, 0, 4, -1, 3, 1, 4, -1, 4}));
}

// `traversal: computed` (templates/lookup/vssm.glsl) derives Next from the node (shadowc_qtNextNode)
// instead of reading the table; this is that function line by line, checked against the Next
// table of every node.
TEST(QuadtreeTables, ComputedNextEqualsTheNextTable) {
  struct N {
    int x, y, z;  // ix, iy, 2^level; z = 0 is Null
  };
  auto nextNode = [](N n) {
    const int up =
        std::min(std::countr_one(static_cast<unsigned>(n.x & n.y)), std::countr_zero(static_cast<unsigned>(n.z)));
    n = {n.x >> up, n.y >> up, n.z >> up};
    if (n.z <= 1) return N{0, 0, 0};
    const int c = (n.x & 1) + 2 * (n.y & 1) + 1;
    return N{(n.x & ~1) | (c & 1), (n.y & ~1) | (c >> 1), n.z};
  };
  for (int h = 1; h <= 5; ++h) {
    const QuadtreeTables t = buildQuadtreeTables(h);
    for (size_t i = 0; i < t.nodes.size(); ++i) {
      const QuadtreeNode& q = t.nodes[i];
      const N got = nextNode({q.ix, q.iy, 1 << q.level});
      if (q.next < 0) {
        EXPECT_EQ(got.z, 0) << "height " << h << " node " << i;
        continue;
      }
      const QuadtreeNode& want = t.nodes[static_cast<size_t>(q.next)];
      EXPECT_EQ(std::make_tuple(got.x, got.y, got.z), std::make_tuple(want.ix, want.iy, 1 << want.level))
          << "height " << h << " node " << i;
    }
  }
}

}  // namespace
}  // namespace shadowc
