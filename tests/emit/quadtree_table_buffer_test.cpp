// `traversal: table` reads Algorithm 2's Next/Child tables (vssm-yang2010 sec. 5.3, Fig. 5) from a
// read-only storage buffer the manifest declares and carries (docs/manifest.md "Buffers"): the
// SPIR-V has the block, the manifest its values (the planner's tables), and the lookup lists it.
// Sibling: `traversal: computed` has neither.
#include <gtest/gtest.h>

#include <algorithm>
#include <cstring>
#include <nlohmann/json.hpp>
#include <regex>
#include <string>
#include <vector>

#include "backend/spirv_backend.h"
#include "driver/driver.h"
#include "plan/quadtree_tables.h"

namespace shadowc {
namespace {

driver::Result compileVssm(const std::string& kernel, const std::string& blocker = "moments") {
  const std::string text = "filter qt {\n  moments linear\n  storage sat(int32)\n  blocker " + blocker + "\n  kernel " +
                           kernel + "\n  fallback pcf(2x2)\n}\n";
  return driver::compileSource(text, "qt.shadow");
}

std::string disassembly(const driver::Result& r, const std::string& file) {
  const std::string* bytes = r.artifact ? r.artifact->file(file) : nullptr;
  if (!bytes || bytes->size() % 4) return "missing " + file;
  std::vector<uint32_t> words(bytes->size() / 4);
  std::memcpy(words.data(), bytes->data(), bytes->size());
  return disassembleSpirv(words);
}

nlohmann::json manifestJson(const driver::Result& r) {
  const std::string* text = r.artifact ? r.artifact->file("manifest.json") : nullptr;
  return text ? nlohmann::json::parse(*text) : nlohmann::json();
}

// The id of the variable decorated with `binding` in set 0, as `%name` of the disassembly.
std::string variableAt(const std::string& dis, int binding) {
  std::smatch m;
  const std::regex re("OpDecorate (%[A-Za-z0-9_]+) Binding " + std::to_string(binding) + "\n");
  return std::regex_search(dis, m, re) ? m[1].str() : "";
}

TEST(QuadtreeTableBuffer, TheShadeSpirvDeclaresAReadOnlyStorageBufferAtBinding10) {
  const driver::Result r = compileVssm("quadtree(height: 3, traversal: table)");
  ASSERT_TRUE(r.ok) << r.log;
  const std::string dis = disassembly(r, "shade.spv");
  const std::string var = variableAt(dis, 10);
  ASSERT_FALSE(var.empty()) << "no binding 10 in shade.spv";
  EXPECT_TRUE(std::regex_search(dis, std::regex(var + " = OpVariable %[A-Za-z0-9_]+ StorageBuffer")))
      << "binding 10 is not a storage buffer";
  EXPECT_TRUE(std::regex_search(dis, std::regex("OpMemberDecorate %[A-Za-z0-9_]+ 0 NonWritable")))
      << "the table block is not readonly";
  EXPECT_NE(dis.find("OpDecorate %_runtimearr_v4int ArrayStride 16"), std::string::npos);  // ivec4[]
}

TEST(QuadtreeTableBuffer, TheManifestCarriesThePlannersTablesAndBindsThem) {
  const driver::Result r = compileVssm("quadtree(height: 3, traversal: table)");
  ASSERT_TRUE(r.ok) << r.log;
  const nlohmann::json m = manifestJson(r);
  ASSERT_TRUE(m.contains("buffers")) << m.dump().substr(0, 300);
  ASSERT_EQ(m["buffers"].size(), 1u);
  const nlohmann::json& b = m["buffers"][0];
  EXPECT_EQ(b["name"], kQuadtreeTableBuffer);
  EXPECT_EQ(b["components"], 4);
  EXPECT_EQ(b["values"].get<std::vector<int32_t>>(), quadtreeTableBuffer(buildQuadtreeTables(3)).values);
  EXPECT_EQ(b["values"].size(), 4u * 85);  // (4^4 - 1) / 3 nodes
  const nlohmann::json binding = {
      {"binding", 10}, {"image", kQuadtreeTableBuffer}, {"access", "storage_buffer_read"}, {"level", -1}};
  const nlohmann::json& shade = m["passes"].back();
  ASSERT_EQ(shade["name"], "shade");
  EXPECT_NE(std::find(shade["bindings"].begin(), shade["bindings"].end(), binding), shade["bindings"].end());
  // The includable lookup declares it too, so an engine binds it (manifest "shade").
  EXPECT_NE(std::find(m["shade"]["bindings"].begin(), m["shade"]["bindings"].end(), binding),
            m["shade"]["bindings"].end());
  const std::string* lookup = r.artifact->file("qt_lookup.glsl");
  ASSERT_NE(lookup, nullptr);
  EXPECT_NE(lookup->find("binding = 10, std430)readonly buffer shadowc_QuadtreeTable"), std::string::npos);
}

// One table serves both walks: the taller tree's (a blocker of height 5 over a kernel of 1).
TEST(QuadtreeTableBuffer, TheTallerOfTheBlockerAndKernelTreesSizesTheTable) {
  const driver::Result r = compileVssm("quadtree(height: 1, traversal: table)", "moments(quadtree(height: 5))");
  ASSERT_TRUE(r.ok) << r.log;
  ASSERT_EQ(r.artifact->manifest.buffers.size(), 1u);
  EXPECT_EQ(r.artifact->manifest.buffers[0].values, quadtreeTableBuffer(buildQuadtreeTables(5)).values);
}

TEST(QuadtreeTableBuffer, TheComputedWalkHasNoBuffer) {
  const driver::Result r = compileVssm("quadtree(height: 3, traversal: computed)");
  ASSERT_TRUE(r.ok) << r.log;
  const std::string dis = disassembly(r, "shade.spv");
  EXPECT_EQ(variableAt(dis, 10), "");
  EXPECT_EQ(dis.find("StorageBuffer"), std::string::npos);
  const nlohmann::json m = manifestJson(r);
  EXPECT_FALSE(m.contains("buffers"));
  EXPECT_EQ(m.dump().find("storage_buffer_read"), std::string::npos);
}

}  // namespace
}  // namespace shadowc
