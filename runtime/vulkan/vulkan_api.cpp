#include "runtime/vulkan/vulkan_api.h"

#include <dlfcn.h>

#include <mutex>
#include <string>

#include "runtime/vulkan/vulkan_error.h"

namespace shadowc::rt {

PFN_vkGetInstanceProcAddr vkGetInstanceProcAddr = nullptr;
#define SHADOWC_VK_DEFINE(name) PFN_##name name = nullptr;
SHADOWC_VK_GLOBAL_FUNCTIONS(SHADOWC_VK_DEFINE)
SHADOWC_VK_INSTANCE_FUNCTIONS(SHADOWC_VK_DEFINE)
SHADOWC_VK_DEVICE_FUNCTIONS(SHADOWC_VK_DEFINE)
#undef SHADOWC_VK_DEFINE

void loadVulkanLoader() {
  static std::once_flag once;
  static std::string failure;
  std::call_once(once, [] {
    void* lib = dlopen("libvulkan.so.1", RTLD_NOW | RTLD_LOCAL);
    if (!lib) lib = dlopen("libvulkan.so", RTLD_NOW | RTLD_LOCAL);
    if (!lib) {
      failure = "no Vulkan loader (libvulkan.so.1 not found); install libvulkan1 and mesa-vulkan-drivers "
                "(scripts/install-deps.sh)";
      return;
    }
#if defined(__SANITIZE_ADDRESS__)
    // Sanitizer builds only (scripts/sanitize.sh): keep lavapipe and the validation layer mapped
    // after the loader unloads them, so LeakSanitizer names their allocations for
    // tests/sanitizers/lsan.supp instead of printing "<unknown module>".
    for (const char* so : {"libvulkan_lvp.so", "libVkLayer_khronos_validation.so"})
      dlopen(so, RTLD_NOW | RTLD_NODELETE);
#endif
    vkGetInstanceProcAddr = reinterpret_cast<PFN_vkGetInstanceProcAddr>(dlsym(lib, "vkGetInstanceProcAddr"));
    if (!vkGetInstanceProcAddr) {
      failure = "the Vulkan loader has no vkGetInstanceProcAddr";
      return;
    }
#define SHADOWC_VK_LOAD(name) name = reinterpret_cast<PFN_##name>(vkGetInstanceProcAddr(nullptr, #name));
    SHADOWC_VK_GLOBAL_FUNCTIONS(SHADOWC_VK_LOAD)
#undef SHADOWC_VK_LOAD
    if (!vkCreateInstance || !vkEnumerateInstanceVersion) {
      failure = "the Vulkan loader is older than Vulkan 1.1";
      return;
    }
    std::string missing;
#define SHADOWC_VK_LOAD(name)                             \
  name = reinterpret_cast<PFN_##name>(dlsym(lib, #name)); \
  if (!name) missing += std::string(missing.empty() ? "" : ", ") + #name;
    SHADOWC_VK_INSTANCE_FUNCTIONS(SHADOWC_VK_LOAD)
    SHADOWC_VK_DEVICE_FUNCTIONS(SHADOWC_VK_LOAD)
#undef SHADOWC_VK_LOAD
    if (!missing.empty()) failure = "the Vulkan loader does not export " + missing;
  });
  if (!failure.empty()) throw VulkanError(failure);
}

const char* vkResultName(VkResult r) {
  switch (r) {
#define SHADOWC_CASE(x) \
  case x:               \
    return #x;
    SHADOWC_CASE(VK_SUCCESS)
    SHADOWC_CASE(VK_NOT_READY)
    SHADOWC_CASE(VK_TIMEOUT)
    SHADOWC_CASE(VK_INCOMPLETE)
    SHADOWC_CASE(VK_ERROR_OUT_OF_HOST_MEMORY)
    SHADOWC_CASE(VK_ERROR_OUT_OF_DEVICE_MEMORY)
    SHADOWC_CASE(VK_ERROR_INITIALIZATION_FAILED)
    SHADOWC_CASE(VK_ERROR_DEVICE_LOST)
    SHADOWC_CASE(VK_ERROR_MEMORY_MAP_FAILED)
    SHADOWC_CASE(VK_ERROR_LAYER_NOT_PRESENT)
    SHADOWC_CASE(VK_ERROR_EXTENSION_NOT_PRESENT)
    SHADOWC_CASE(VK_ERROR_FEATURE_NOT_PRESENT)
    SHADOWC_CASE(VK_ERROR_INCOMPATIBLE_DRIVER)
    SHADOWC_CASE(VK_ERROR_TOO_MANY_OBJECTS)
    SHADOWC_CASE(VK_ERROR_FORMAT_NOT_SUPPORTED)
    SHADOWC_CASE(VK_ERROR_FRAGMENTED_POOL)
    SHADOWC_CASE(VK_ERROR_OUT_OF_POOL_MEMORY)
    SHADOWC_CASE(VK_ERROR_INVALID_SHADER_NV)
#undef SHADOWC_CASE
    default:
      return "VK_ERROR_UNKNOWN";
  }
}

void checkVk(VkResult r, const char* what) {
  if (r != VK_SUCCESS) throw VulkanError(std::string(what) + " failed: " + vkResultName(r));
}

}  // namespace shadowc::rt
