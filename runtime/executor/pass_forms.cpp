#include "runtime/executor/pass_forms.h"

#include <fmt/core.h>
#include <fmt/ranges.h>

#include <algorithm>
#include <cstdlib>
#include <stdexcept>
#include <utility>

#include "runtime/executor/pass_executor.h"  // ExecutorError
#include "runtime/vulkan/vulkan_context.h"

namespace shadowc::rt {

DeviceTraits deviceTraits(const VulkanContext& ctx) {
  DeviceTraits t;
  t.name = ctx.deviceName();
  switch (ctx.properties().deviceType) {
    case VK_PHYSICAL_DEVICE_TYPE_CPU:
      t.type = FormDevice::Cpu;
      break;
    case VK_PHYSICAL_DEVICE_TYPE_INTEGRATED_GPU:
    case VK_PHYSICAL_DEVICE_TYPE_DISCRETE_GPU:
    case VK_PHYSICAL_DEVICE_TYPE_VIRTUAL_GPU:
      t.type = FormDevice::Gpu;
      break;
    default:
      t.type = FormDevice::Any;  // "other": no form is declared for it
  }
  VkPhysicalDeviceSubgroupProperties sub{VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_SUBGROUP_PROPERTIES};
  VkPhysicalDeviceProperties2 p2{VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_PROPERTIES_2};
  p2.pNext = &sub;
  vkGetPhysicalDeviceProperties2(ctx.physicalDevice(), &p2);
  t.subgroupSize = std::max(1u, sub.subgroupSize);
  if (sub.supportedStages & VK_SHADER_STAGE_COMPUTE_BIT) {
    // The bits in the order of subgroupOperationNames().
    const VkSubgroupFeatureFlags bits[] = {VK_SUBGROUP_FEATURE_BASIC_BIT,      VK_SUBGROUP_FEATURE_VOTE_BIT,
                                           VK_SUBGROUP_FEATURE_ARITHMETIC_BIT, VK_SUBGROUP_FEATURE_BALLOT_BIT,
                                           VK_SUBGROUP_FEATURE_SHUFFLE_BIT,    VK_SUBGROUP_FEATURE_SHUFFLE_RELATIVE_BIT,
                                           VK_SUBGROUP_FEATURE_CLUSTERED_BIT,  VK_SUBGROUP_FEATURE_QUAD_BIT};
    for (size_t i = 0; i < subgroupOperationNames().size(); ++i)
      if (sub.supportedOperations & bits[i]) t.subgroupOperations.push_back(subgroupOperationNames()[i]);
  }
  return t;
}

std::string passFormFromEnvironment() {
  const char* v = std::getenv("SHADOWC_PASS_FORM");
  return v && *v ? v : kPassFormAuto;
}

std::string checkedPassForm(const std::string& choice) {
  const std::string value = choice.empty() ? passFormFromEnvironment() : choice;
  const std::vector<std::string>& names = passFormNames();
  if (value == kPassFormAuto || std::find(names.begin(), names.end(), value) != names.end()) return value;
  throw std::invalid_argument(fmt::format("{} '{}' is not a pass form: {}, {}",
                                          choice.empty() ? "SHADOWC_PASS_FORM" : "--pass-form", value, kPassFormAuto,
                                          fmt::join(names, ", ")));
}

std::string unmetNeed(const FormNeeds& needs, const DeviceTraits& device) {
  if (device.subgroupSize < needs.subgroupSizeMin)
    return fmt::format("subgroup size {} or more (the device has {})", needs.subgroupSizeMin, device.subgroupSize);
  for (const std::string& op : needs.subgroupOperations)
    if (std::find(device.subgroupOperations.begin(), device.subgroupOperations.end(), op) ==
        device.subgroupOperations.end())
      return fmt::format("subgroup operation '{}' in compute shaders", op);
  return "";
}

namespace {

// The auto choice for one pass: runnable and declared for the device type, else runnable.
const PassForm* autoForm(const Pass& pass, const std::vector<PassForm>& forms, const DeviceTraits& device) {
  const PassForm* fallback = nullptr;
  for (const PassForm& f : forms) {
    if (!unmetNeed(f.needs, device).empty()) continue;
    if (f.needs.device == FormDevice::Any || f.needs.device == device.type) return &f;
    if (!fallback) fallback = &f;
  }
  if (!fallback)
    throw ExecutorError(fmt::format("pass '{}': the device '{}' can run none of its forms ({})", pass.name, device.name,
                                    unmetNeed(forms.front().needs, device)));
  return fallback;
}

}  // namespace

ChosenForms chooseForms(const Manifest& manifest, const DeviceTraits& device, const std::string& choice) {
  ChosenForms out{manifest, {}};
  const std::string checked = choice.empty() ? std::string(kPassFormAuto) : checkedPassForm(choice);
  const bool automatic = checked == kPassFormAuto;
  for (Pass& pass : out.manifest.passes) {
    if (pass.forms.empty()) continue;
    const std::vector<PassForm> forms = formsOf(pass);
    const PassForm* chosen = nullptr;
    std::string why = "override";
    if (automatic) {
      chosen = autoForm(pass, forms, device);
      why = fmt::format("auto, {} device", toString(device.type));
    } else {
      const auto it = std::find_if(forms.begin(), forms.end(), [&](const PassForm& f) { return f.name == choice; });
      if (it == forms.end())
        throw ExecutorError(fmt::format("pass '{}' has no form '{}' (pass form override)", pass.name, choice));
      if (const std::string need = unmetNeed(it->needs, device); !need.empty())
        throw ExecutorError(
            fmt::format("pass '{}': form '{}' needs {}, which '{}' lacks", pass.name, choice, need, device.name));
      chosen = &*it;
    }
    out.choices.push_back({pass.name, chosen->name, why});
    pass = withForm(std::move(pass), *chosen);
  }
  return out;
}

std::string describeChoices(const std::vector<FormChoice>& choices) {
  if (choices.empty()) return "";
  std::string out = "pass forms:";
  for (size_t i = 0; i < choices.size(); ++i)
    out += fmt::format("{} {} {}", i ? "," : "", choices[i].pass, choices[i].form);
  return out + " (" + choices.front().why + ")";
}

}  // namespace shadowc::rt
