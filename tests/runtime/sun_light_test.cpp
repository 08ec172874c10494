// A sun in the scene format and the Embree reference: the JSON form loads and is
// checked, the reference's directions lie on the sun's cone with equal solid angle per stratum,
// and its visibility on sun_two_planes matches the closed form of the cosine-weighted fraction of
// the cone that passes a half-plane edge (docs/scenes.md, tests/gpu/sun_closed_form_test.cpp).
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>

#include "runtime/reference/embree_reference.h"
#include "runtime/scene/scene.h"

namespace shadowc::rt {
namespace {

std::string errorOf(const std::string& light) {
  try {
    parseScene(R"({"camera": {"eye": [0, 3, 3], "target": [0, 0, 0]}, "light": )" + light +
                   R"(, "objects": [{"type": "plane", "size": 4}]})",
               "t.json", ".");
  } catch (const SceneError& e) {
    return e.what();
  }
  return "(no error)";
}

// V(x) of sun_two_planes: edge at height h over x < 0, sun of angular diameter a straight down.
double exactSunVisibility(double x, double h, double angleDegrees) {
  const double s = std::sin(0.5 * angleDegrees * M_PI / 180.0);
  constexpr int kSteps = 4000;
  double sum = 0;
  for (int i = 0; i < kSteps; ++i) {
    const double rho = s * (i + 0.5) / kSteps;
    sum += 2 * rho * std::acos(std::clamp(-x * std::sqrt(1 - rho * rho) / (h * rho), -1.0, 1.0));
  }
  return sum * (s / kSteps) / (M_PI * s * s);
}

TEST(SunLight, JsonFormLoadsAndIsChecked) {
  const Scene s = parseScene(R"({"camera": {"eye": [0, 3, 3], "target": [0, 0, 0]},
    "light": {"type": "sun", "direction": [0, -2, 0], "angle": 0.53},
    "objects": [{"type": "plane", "size": 4}, {"type": "box", "size": 1, "transform": {"translate": [0, 5, 0]}}]})",
                             "t.json", ".");
  EXPECT_EQ(s.light.type, LightType::Sun);
  EXPECT_FLOAT_EQ(s.light.angleDegrees, 0.53f);
  EXPECT_FLOAT_EQ(s.light.direction.y, -1.0f);  // normalized
  EXPECT_NE(errorOf(R"({"type": "sun", "direction": [0, -1, 0], "angle": 50})")
                .find("light.angle: expected an angular diameter"),
            std::string::npos);
  EXPECT_NE(errorOf(R"({"type": "sun", "direction": [0, -1, 0]})").find("light.angle: missing required field"),
            std::string::npos)
      << errorOf(R"({"type": "sun", "direction": [0, -1, 0]})");
  EXPECT_NE(errorOf(R"({"type": "sun", "direction": [0, -1, 0], "angle": 1, "size": 1})").find("size"),
            std::string::npos);
  EXPECT_NE(errorOf(R"({"type": "sunn", "direction": [0, -1, 0], "angle": 1})").find("did you mean 'sun'"),
            std::string::npos);
  // The spot form is unchanged, and its hash does not move with the new fields.
  const Scene spot = loadScene("two_planes");
  EXPECT_EQ(spot.light.type, LightType::Spot);
  Scene asSun = spot;
  asSun.light.type = LightType::Sun;
  asSun.light.angleDegrees = 1;
  EXPECT_NE(asSun.contentHash(), spot.contentHash());
}

TEST(SunLight, SampleDirectionsCoverTheConeWithEqualSolidAngle) {
  Scene s = loadScene("sun_outdoor");
  const glm::vec3 toSun = -s.light.direction;
  const double cosMax = std::cos(0.5 * s.light.angleDegrees * M_PI / 180);
  constexpr int n = 64;  // strata centres: the half-solid-angle cap holds 46^2 of 64^2 (0.517)
  double inner = 0, maxAngle = 0;
  for (int j = 0; j < n; ++j)
    for (int i = 0; i < n; ++i) {
      const glm::vec3 d = sunSampleDirection(s.light, i, j, n, 0.5f, 0.5f);
      EXPECT_NEAR(glm::length(d), 1.0f, 1e-6f);
      const double c = glm::dot(glm::dvec3(d), glm::dvec3(toSun));
      EXPECT_GE(c, cosMax - 1e-7);
      maxAngle = std::max(maxAngle, std::acos(std::min(c, 1.0)));
      // Equal solid angle: the half-angle cap of (1 - cos) halved holds half of the strata.
      inner += (1 - c) < 0.5 * (1 - cosMax);
    }
  EXPECT_GT(maxAngle, 0.9 * 0.5 * s.light.angleDegrees * M_PI / 180);  // reaches the rim
  EXPECT_NEAR(inner / (n * n), 0.5, 0.05);
}

TEST(SunLight, ReferenceMatchesTheClosedFormOnSunTwoPlanes) {
  const Scene s = loadScene("sun_two_planes");
  ASSERT_EQ(s.light.type, LightType::Sun);
  const double w = 2 * std::tan(0.5 * s.light.angleDegrees * M_PI / 180);  // penumbra width at h = 1
  double worst = 0;
  for (double t : {-0.6, -0.4, -0.25, -0.1, 0.0, 0.1, 0.25, 0.4, 0.6}) {
    const double x = t * w;
    const double ref = referenceVisibilityAt(s, {float(x), 0, 0.1f}, {0, 1, 0}, 32, 7);
    worst = std::max(worst, std::abs(ref - exactSunVisibility(x, 1.0, s.light.angleDegrees)));
  }
  EXPECT_LT(worst, 0.01);  // 32^2 stratified directions
  // Sibling: a sun twice as wide gives a visibly different answer at a quarter penumbra.
  Scene wide = s;
  wide.light.angleDegrees *= 2;
  EXPECT_GT(std::abs(referenceVisibilityAt(wide, {float(0.25 * w), 0, 0.1f}, {0, 1, 0}, 32, 7) -
                     exactSunVisibility(0.25 * w, 1.0, s.light.angleDegrees)),
            0.05);
}

}  // namespace
}  // namespace shadowc::rt
