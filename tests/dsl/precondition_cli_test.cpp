// The checker alone owns validity: every precondition the emitter, planner, lookup
// specialization or quadtree table builder enforced is a checker rule with a code and a caret.
// Each former precondition runs through the built binary's `shadowc check` and must fail there
// with its code at its line:column; its valid neighbour must pass `check` and `compile`.
#include <gtest/gtest.h>

#include <fstream>

#include "support/test_support.h"

namespace {

struct Precondition {
  const char* name;
  const char* body;       // lines of `filter f { ... }`; the first body line is line 2
  const char* code;       // expected diagnostic code
  int line, column;       // where the caret points
  const char* neighbour;  // the nearest valid body (passes check and compile)
};

const Precondition kPreconditions[] = {
    // lookup specialization "quadtree height must be 1..5" and the table builder's [0, 6].
    {"kernel_quadtree_height_0", "moments linear\nstorage sat(int32)\nblocker moments\nkernel quadtree(height: 0)",
     "E0314", 5, 25, "moments linear\nstorage sat(int32)\nblocker moments\nkernel quadtree(height: 1)"},
    {"kernel_quadtree_height_6", "moments linear\nstorage sat(int32)\nblocker moments\nkernel quadtree(height: 6)",
     "E0314", 5, 25, "moments linear\nstorage sat(int32)\nblocker moments\nkernel quadtree(height: 5)"},
    {"blocker_quadtree_height_0",
     "moments linear\nstorage sat(int32)\nblocker moments(quadtree(height: 0))\nkernel uniform(4)", "E0314", 4, 34,
     "moments linear\nstorage sat(int32)\nblocker moments(quadtree(height: 1))\nkernel uniform(4)"},
    {"blocker_quadtree_height_6",
     "moments linear\nstorage sat(int32)\nblocker moments(quadtree(height: 6))\nkernel uniform(4)", "E0314", 4, 34,
     "moments linear\nstorage sat(int32)\nblocker moments(quadtree(height: 5))\nkernel uniform(4)"},
    // "the VSSM blocker estimate (eq. 4) needs the linear warp"
    {"vssm_exp_warp", "moments exp(exponent: 20)\nstorage sat(fp32_centered)\nblocker moments\nkernel uniform(4)",
     "E0417", 2, 9, "moments linear\nstorage sat(fp32_centered)\nblocker moments\nkernel uniform(4)"},
    {"vssm_evsm2_warp", "moments evsm2(exponent: 20)\nstorage sat(fp32_centered)\nblocker moments\nkernel uniform(4)",
     "E0417", 2, 9, "moments linear\nstorage sat(fp32_centered)\nblocker moments\nkernel uniform(4)"},
    {"vssm_msm_warp", "moments msm\nstorage sat(int32)\nblocker moments\nkernel uniform(4)", "E0417", 2, 9,
     "moments linear\nstorage sat(int32)\nblocker moments\nkernel uniform(4)"},
    // Moment shadow maps: what the storage must give four moments (Peters & Klein 2015).
    {"msm_layers", "moments msm(layers: 2)", "E0440", 2, 21, "moments msm(layers: 1)"},
    {"msm_fp16", "moments msm\nstorage fp16", "E0441", 3, 9, "moments msm\nstorage unorm16"},
    {"msm_fp32_sat", "moments msm\nstorage sat(fp32_centered)\nkernel fixed(5)", "E0442", 3, 9,
     "moments msm\nstorage sat(int32)\nkernel fixed(5)"},
    // "the VSSM path works on a single (unlayered) moments map"
    {"vssm_layers", "moments linear(layers: 2)\nstorage sat(int32)\nblocker moments\nkernel uniform(4)", "E0418", 2, 24,
     "moments linear(layers: 1)\nstorage sat(int32)\nblocker moments\nkernel uniform(4)"},
    // "the moments blocker estimate needs a moments representation"
    {"moment_blocker_on_depth", "depth\nblocker moments", "E0403", 3, 9,
     "moments linear\nstorage sat(int32)\nblocker moments"},
    // "power_cdf stores min/max, which a summed-area table cannot sum"
    {"power_cdf_sat", "moments power_cdf\nstorage sat(fp32_centered)", "E0411", 3, 9,
     "moments power_cdf\nstorage fp32"},
    // "layers must be >= 1"
    {"zero_layers", "moments linear(layers: 0)", "E0304", 2, 24, "moments linear(layers: 1)"},
    // "non-finite constant in filter spec": no number the lexer accepts is infinite.
    {"non_finite_constant", "light area(1e999)", "E0104", 2, 12, "light area(1e3)"},
};

std::string writeFilter(const std::string& dir, const std::string& name, const std::string& body) {
  const std::string file = dir + "/" + name + ".shadow";
  std::ofstream(file) << "filter f {\n" << body << "\n}\n";
  return file;
}

class FormerPrecondition : public ::testing::TestWithParam<Precondition> {};

TEST_P(FormerPrecondition, CheckRejectsWithCodeAtLineColumn) {
  const Precondition& p = GetParam();
  const std::string dir = shadowc::test::freshTempDir(std::string("pre_") + p.name).string();
  const std::string file = writeFilter(dir, p.name, p.body);
  const shadowc::test::CliResult r = shadowc::test::runShadowc("check " + file);
  EXPECT_EQ(r.code, 1) << r.out << r.err;
  const std::string where = file + ":" + std::to_string(p.line) + ":" + std::to_string(p.column) + ": error: ";
  const size_t at = r.err.find(where);
  ASSERT_NE(at, std::string::npos) << "expected '" << where << "...[" << p.code << "]' in:\n" << r.err;
  const std::string first = r.err.substr(at, r.err.find('\n', at) - at);
  EXPECT_NE(first.find(std::string("[") + p.code + "]"), std::string::npos) << first;
  // The first error is the precondition itself, not a follow-on.
  EXPECT_EQ(r.err.find(": error: "), at + where.size() - std::string(": error: ").size()) << r.err;
}

// Sibling: the nearest valid description passes `check` and compiles (so the rule is not
// stricter than the emitter, and the boundary values 1 and 5 really emit).
TEST_P(FormerPrecondition, ValidNeighbourChecksAndCompiles) {
  const Precondition& p = GetParam();
  const std::string dir = shadowc::test::freshTempDir(std::string("ok_") + p.name).string();
  const std::string file = writeFilter(dir, p.name, p.neighbour);
  const shadowc::test::CliResult c = shadowc::test::runShadowc("check " + file);
  EXPECT_EQ(c.code, 0) << c.out << c.err;
  EXPECT_EQ(c.err.find("error:"), std::string::npos) << c.err;
  const shadowc::test::CliResult k = shadowc::test::runShadowc("compile " + file + " -o " + dir + "/out");
  EXPECT_EQ(k.code, 0) << k.out << k.err;
}

INSTANTIATE_TEST_SUITE_P(CheckCli, FormerPrecondition, ::testing::ValuesIn(kPreconditions),
                         [](const auto& info) { return std::string(info.param.name); });

}  // namespace
