// manifest.json round trip and rejection of manifests this runtime must not execute.
#include <gtest/gtest.h>

#include "manifest/manifest.h"
#include "plan/planner.h"
#include "plan/test_specs.h"

namespace shadowc {
namespace {

Manifest planned(const FilterSpec& spec) {
  Manifest m = planPasses(spec).manifest;
  m.compilerVersion = "test";
  m.spec = {{"name", spec.name}};
  m.shade.glsl = spec.name + "_lookup.glsl";
  m.shade.function = "shadowc_visibility";
  m.shade.signature = "float shadowc_visibility(vec3 worldPos, vec3 worldNormal)";
  m.shade.bindings = {{0, "frame", Access::Uniform, -1}, {4, "shadow_depth", Access::Sampled, -1}};
  m.contentHash = "xxh3-128:00000000000000000000000000000000";
  return m;
}

TEST(ManifestJson, RoundTripIsExactForEveryTechniqueFamily) {
  FilterSpec lloyd = test::layeredEvsmSpec();
  lloyd.moments.split = SplitPlacement::Lloyd;
  for (const FilterSpec& spec :
       {test::pcfSpec(), test::vssmInt32Spec(), test::layeredEvsmSpec(), test::blurMipSpec(), lloyd}) {
    const nlohmann::ordered_json j = toJson(planned(spec));
    const nlohmann::ordered_json back = toJson(manifestFromJson(nlohmann::json::parse(j.dump())));
    EXPECT_EQ(j.dump(2), back.dump(2)) << spec.name;
  }
}

TEST(ManifestJson, WrongFormatVersionIsRejectedWithTheReason) {
  nlohmann::json j = toJson(planned(test::vssmInt32Spec()));
  j["format_version"] = kManifestFormatVersion + 1;
  try {
    manifestFromJson(j);
    FAIL() << "accepted a manifest of another format version";
  } catch (const ManifestError& e) {
    const std::string msg = e.what();
    EXPECT_NE(msg.find("format version " + std::to_string(kManifestFormatVersion + 1)), std::string::npos) << msg;
    EXPECT_NE(msg.find("recompile"), std::string::npos) << msg;
  }
}

TEST(ManifestJson, BindingOfAnUnknownImageIsRejectedNamingPassAndImage) {
  nlohmann::json j = toJson(planned(test::vssmInt32Spec()));
  j["passes"][1]["bindings"][0]["image"] = "no_such_image";
  try {
    manifestFromJson(j);
    FAIL() << "accepted a binding of an undeclared image";
  } catch (const ManifestError& e) {
    const std::string msg = e.what();
    EXPECT_NE(msg.find("no_such_image"), std::string::npos) << msg;
    EXPECT_NE(msg.find(j["passes"][1]["name"].get<std::string>()), std::string::npos) << msg;
  }
}

// Sibling: the untouched manifest is accepted, so the two rejections above are about the edit.
TEST(ManifestJson, TheUneditedManifestIsAccepted) {
  EXPECT_NO_THROW(manifestFromJson(toJson(planned(test::vssmInt32Spec()))));
}

TEST(ManifestJson, MissingFieldIsNamed) {
  nlohmann::json j = toJson(planned(test::pcfSpec()));
  j.erase("images");
  try {
    manifestFromJson(j);
    FAIL();
  } catch (const ManifestError& e) {
    EXPECT_NE(std::string(e.what()).find("'images'"), std::string::npos) << e.what();
  }
}

// A number that does not fit the field is one clear error, never a cast out of range
// (fuzz_manifest found a 49-digit "shift"; tests/fuzz/corpus/manifest/regression_shift_out_of_range.json).
TEST(ManifestJson, ANumberThatDoesNotFitItsFieldIsOneClearError) {
  nlohmann::json j = toJson(planned(test::pcfSpec()));
  ASSERT_TRUE(j["images"][0]["size"].contains("shift"));
  const std::pair<nlohmann::json, const char*> cases[] = {
      {nlohmann::json(uint64_t(1) << 40), "'shift' is out of range"},
      {nlohmann::json(-(int64_t(1) << 40)), "'shift' is out of range"},
      {nlohmann::json(4.4e48), "'shift' has the wrong type"},  // a float where an integer belongs
      {nlohmann::json(2.0), "'shift' has the wrong type"},
  };
  for (const auto& [bad, message] : cases) {
    j["images"][0]["size"]["shift"] = bad;
    try {
      manifestFromJson(j);
      FAIL() << bad.dump();
    } catch (const ManifestError& e) {
      EXPECT_NE(std::string(e.what()).find(message), std::string::npos) << bad.dump() << ": " << e.what();
    }
  }
  j["images"][0]["size"]["shift"] = 1;  // the sibling: an integer in range is read
  EXPECT_NO_THROW(manifestFromJson(j));
}

// The same for an array of integers (fuzz_manifest found a huge float in "local_size";
// tests/fuzz/corpus/manifest/regression_local_size_float.json).
TEST(ManifestJson, ALocalSizeThatIsNotThreeFittingIntegersIsOneClearError) {
  nlohmann::json j = toJson(planned(test::pcfSpec()));
  ASSERT_TRUE(j["passes"][0].contains("local_size"));
  const std::pair<nlohmann::json, const char*> cases[] = {
      {nlohmann::json::array({8, 4.4e48, 1}), "'local_size' has the wrong type (an integer"},
      {nlohmann::json::array({8, uint64_t(1) << 40, 1}), "'local_size' is out of range"},
      {nlohmann::json::array({8, -1, 1}), "'local_size' is out of range"},
      {nlohmann::json::array({8, 8}), "'local_size' has the wrong type (an array of 3 integers"},
      {nlohmann::json(8), "'local_size' has the wrong type (an array of 3 integers"},
  };
  for (const auto& [bad, message] : cases) {
    j["passes"][0]["local_size"] = bad;
    try {
      manifestFromJson(j);
      FAIL() << bad.dump();
    } catch (const ManifestError& e) {
      EXPECT_NE(std::string(e.what()).find(message), std::string::npos) << bad.dump() << ": " << e.what();
    }
  }
  j["passes"][0]["local_size"] = nlohmann::json::array({8, 8, 1});  // the sibling: three integers are read
  EXPECT_NO_THROW(manifestFromJson(j));
}

}  // namespace
}  // namespace shadowc
