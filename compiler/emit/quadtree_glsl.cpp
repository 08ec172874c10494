// GLSL rendering of the unrolled quadtree traversal; see quadtree_glsl.h.
#include "emit/quadtree_glsl.h"

#include <fmt/format.h>

#include "plan/internal_error.h"

namespace shadowc {

namespace {

void emitUnrolledNode(std::string& out, int height, int level, int ix, int iy, int indent, std::string_view visitFn,
                      std::string_view leafFn) {
  const std::string pad(static_cast<size_t>(indent), ' ');
  const std::string node = fmt::format("ivec3({}, {}, {})", ix, iy, 1 << level);
  if (level == height) {
    out += fmt::format("{}{}({});\n", pad, leafFn, node);
    return;
  }
  out += fmt::format("{}if ({}({})) {{\n", pad, visitFn, node);
  for (int c = 0; c < 4; ++c)
    emitUnrolledNode(out, height, level + 1, 2 * ix + (c & 1), 2 * iy + (c >> 1), indent + 2, visitFn, leafFn);
  out += fmt::format("{}}}\n", pad);
}

}  // namespace

std::string emitUnrolledQuadtreeGlsl(int height, std::string_view functionName, std::string_view visitFn,
                                     std::string_view leafFn) {
  if (height < 0 || height > 6) throw InternalError(fmt::format("quadtree height {} not in [0, 6]", height));  // E0314
  std::string out;
  out += fmt::format("// Algorithm 2 (vssm-yang2010) unrolled for height {}: pre-order, children skipped when the\n",
                     height);
  out += "// parent is accepted (fully lit or normal sub-kernel); no loop, no table.\n";
  out += fmt::format("bool {}(ivec3 node);\nvoid {}(ivec3 node);\n", visitFn, leafFn);
  out += fmt::format("void {}() {{\n", functionName);
  emitUnrolledNode(out, height, 0, 0, 0, 2, visitFn, leafFn);
  out += "}\n";
  return out;
}

}  // namespace shadowc
