// The executor's choice among a pass's forms (runtime/executor/pass_forms.h), without a device:
// device traits are given, so every branch is reached (a GPU, a CPU, a device of another type,
// missing subgroup features). And the SAT's GPU form, read from a compiled manifest, has at least
// 64 invocations per row of a 2048^2 map (one invocation per row is what made the serial scans
// latency-bound on a GPU).
#include "runtime/executor/pass_forms.h"

#include <gtest/gtest.h>

#include <stdexcept>
#include <string>

#include "compiler/driver/driver.h"
#include "runtime/executor/pass_executor.h"
#include "support/test_support.h"

namespace shadowc::rt {
namespace {

Manifest satManifest() {
  const driver::Result r = driver::compileFile((test::sourceDir() / "samples/filters/vssm_int32_sat.shadow").string());
  if (!r.artifact) throw std::runtime_error(r.log);
  return r.artifact->manifest;
}

const Pass& pass(const Manifest& m, const std::string& name) {
  for (const Pass& p : m.passes)
    if (p.name == name) return p;
  throw std::runtime_error("no pass " + name);
}

DeviceTraits traits(FormDevice type, uint32_t subgroup = 32, std::vector<std::string> ops = {"basic", "arithmetic"}) {
  return {type, subgroup, std::move(ops), "test device"};
}

std::string chosen(const ChosenForms& c) {
  std::string s;
  for (const FormChoice& f : c.choices) s += f.pass + "=" + f.form + " ";
  return s;
}

TEST(PassForms, SatScansDeclareASerialCpuFormAndAParallelGpuForm) {
  const Manifest m = satManifest();
  for (const char* name : {"sat_rows", "sat_columns"}) {
    const std::vector<PassForm> forms = formsOf(pass(m, name));
    ASSERT_EQ(forms.size(), 2u) << name;
    EXPECT_EQ(forms[0].name, "serial");
    EXPECT_EQ(forms[0].needs.device, FormDevice::Cpu);
    EXPECT_EQ(forms[1].name, "parallel");
    EXPECT_EQ(forms[1].needs.device, FormDevice::Gpu);
    EXPECT_NE(forms[0].spirv, forms[1].spirv);
  }
  EXPECT_TRUE(pass(m, "shade").forms.empty());
}

// Invocations per row (column) = workgroups x local size / rows, from the manifest's dispatch.
uint64_t invocationsPerLine(const Pass& p, uint32_t map) {
  const auto g = dispatchGroups(p, map, 256, 256);
  return uint64_t(g[0]) * g[1] * g[2] * p.localSize[0] * p.localSize[1] * p.localSize[2] / map;
}

TEST(PassForms, ParallelSatFormHasAtLeast64InvocationsPerRowOfA2048Map) {
  const Manifest m = satManifest();
  for (const char* name : {"sat_rows", "sat_columns"}) {
    const std::vector<PassForm> forms = formsOf(pass(m, name));
    EXPECT_GE(invocationsPerLine(withForm(pass(m, name), forms[1]), 2048), 64u) << name;
    // Sibling: the serial form has one per row, which this measure must report as such.
    EXPECT_EQ(invocationsPerLine(withForm(pass(m, name), forms[0]), 2048), 1u) << name;
  }
}

// fp32 sums depend on their order and the blocked one errs more for small boxes
// (templates/passes/sat_common.glsl "Two forms"): an fp32 table keeps the serial scans alone.
TEST(PassForms, AnFp32SatHasTheSerialFormOnly) {
  const driver::Result r =
      driver::compileFile((test::sourceDir() / "samples/filters/vssm_fp32_centered_sat.shadow").string());
  ASSERT_TRUE(r.artifact) << r.log;
  for (const char* name : {"sat_rows", "sat_columns"}) {
    EXPECT_TRUE(pass(r.artifact->manifest, name).forms.empty()) << name;
    EXPECT_EQ(formsOf(pass(r.artifact->manifest, name)).size(), 1u) << name;
  }
  // Sibling: the int32 table's scans have both.
  EXPECT_EQ(formsOf(pass(satManifest(), "sat_rows")).size(), 2u);
}

TEST(PassForms, AutoPicksTheFormDeclaredForTheDeviceType) {
  const Manifest m = satManifest();
  EXPECT_EQ(chosen(chooseForms(m, traits(FormDevice::Cpu), "auto")), "sat_rows=serial sat_columns=serial ");
  const ChosenForms gpu = chooseForms(m, traits(FormDevice::Gpu), "auto");
  EXPECT_EQ(chosen(gpu), "sat_rows=parallel sat_columns=parallel ");
  EXPECT_EQ(gpu.choices.front().why, "auto, gpu device");
  // The chosen manifest runs that form: its dispatch, no alternatives left.
  EXPECT_EQ(pass(gpu.manifest, "sat_rows").dispatch.mode, DispatchMode::RowGroups);
  EXPECT_TRUE(pass(gpu.manifest, "sat_rows").forms.empty());
  // A device of another type: no form is declared for it, the first it can run (the pass's own).
  EXPECT_EQ(chosen(chooseForms(m, traits(FormDevice::Any), "")), "sat_rows=serial sat_columns=serial ");
}

// A form whose need the device lacks is not chosen, even on the device type it is declared for.
TEST(PassForms, AFormTheDeviceCannotRunIsNotChosen) {
  Manifest m = satManifest();
  for (Pass& p : m.passes)
    if (!p.forms.empty()) p.forms[0].needs.subgroupSizeMin = 64;
  EXPECT_EQ(chosen(chooseForms(m, traits(FormDevice::Gpu, 32), "auto")), "sat_rows=serial sat_columns=serial ");
  EXPECT_EQ(chosen(chooseForms(m, traits(FormDevice::Gpu, 64), "auto")), "sat_rows=parallel sat_columns=parallel ");
  for (Pass& p : m.passes)
    if (!p.forms.empty()) p.forms[0].needs = {FormDevice::Gpu, 0, {"clustered"}};
  EXPECT_EQ(chosen(chooseForms(m, traits(FormDevice::Gpu), "auto")), "sat_rows=serial sat_columns=serial ");
  EXPECT_EQ(unmetNeed(pass(m, "sat_rows").forms[0].needs, traits(FormDevice::Gpu)),
            "subgroup operation 'clustered' in compute shaders");
}

TEST(PassForms, OverrideRunsTheNamedFormOrSaysWhyNot) {
  Manifest m = satManifest();
  const ChosenForms forced = chooseForms(m, traits(FormDevice::Cpu), "parallel");
  EXPECT_EQ(chosen(forced), "sat_rows=parallel sat_columns=parallel ");
  EXPECT_EQ(forced.choices.front().why, "override");
  // A name no pass has is refused whatever the manifest, before any pass is looked at.
  EXPECT_THROW(chooseForms(m, traits(FormDevice::Cpu), "tiled"), std::invalid_argument);
  Manifest plain = m;
  for (Pass& p : plain.passes) p.forms.clear();
  EXPECT_THROW(chooseForms(plain, traits(FormDevice::Cpu), "diagonal"), std::invalid_argument);
  EXPECT_NO_THROW(chooseForms(plain, traits(FormDevice::Cpu), "serial"));
  for (Pass& p : m.passes)
    if (!p.forms.empty()) p.forms[0].needs.subgroupOperations = {"quad"};
  try {
    chooseForms(m, traits(FormDevice::Gpu), "parallel");
    FAIL() << "forced a form whose subgroup operation the device lacks";
  } catch (const ExecutorError& e) {
    EXPECT_NE(std::string(e.what()).find("subgroup operation 'quad'"), std::string::npos) << e.what();
  }
}

TEST(PassForms, ValidateLineNamesEveryChoice) {
  const ChosenForms c = chooseForms(satManifest(), traits(FormDevice::Cpu), "auto");
  EXPECT_EQ(describeChoices(c.choices), "pass forms: sat_rows serial, sat_columns serial (auto, cpu device)");
  EXPECT_EQ(describeChoices({}), "");
}

}  // namespace
}  // namespace shadowc::rt
