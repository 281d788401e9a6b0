// Instance, validation messenger, physical device choice, logical device and one-shot
// submission (see prism/vk/device.hpp).
#include "prism/vk/device.hpp"

#include <algorithm>
#include <cstring>

namespace prism::vk {
namespace {

constexpr const char* kValidationLayer = "VK_LAYER_KHRONOS_validation";
constexpr const char* kInstallDriver =
    "install mesa-vulkan-drivers (lavapipe, Vulkan on the CPU; scripts/setup.sh) or a GPU's Vulkan driver";

bool hasLayer(const char* name) {
    std::uint32_t count = 0;
    vkEnumerateInstanceLayerProperties(&count, nullptr);
    std::vector<VkLayerProperties> layers(count);
    vkEnumerateInstanceLayerProperties(&count, layers.data());
    return std::any_of(layers.begin(), layers.end(),
                       [&](const auto& l) { return std::strcmp(l.layerName, name) == 0; });
}

Instance createInstance(bool validation) {
    if (validation && !hasLayer(kValidationLayer))
        throw VkError(std::string("the Khronos validation layer ") + kValidationLayer +
                      " is not installed; install vulkan-validationlayers (scripts/setup.sh) or create the "
                      "Device without validation");
    VkApplicationInfo app{VK_STRUCTURE_TYPE_APPLICATION_INFO};
    app.pApplicationName = "prism";
    app.apiVersion = VK_API_VERSION_1_1;
    const char* extensions[] = {VK_EXT_DEBUG_UTILS_EXTENSION_NAME};
    VkInstanceCreateInfo info{VK_STRUCTURE_TYPE_INSTANCE_CREATE_INFO};
    info.pApplicationInfo = &app;
    if (validation) {
        info.enabledLayerCount = 1;
        info.ppEnabledLayerNames = &kValidationLayer;
        info.enabledExtensionCount = 1;
        info.ppEnabledExtensionNames = extensions;
    }
    VkInstance instance = VK_NULL_HANDLE;
    const VkResult result = vkCreateInstance(&info, nullptr, &instance);
    if (result == VK_ERROR_INCOMPATIBLE_DRIVER || result == VK_ERROR_INITIALIZATION_FAILED)
        throw NoDeviceError("no Vulkan driver found (vkCreateInstance: " + resultName(result) + "); " + kInstallDriver);
    check(result, "vkCreateInstance");
    return Instance(VK_NULL_HANDLE, instance);
}

VKAPI_ATTR VkBool32 VKAPI_CALL recordMessage(VkDebugUtilsMessageSeverityFlagBitsEXT severity,
                                             VkDebugUtilsMessageTypeFlagsEXT,
                                             const VkDebugUtilsMessengerCallbackDataEXT* data, void* user) {
    auto* log = static_cast<Device::MessageLog*>(user);
    const char* level = severity >= VK_DEBUG_UTILS_MESSAGE_SEVERITY_ERROR_BIT_EXT ? "error" : "warning";
    std::lock_guard lock(log->mutex);
    log->messages.push_back(std::string(level) + ": " + (data->pMessage ? data->pMessage : ""));
    return VK_FALSE;
}

DebugMessenger createMessenger(VkInstance instance, Device::MessageLog& log) {
    auto create = reinterpret_cast<PFN_vkCreateDebugUtilsMessengerEXT>(
        vkGetInstanceProcAddr(instance, "vkCreateDebugUtilsMessengerEXT"));
    if (!create) throw VkError("VK_EXT_debug_utils is missing; install vulkan-validationlayers (scripts/setup.sh)");
    VkDebugUtilsMessengerCreateInfoEXT info{VK_STRUCTURE_TYPE_DEBUG_UTILS_MESSENGER_CREATE_INFO_EXT};
    info.messageSeverity =
        VK_DEBUG_UTILS_MESSAGE_SEVERITY_WARNING_BIT_EXT | VK_DEBUG_UTILS_MESSAGE_SEVERITY_ERROR_BIT_EXT;
    info.messageType = VK_DEBUG_UTILS_MESSAGE_TYPE_GENERAL_BIT_EXT | VK_DEBUG_UTILS_MESSAGE_TYPE_VALIDATION_BIT_EXT |
                       VK_DEBUG_UTILS_MESSAGE_TYPE_PERFORMANCE_BIT_EXT;
    info.pfnUserCallback = recordMessage;
    info.pUserData = &log;
    VkDebugUtilsMessengerEXT messenger = VK_NULL_HANDLE;
    check(create(instance, &info, nullptr, &messenger), "vkCreateDebugUtilsMessengerEXT");
    return DebugMessenger(instance, messenger);
}

bool hasDeviceExtension(VkPhysicalDevice device, const char* name) {
    std::uint32_t count = 0;
    vkEnumerateDeviceExtensionProperties(device, nullptr, &count, nullptr);
    std::vector<VkExtensionProperties> extensions(count);
    vkEnumerateDeviceExtensionProperties(device, nullptr, &count, extensions.data());
    return std::any_of(extensions.begin(), extensions.end(),
                       [&](const auto& e) { return std::strcmp(e.extensionName, name) == 0; });
}

// The graphics queue family of `device`, or -1.
int graphicsFamily(VkPhysicalDevice device) {
    std::uint32_t count = 0;
    vkGetPhysicalDeviceQueueFamilyProperties(device, &count, nullptr);
    std::vector<VkQueueFamilyProperties> families(count);
    vkGetPhysicalDeviceQueueFamilyProperties(device, &count, families.data());
    for (std::uint32_t i = 0; i < count; ++i)
        if (families[i].queueFlags & VK_QUEUE_GRAPHICS_BIT) return static_cast<int>(i);
    return -1;
}

// The device extensions GL's conventions need (prism/vk/clip_convention.hpp): its depth
// range and its provoking vertex.
constexpr const char* kRequiredExtensions[] = {VK_EXT_DEPTH_CLIP_CONTROL_EXTENSION_NAME,
                                               VK_EXT_PROVOKING_VERTEX_EXTENSION_NAME};

bool hasRequiredExtensions(VkPhysicalDevice device) {
    return std::all_of(std::begin(kRequiredExtensions), std::end(kRequiredExtensions),
                       [&](const char* name) { return hasDeviceExtension(device, name); });
}

// A usable device, GPUs before CPU implementations: Vulkan 1.1, a graphics queue and the
// required extensions.
VkPhysicalDevice pickPhysicalDevice(VkInstance instance) {
    std::uint32_t count = 0;
    vkEnumeratePhysicalDevices(instance, &count, nullptr);
    std::vector<VkPhysicalDevice> devices(count);
    vkEnumeratePhysicalDevices(instance, &count, devices.data());
    auto rank = [](VkPhysicalDevice d) {
        VkPhysicalDeviceProperties p;
        vkGetPhysicalDeviceProperties(d, &p);
        return p.deviceType == VK_PHYSICAL_DEVICE_TYPE_DISCRETE_GPU ? 0
               : p.deviceType == VK_PHYSICAL_DEVICE_TYPE_CPU        ? 2
                                                                    : 1;
    };
    std::stable_sort(devices.begin(), devices.end(), [&](auto a, auto b) { return rank(a) < rank(b); });
    std::string refused;
    for (auto d : devices) {
        VkPhysicalDeviceProperties p;
        vkGetPhysicalDeviceProperties(d, &p);
        if (p.apiVersion >= VK_API_VERSION_1_1 && graphicsFamily(d) >= 0 && hasRequiredExtensions(d)) return d;
        refused += std::string(refused.empty() ? "" : ", ") + p.deviceName;
    }
    if (devices.empty()) throw NoDeviceError(std::string("no Vulkan device found; ") + kInstallDriver);
    throw NoDeviceError(
        "no Vulkan device has Vulkan 1.1, a graphics queue, VK_EXT_depth_clip_control and VK_EXT_provoking_vertex "
        "(found: " +
        refused + "); " + kInstallDriver);
}

LogicalDevice createLogicalDevice(VkInstance instance, VkPhysicalDevice physical, std::uint32_t family) {
    const float priority = 1.0f;
    VkDeviceQueueCreateInfo queue{VK_STRUCTURE_TYPE_DEVICE_QUEUE_CREATE_INFO};
    queue.queueFamilyIndex = family;
    queue.queueCount = 1;
    queue.pQueuePriorities = &priority;
    VkPhysicalDeviceProvokingVertexFeaturesEXT provoking{
        VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_PROVOKING_VERTEX_FEATURES_EXT};
    provoking.provokingVertexLast = VK_TRUE;
    VkPhysicalDeviceDepthClipControlFeaturesEXT clipControl{
        VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_DEPTH_CLIP_CONTROL_FEATURES_EXT};
    clipControl.depthClipControl = VK_TRUE;
    clipControl.pNext = &provoking;
    VkDeviceCreateInfo info{VK_STRUCTURE_TYPE_DEVICE_CREATE_INFO};
    info.pNext = &clipControl;
    info.queueCreateInfoCount = 1;
    info.pQueueCreateInfos = &queue;
    info.enabledExtensionCount = static_cast<std::uint32_t>(std::size(kRequiredExtensions));
    info.ppEnabledExtensionNames = kRequiredExtensions;
    VkDevice device = VK_NULL_HANDLE;
    check(vkCreateDevice(physical, &info, nullptr, &device), "vkCreateDevice");
    return LogicalDevice(instance, device);
}

}  // namespace

Device::Device(DeviceOptions options) : options_(options), log_(std::make_unique<MessageLog>()) {
    instance_ = createInstance(options.validation);
    if (options.validation) messenger_ = createMessenger(instance_.get(), *log_);
    physical_ = pickPhysicalDevice(instance_.get());
    VkPhysicalDeviceProperties properties;
    vkGetPhysicalDeviceProperties(physical_, &properties);
    name_ = properties.deviceName;
    queueFamily_ = static_cast<std::uint32_t>(graphicsFamily(physical_));
    device_ = createLogicalDevice(instance_.get(), physical_, queueFamily_);
    vkGetDeviceQueue(device_.get(), queueFamily_, 0, &queue_);
    VkCommandPoolCreateInfo pool{VK_STRUCTURE_TYPE_COMMAND_POOL_CREATE_INFO};
    pool.flags = VK_COMMAND_POOL_CREATE_TRANSIENT_BIT;
    pool.queueFamilyIndex = queueFamily_;
    VkCommandPool commandPool = VK_NULL_HANDLE;
    check(vkCreateCommandPool(device_.get(), &pool, nullptr, &commandPool), "vkCreateCommandPool");
    commandPool_ = CommandPool(device_.get(), commandPool);
}

Device::~Device() {
    if (device_) vkDeviceWaitIdle(device_.get());
}

std::vector<std::string> Device::validationMessages() const {
    std::lock_guard lock(log_->mutex);
    return log_->messages;
}

std::uint32_t Device::memoryType(std::uint32_t typeBits, VkMemoryPropertyFlags properties) const {
    VkPhysicalDeviceMemoryProperties memory;
    vkGetPhysicalDeviceMemoryProperties(physical_, &memory);
    for (std::uint32_t i = 0; i < memory.memoryTypeCount; ++i)
        if ((typeBits & (1u << i)) && (memory.memoryTypes[i].propertyFlags & properties) == properties) return i;
    throw VkError(name_ + " has no memory type with properties " + std::to_string(properties));
}

void Device::submit(const std::function<void(VkCommandBuffer)>& commands) const {
    VkCommandBufferAllocateInfo allocate{VK_STRUCTURE_TYPE_COMMAND_BUFFER_ALLOCATE_INFO};
    allocate.commandPool = commandPool_.get();
    allocate.level = VK_COMMAND_BUFFER_LEVEL_PRIMARY;
    allocate.commandBufferCount = 1;
    VkCommandBuffer cmd = VK_NULL_HANDLE;
    check(vkAllocateCommandBuffers(device_.get(), &allocate, &cmd), "vkAllocateCommandBuffers");
    struct FreeOnExit {
        VkDevice device;
        VkCommandPool pool;
        VkCommandBuffer cmd;
        ~FreeOnExit() { vkFreeCommandBuffers(device, pool, 1, &cmd); }
    } freeOnExit{device_.get(), commandPool_.get(), cmd};
    VkCommandBufferBeginInfo begin{VK_STRUCTURE_TYPE_COMMAND_BUFFER_BEGIN_INFO};
    begin.flags = VK_COMMAND_BUFFER_USAGE_ONE_TIME_SUBMIT_BIT;
    check(vkBeginCommandBuffer(cmd, &begin), "vkBeginCommandBuffer");
    commands(cmd);
    check(vkEndCommandBuffer(cmd), "vkEndCommandBuffer");
    VkFenceCreateInfo fenceInfo{VK_STRUCTURE_TYPE_FENCE_CREATE_INFO};
    VkFence rawFence = VK_NULL_HANDLE;
    check(vkCreateFence(device_.get(), &fenceInfo, nullptr, &rawFence), "vkCreateFence");
    Fence fence(device_.get(), rawFence);
    VkSubmitInfo submitInfo{VK_STRUCTURE_TYPE_SUBMIT_INFO};
    submitInfo.commandBufferCount = 1;
    submitInfo.pCommandBuffers = &cmd;
    check(vkQueueSubmit(queue_, 1, &submitInfo, fence.get()), "vkQueueSubmit");
    check(vkWaitForFences(device_.get(), 1, &rawFence, VK_TRUE, UINT64_MAX), "vkWaitForFences");
}

}  // namespace prism::vk
