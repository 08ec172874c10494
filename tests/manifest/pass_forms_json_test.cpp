// manifest.json "form" / "needs" / "forms" (docs/manifest.md "Pass forms"): round trip, absent
// for passes with one form, and the errors of a malformed list.
#include <gtest/gtest.h>

#include "manifest/manifest.h"
#include "plan/planner.h"
#include "plan/test_specs.h"

namespace shadowc {
namespace {

nlohmann::json satPassJson() {
  Manifest m = planPasses(test::vssmInt32Spec()).manifest;
  m.spec = nlohmann::json::object();
  m.contentHash = "xxh3-128:00000000000000000000000000000000";
  return nlohmann::json::parse(toJson(m).dump());
}

nlohmann::json& passNamed(nlohmann::json& j, const std::string& name) {
  for (auto& p : j["passes"])
    if (p["name"] == name) return p;
  throw std::runtime_error("no pass " + name);
}

TEST(PassFormsJson, SatScansCarryBothFormsAndOtherPassesNone) {
  nlohmann::json j = satPassJson();
  const nlohmann::json& rows = passNamed(j, "sat_rows");
  EXPECT_EQ(rows["form"], "serial");
  EXPECT_EQ(rows["needs"]["device"], "cpu");
  ASSERT_EQ(rows["forms"].size(), 1u);
  EXPECT_EQ(rows["forms"][0]["form"], "parallel");
  EXPECT_EQ(rows["forms"][0]["needs"]["device"], "gpu");
  EXPECT_EQ(rows["forms"][0]["dispatch"]["mode"], "row_groups");
  EXPECT_FALSE(passNamed(j, "shade").contains("forms"));
  EXPECT_FALSE(passNamed(j, "shade").contains("form"));
  const Manifest back = manifestFromJson(j);
  const std::vector<PassForm> forms = formsOf(back.passes.front());
  ASSERT_EQ(forms.size(), 2u);
  EXPECT_EQ(forms[1].dispatch.mode, DispatchMode::RowGroups);
  EXPECT_EQ(forms[1].spirv, "sat_rows_parallel.spv");
}

void expectError(const nlohmann::json& j, const std::string& part) {
  try {
    manifestFromJson(j);
    ADD_FAILURE() << "accepted: " << part;
  } catch (const ManifestError& e) {
    EXPECT_NE(std::string(e.what()).find(part), std::string::npos) << e.what();
  }
}

TEST(PassFormsJson, MalformedFormListsAreOneClearError) {
  {
    nlohmann::json j = satPassJson();
    passNamed(j, "sat_rows")["forms"][0]["form"] = "serial";
    expectError(j, "form names must be unique");
  }
  {
    nlohmann::json j = satPassJson();
    passNamed(j, "sat_rows")["forms"][0]["needs"]["subgroup_operations"] = {"warp_magic"};
    expectError(j, "unknown subgroup operation 'warp_magic'");
  }
  {
    nlohmann::json j = satPassJson();
    passNamed(j, "sat_rows")["needs"]["device"] = "tpu";
    expectError(j, "unknown value 'tpu'");
  }
  {
    nlohmann::json j = satPassJson();
    passNamed(j, "sat_rows").erase("form");
    expectError(j, "does not name its own");
  }
  {
    nlohmann::json j = satPassJson();
    passNamed(j, "sat_rows")["forms"][0]["needs"]["subgroup_size_min"] = -1;
    expectError(j, "subgroup_size_min");
  }
}

}  // namespace
}  // namespace shadowc
