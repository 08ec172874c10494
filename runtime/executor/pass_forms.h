// Choosing among a pass's forms (docs/manifest.md "Pass forms"): by what each form declares it
// needs (a device type, subgroup size and operations), never by what the pass does. Pure
// functions of the manifest and the device's traits, so the choice is testable without a device.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include "manifest/manifest.h"

namespace shadowc::rt {

class VulkanContext;

// What the forms may ask of a device.
struct DeviceTraits {
  FormDevice type = FormDevice::Any;  // Cpu for a CPU device, Gpu for an integrated, discrete or virtual GPU
  uint32_t subgroupSize = 1;
  std::vector<std::string> subgroupOperations;  // supported in compute shaders (manifest.h names)
  std::string name;
};
DeviceTraits deviceTraits(const VulkanContext& ctx);

// "auto" (or ""): per pass the first form, own form first, that the device can run and that is
// declared for its type (or `any`); when none is declared for it, the first it can run. Any other
// value names the form every pass with forms must run (a test or benchmark override); a pass
// without that form, or whose form the device cannot run, is an error. Passes with one form run it.
inline constexpr const char* kPassFormAuto = "auto";
// The override the environment asks for: SHADOWC_PASS_FORM, else "auto".
std::string passFormFromEnvironment();
// `choice` ("" = the environment's) when it is "auto" or a form name the compiler gives a pass
// (passFormNames()); otherwise throws std::invalid_argument naming where it came from and the
// names there are, whatever the filter: a misspelt override must not time the default instead.
std::string checkedPassForm(const std::string& choice);

struct FormChoice {
  std::string pass, form, why;  // why: "auto, cpu device" or "override"
};
struct ChosenForms {
  Manifest manifest;                // every pass replaced by its chosen form (no alternatives left)
  std::vector<FormChoice> choices;  // one per pass with forms, manifest order
};
// Throws ExecutorError (pass_executor.h) naming the pass and the unmet need.
ChosenForms chooseForms(const Manifest& manifest, const DeviceTraits& device, const std::string& choice);

// Empty when the device has what the form needs, else the first unmet need in words.
std::string unmetNeed(const FormNeeds& needs, const DeviceTraits& device);

// One line for `validate`: "pass forms: sat_rows serial, sat_columns serial (auto, cpu device)".
std::string describeChoices(const std::vector<FormChoice>& choices);

}  // namespace shadowc::rt
