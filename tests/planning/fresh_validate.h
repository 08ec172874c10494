// The independent check of a plan: the description the planner wrote, saved to a file, compiled
// from that file by the driver and run on a freshly prepared scene through the run harness, as
// `shadowc validate` does (cli/validation_run.cpp: compileFile, prepareScene, runOnScene); none of
// the planner's own candidates, scenes or measurements are reused.
#pragma once

#include <gtest/gtest.h>

#include <string>

#include "driver/driver.h"
#include "runtime/harness/scene_run.h"
#include "runtime/images/atomic_file.h"
#include "runtime/scene/cascade_setup.h"
#include "support/test_support.h"

namespace shadowc::test {

inline rt::Metrics validateWrittenPlan(rt::VulkanContext& ctx, const std::string& text, const std::string& scene,
                                       uint32_t screen, uint32_t map, int samples) {
  const auto path = freshTempDir("plan-validate") / "planned.shadow";
  rt::writeFileAtomically(path, text);
  const driver::Result compiled = driver::compileFile(path.string());
  EXPECT_TRUE(compiled.artifact) << compiled.log;
  if (!compiled.artifact) return {};
  rt::SceneSettings settings;
  settings.scene = scene;
  settings.screen = screen;
  settings.map = map;
  settings.referenceSamples = samples;
  settings.useCache = false;  // traced afresh, never the planner's (or a cached) reference
  rt::setFilterViews(settings, compiled.artifact->manifest.spec);
  const auto prepared = rt::prepareScene(ctx, settings);
  const rt::Metrics m = rt::runOnScene(ctx, compiled.artifact->passes(), *prepared).metrics;
  EXPECT_GT(m.compared, uint64_t(screen) * screen / 8) << "too few geometry pixels on " << scene;
  EXPECT_EQ(m.nonFinite, 0u);
  EXPECT_EQ(m.outOfRange, 0u);
  return m;
}

}  // namespace shadowc::test
