#include "runtime/vulkan/vulkan_context.h"

#include <algorithm>
#include <cctype>
#include <cstdlib>
#include <cstring>

#include <fmt/core.h>

#include "runtime/vulkan/vulkan_error.h"

namespace shadowc::rt {
namespace {

constexpr const char* kValidationLayer = "VK_LAYER_KHRONOS_validation";

VKAPI_ATTR VkBool32 VKAPI_CALL onValidationMessage(VkDebugUtilsMessageSeverityFlagBitsEXT severity,
                                                   VkDebugUtilsMessageTypeFlagsEXT,
                                                   const VkDebugUtilsMessengerCallbackDataEXT* data, void* user) {
  const char* level = (severity & VK_DEBUG_UTILS_MESSAGE_SEVERITY_ERROR_BIT_EXT) ? "error" : "warning";
  std::string text = fmt::format("[{}] {}: {}", level, data->pMessageIdName ? data->pMessageIdName : "?",
                                 data->pMessage ? data->pMessage : "");
  static_cast<VulkanContext*>(user)->recordValidationMessage(std::move(text));
  return VK_FALSE;  // never abort the call: we count and report instead
}

VkDebugUtilsMessengerCreateInfoEXT messengerInfo(VulkanContext* self) {
  VkDebugUtilsMessengerCreateInfoEXT info{VK_STRUCTURE_TYPE_DEBUG_UTILS_MESSENGER_CREATE_INFO_EXT};
  // Warnings count as failures too (tests assert zero messages of either kind).
  info.messageSeverity = VK_DEBUG_UTILS_MESSAGE_SEVERITY_WARNING_BIT_EXT | VK_DEBUG_UTILS_MESSAGE_SEVERITY_ERROR_BIT_EXT;
  info.messageType = VK_DEBUG_UTILS_MESSAGE_TYPE_GENERAL_BIT_EXT | VK_DEBUG_UTILS_MESSAGE_TYPE_VALIDATION_BIT_EXT |
                     VK_DEBUG_UTILS_MESSAGE_TYPE_PERFORMANCE_BIT_EXT;
  info.pfnUserCallback = onValidationMessage;
  info.pUserData = self;
  return info;
}

bool layerAvailable(const char* name) {
  uint32_t n = 0;
  vkEnumerateInstanceLayerProperties(&n, nullptr);
  std::vector<VkLayerProperties> layers(n);
  vkEnumerateInstanceLayerProperties(&n, layers.data());
  return std::any_of(layers.begin(), layers.end(), [&](const VkLayerProperties& l) { return std::strcmp(l.layerName, name) == 0; });
}

VkInstance createBareInstance() {
  VkApplicationInfo app{VK_STRUCTURE_TYPE_APPLICATION_INFO};
  app.pApplicationName = "shadowc";
  app.apiVersion = VK_API_VERSION_1_2;
  VkInstanceCreateInfo info{VK_STRUCTURE_TYPE_INSTANCE_CREATE_INFO};
  info.pApplicationInfo = &app;
  VkInstance instance = VK_NULL_HANDLE;
  const VkResult r = vkCreateInstance(&info, nullptr, &instance);
  if (r == VK_ERROR_INCOMPATIBLE_DRIVER) throw VulkanError("no Vulkan driver found (install mesa-vulkan-drivers for lavapipe)");
  checkVk(r, "vkCreateInstance");
  return instance;
}

std::vector<PhysicalDeviceInfo> enumerate(VkInstance instance) {
  uint32_t n = 0;
  checkVk(vkEnumeratePhysicalDevices(instance, &n, nullptr), "vkEnumeratePhysicalDevices");
  std::vector<VkPhysicalDevice> devices(n);
  checkVk(vkEnumeratePhysicalDevices(instance, &n, devices.data()), "vkEnumeratePhysicalDevices");
  std::vector<PhysicalDeviceInfo> out;
  for (uint32_t i = 0; i < n; ++i) {
    VkPhysicalDeviceProperties p;
    vkGetPhysicalDeviceProperties(devices[i], &p);
    out.push_back({i, p.deviceName, p.deviceType, p.apiVersion});
  }
  return out;
}

std::string lower(std::string s) {
  for (char& c : s) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
  return s;
}

std::string deviceList(const std::vector<PhysicalDeviceInfo>& devices) {
  if (devices.empty()) return "none";
  std::string s;
  for (const auto& d : devices) s += fmt::format("{}{}: {}", s.empty() ? "" : ", ", d.index, d.name);
  return s;
}

// --device: "" = llvmpipe (lavapipe, reproducible CPU timings), digits = index, else a
// case-insensitive substring of the device name.
uint32_t selectDevice(const std::vector<PhysicalDeviceInfo>& devices, const std::string& selector) {
  if (devices.empty()) throw VulkanError("no Vulkan device found (install mesa-vulkan-drivers for lavapipe)");
  if (selector.empty()) {
    for (const auto& d : devices)
      if (d.type == VK_PHYSICAL_DEVICE_TYPE_CPU && lower(d.name).find("llvmpipe") != std::string::npos) return d.index;
    throw VulkanError("no lavapipe (llvmpipe) device; available: " + deviceList(devices) + "; pick one with --device");
  }
  if (std::all_of(selector.begin(), selector.end(), [](char c) { return std::isdigit(static_cast<unsigned char>(c)); })) {
    const unsigned long i = std::stoul(selector);
    if (i >= devices.size())
      throw VulkanError(fmt::format("--device {}: no such device index; available: {}", selector, deviceList(devices)));
    return static_cast<uint32_t>(i);
  }
  for (const auto& d : devices)
    if (lower(d.name).find(lower(selector)) != std::string::npos) return d.index;
  throw VulkanError(fmt::format("--device '{}' matches no device; available: {}", selector, deviceList(devices)));
}

}  // namespace

bool validationRequestedByEnvironment() {
  const char* v = std::getenv("SHADOWC_VALIDATION");
  return v && std::string(v) == "1";
}

std::vector<PhysicalDeviceInfo> VulkanContext::listDevices() {
  loadVulkanLoader();
  VkInstance instance = createBareInstance();
  std::vector<PhysicalDeviceInfo> out;
  try {
    out = enumerate(instance);
  } catch (...) {
    vkDestroyInstance(instance, nullptr);
    throw;
  }
  vkDestroyInstance(instance, nullptr);
  return out;
}

VulkanContext::VulkanContext(const VulkanOptions& options)
    : validation_(options.validation || validationRequestedByEnvironment()) {
  loadVulkanLoader();
  uint32_t loaderVersion = 0;
  vkEnumerateInstanceVersion(&loaderVersion);
  if (loaderVersion < VK_API_VERSION_1_2)
    throw VulkanError(fmt::format("the Vulkan loader supports {}.{}; shadowc needs Vulkan 1.2",
                                  VK_API_VERSION_MAJOR(loaderVersion), VK_API_VERSION_MINOR(loaderVersion)));

  VkApplicationInfo app{VK_STRUCTURE_TYPE_APPLICATION_INFO};
  app.pApplicationName = "shadowc";
  app.apiVersion = VK_API_VERSION_1_2;
  VkInstanceCreateInfo info{VK_STRUCTURE_TYPE_INSTANCE_CREATE_INFO};
  info.pApplicationInfo = &app;
  std::vector<const char*> layers, extensions;
  // Core validation + synchronization validation. Best practices stays off: its advice is
  // about real GPUs, and every warning here counts as a test failure.
  const VkValidationFeatureEnableEXT enables[] = {VK_VALIDATION_FEATURE_ENABLE_SYNCHRONIZATION_VALIDATION_EXT};
  VkValidationFeaturesEXT features{VK_STRUCTURE_TYPE_VALIDATION_FEATURES_EXT};
  features.enabledValidationFeatureCount = 1;
  features.pEnabledValidationFeatures = enables;
  VkDebugUtilsMessengerCreateInfoEXT messenger = messengerInfo(this);
  if (validation_) {
    if (!layerAvailable(kValidationLayer))
      throw VulkanError("validation requested but VK_LAYER_KHRONOS_validation is not installed (vulkan-validationlayers)");
    layers.push_back(kValidationLayer);
    extensions.push_back(VK_EXT_DEBUG_UTILS_EXTENSION_NAME);
    // Chained so that messages from vkCreateInstance/vkDestroyInstance are caught as well.
    features.pNext = &messenger;
    info.pNext = &features;
  }
  info.enabledLayerCount = static_cast<uint32_t>(layers.size());
  info.ppEnabledLayerNames = layers.data();
  info.enabledExtensionCount = static_cast<uint32_t>(extensions.size());
  info.ppEnabledExtensionNames = extensions.data();
  {
    const VkResult r = vkCreateInstance(&info, nullptr, &instance_);
    if (r == VK_ERROR_INCOMPATIBLE_DRIVER) throw VulkanError("no Vulkan driver found (install mesa-vulkan-drivers for lavapipe)");
    checkVk(r, "vkCreateInstance");
  }
  try {
    if (validation_) {
      // Extension entry points belong to this instance (not to the process-wide table).
      auto create = reinterpret_cast<PFN_vkCreateDebugUtilsMessengerEXT>(
          vkGetInstanceProcAddr(instance_, "vkCreateDebugUtilsMessengerEXT"));
      destroyMessenger_ = reinterpret_cast<PFN_vkDestroyDebugUtilsMessengerEXT>(
          vkGetInstanceProcAddr(instance_, "vkDestroyDebugUtilsMessengerEXT"));
      if (!create || !destroyMessenger_) throw VulkanError("VK_EXT_debug_utils is not available");
      checkVk(create(instance_, &messenger, nullptr, &messenger_), "vkCreateDebugUtilsMessengerEXT");
    }

    const auto devices = enumerate(instance_);
    const uint32_t index = selectDevice(devices, options.device);
    uint32_t n = 0;
    vkEnumeratePhysicalDevices(instance_, &n, nullptr);
    std::vector<VkPhysicalDevice> handles(n);
    vkEnumeratePhysicalDevices(instance_, &n, handles.data());
    physical_ = handles.at(index);
    vkGetPhysicalDeviceProperties(physical_, &properties_);
    vkGetPhysicalDeviceMemoryProperties(physical_, &memory_);
    if (properties_.apiVersion < VK_API_VERSION_1_2)
      throw VulkanError(fmt::format("device '{}' supports only Vulkan {}.{}; shadowc needs 1.2", properties_.deviceName,
                                    VK_API_VERSION_MAJOR(properties_.apiVersion), VK_API_VERSION_MINOR(properties_.apiVersion)));

    // One queue for everything: compute passes, the rasterizer and timestamps.
    uint32_t qn = 0;
    vkGetPhysicalDeviceQueueFamilyProperties(physical_, &qn, nullptr);
    std::vector<VkQueueFamilyProperties> families(qn);
    vkGetPhysicalDeviceQueueFamilyProperties(physical_, &qn, families.data());
    bool found = false;
    for (uint32_t i = 0; i < qn && !found; ++i) {
      const VkQueueFlags need = VK_QUEUE_GRAPHICS_BIT | VK_QUEUE_COMPUTE_BIT;
      if ((families[i].queueFlags & need) == need && families[i].timestampValidBits > 0) {
        queueFamily_ = i;
        found = true;
      }
    }
    if (!found)
      throw VulkanError(fmt::format("device '{}' has no graphics+compute queue with timestamps", properties_.deviceName));

    VkPhysicalDeviceFeatures supported{};
    vkGetPhysicalDeviceFeatures(physical_, &supported);
    VkPhysicalDeviceFeatures enabled{};
    // Lets templates declare writeonly images without a format qualifier where convenient.
    enabled.shaderStorageImageWriteWithoutFormat = supported.shaderStorageImageWriteWithoutFormat;
    // rg32f, r16f, r16 (unorm), rg32ui ... as storage images need the extended formats.
    enabled.shaderStorageImageExtendedFormats = supported.shaderStorageImageExtendedFormats;
    const float priority = 1.0f;
    VkDeviceQueueCreateInfo queueInfo{VK_STRUCTURE_TYPE_DEVICE_QUEUE_CREATE_INFO};
    queueInfo.queueFamilyIndex = queueFamily_;
    queueInfo.queueCount = 1;
    queueInfo.pQueuePriorities = &priority;
    VkDeviceCreateInfo deviceInfo{VK_STRUCTURE_TYPE_DEVICE_CREATE_INFO};
    deviceInfo.queueCreateInfoCount = 1;
    deviceInfo.pQueueCreateInfos = &queueInfo;
    deviceInfo.pEnabledFeatures = &enabled;
    checkVk(vkCreateDevice(physical_, &deviceInfo, nullptr, &device_), "vkCreateDevice");
    vkGetDeviceQueue(device_, queueFamily_, 0, &queue_);

    VkCommandPoolCreateInfo poolInfo{VK_STRUCTURE_TYPE_COMMAND_POOL_CREATE_INFO};
    poolInfo.flags = VK_COMMAND_POOL_CREATE_RESET_COMMAND_BUFFER_BIT;
    poolInfo.queueFamilyIndex = queueFamily_;
    checkVk(vkCreateCommandPool(device_, &poolInfo, nullptr, &pool_), "vkCreateCommandPool");
    VkFenceCreateInfo fenceInfo{VK_STRUCTURE_TYPE_FENCE_CREATE_INFO};
    checkVk(vkCreateFence(device_, &fenceInfo, nullptr, &fence_), "vkCreateFence");
  } catch (...) {
    release();
    throw;
  }
}

VulkanContext::~VulkanContext() { release(); }

void VulkanContext::release() {
  if (device_) {
    vkDeviceWaitIdle(device_);
    if (fence_) vkDestroyFence(device_, fence_, nullptr);
    if (pool_) vkDestroyCommandPool(device_, pool_, nullptr);
    vkDestroyDevice(device_, nullptr);
  }
  if (messenger_ && destroyMessenger_) destroyMessenger_(instance_, messenger_, nullptr);
  if (instance_) vkDestroyInstance(instance_, nullptr);
  device_ = VK_NULL_HANDLE;
  fence_ = VK_NULL_HANDLE;
  pool_ = VK_NULL_HANDLE;
  messenger_ = VK_NULL_HANDLE;
  instance_ = VK_NULL_HANDLE;
}

std::string VulkanContext::describe() const {
  return fmt::format("{}, Vulkan {}.{}.{}", properties_.deviceName, VK_API_VERSION_MAJOR(properties_.apiVersion),
                     VK_API_VERSION_MINOR(properties_.apiVersion), VK_API_VERSION_PATCH(properties_.apiVersion));
}

void VulkanContext::recordValidationMessage(std::string text) {
  fmt::print(stderr, "shadowc: validation: {}\n", text);
  std::lock_guard lock(mutex_);
  messages_.push_back(std::move(text));
}

size_t VulkanContext::validationMessageCount() const {
  std::lock_guard lock(mutex_);
  return messages_.size();
}

std::vector<std::string> VulkanContext::validationMessages() const {
  std::lock_guard lock(mutex_);
  return messages_;
}

void VulkanContext::clearValidationMessages() {
  std::lock_guard lock(mutex_);
  messages_.clear();
}

void VulkanContext::submitAndWait(VkCommandBuffer cmd) const {
  VkSubmitInfo submit{VK_STRUCTURE_TYPE_SUBMIT_INFO};
  submit.commandBufferCount = 1;
  submit.pCommandBuffers = &cmd;
  checkVk(vkResetFences(device_, 1, &fence_), "vkResetFences");
  checkVk(vkQueueSubmit(queue_, 1, &submit, fence_), "vkQueueSubmit");
  checkVk(vkWaitForFences(device_, 1, &fence_, VK_TRUE, UINT64_MAX), "vkWaitForFences");
}

void VulkanContext::submitAndWait(const std::function<void(VkCommandBuffer)>& record) const {
  VkCommandBufferAllocateInfo alloc{VK_STRUCTURE_TYPE_COMMAND_BUFFER_ALLOCATE_INFO};
  alloc.commandPool = pool_;
  alloc.level = VK_COMMAND_BUFFER_LEVEL_PRIMARY;
  alloc.commandBufferCount = 1;
  VkCommandBuffer cmd = VK_NULL_HANDLE;
  checkVk(vkAllocateCommandBuffers(device_, &alloc, &cmd), "vkAllocateCommandBuffers");
  try {
    VkCommandBufferBeginInfo begin{VK_STRUCTURE_TYPE_COMMAND_BUFFER_BEGIN_INFO};
    begin.flags = VK_COMMAND_BUFFER_USAGE_ONE_TIME_SUBMIT_BIT;
    checkVk(vkBeginCommandBuffer(cmd, &begin), "vkBeginCommandBuffer");
    record(cmd);
    checkVk(vkEndCommandBuffer(cmd), "vkEndCommandBuffer");
    submitAndWait(cmd);
  } catch (...) {
    vkFreeCommandBuffers(device_, pool_, 1, &cmd);
    throw;
  }
  vkFreeCommandBuffers(device_, pool_, 1, &cmd);
}

uint32_t VulkanContext::memoryType(uint32_t typeBits, VkMemoryPropertyFlags flags) const {
  for (uint32_t i = 0; i < memory_.memoryTypeCount; ++i)
    if ((typeBits & (1u << i)) && (memory_.memoryTypes[i].propertyFlags & flags) == flags) return i;
  throw VulkanError(fmt::format("device '{}' has no memory type with flags {:#x}", properties_.deviceName, flags));
}

VkFormatFeatureFlags VulkanContext::formatFeatures(VkFormat format) const {
  VkFormatProperties p{};
  vkGetPhysicalDeviceFormatProperties(physical_, format, &p);
  return p.optimalTilingFeatures;
}

const std::vector<uint32_t>& VulkanContext::cachedSpirv(const std::string& key,
                                                        const std::function<std::vector<uint32_t>()>& build) {
  std::lock_guard lock(mutex_);
  auto it = spirvCache_.find(key);
  if (it == spirvCache_.end()) it = spirvCache_.emplace(key, build()).first;
  return it->second;
}

}  // namespace shadowc::rt
