/*
 * vkhost: a small Vulkan compute host, loaded by the .NET test harness (DllImport "vkhost").
 *
 * It runs compute kernels compiled from the package's HLSL to SPIR-V on the first Vulkan device (lavapipe, the CPU
 * driver, when VK_ICD_FILENAMES points at it). Buffers are host-visible and coherent (the caller maps them once and
 * reads and writes them in place); kernels are pipelines whose single descriptor set (set 0) is pushed per dispatch
 * (VK_KHR_push_descriptor), so the caller binds buffers by the binding numbers it reflected from each kernel's SPIR-V.
 * Dispatches are recorded into one command buffer, each followed by a full compute-to-compute and compute-to-indirect
 * barrier, and run by vkh_submit, which waits for the device.
 *
 * With VKH_VALIDATION=1 in the environment the Khronos validation layer is enabled when installed; every message of
 * severity warning or error is counted (vkh_validation_messages) and printed to stderr.
 *
 * Build: gcc -O2 -std=c11 -shared -fPIC -o libvkhost.so vkhost.c -lvulkan   (build.sh)
 */
#define _POSIX_C_SOURCE 200112L
#include <vulkan/vulkan.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <time.h>

#define VKH_EXPORT __attribute__((visibility("default")))
#define VKH_MAX_BINDINGS 32

typedef struct vkh_ctx {
    VkInstance instance;
    VkPhysicalDevice physical;
    VkDevice device;
    VkQueue queue;
    uint32_t queue_family;
    VkCommandPool pool;
    VkCommandBuffer cmd;
    VkFence fence;
    VkPhysicalDeviceMemoryProperties memory;
    VkPhysicalDeviceProperties properties;
    VkDebugUtilsMessengerEXT messenger;
    PFN_vkCmdPushDescriptorSetKHR push_descriptors;
    int recording;
    int live_buffers;
    int live_kernels;
    int validation_messages;
    uint32_t recorded;
} vkh_ctx;

typedef struct vkh_buffer {
    VkBuffer buffer;
    VkDeviceMemory memory;
    void *mapped;
    uint64_t size;
} vkh_buffer;

typedef struct vkh_kernel {
    VkShaderModule module;
    VkDescriptorSetLayout set_layout;
    VkPipelineLayout layout;
    VkPipeline pipeline;
    int bindings;
    uint32_t binding[VKH_MAX_BINDINGS];
    VkDescriptorType type[VKH_MAX_BINDINGS];
} vkh_kernel;

static void set_error(char *err, int len, const char *what, VkResult r) {
    if (err && len > 0) snprintf(err, (size_t)len, "%s failed (VkResult %d)", what, (int)r);
}

static VKAPI_ATTR VkBool32 VKAPI_CALL on_message(VkDebugUtilsMessageSeverityFlagBitsEXT severity,
    VkDebugUtilsMessageTypeFlagsEXT type, const VkDebugUtilsMessengerCallbackDataEXT *data, void *user) {
    (void)type;
    vkh_ctx *ctx = (vkh_ctx *)user;
    if (severity >= VK_DEBUG_UTILS_MESSAGE_SEVERITY_WARNING_BIT_EXT) {
        ctx->validation_messages++;
        fprintf(stderr, "vkhost validation: %s\n", data->pMessage);
    }
    return VK_FALSE;
}

static int has_layer(const char *name) {
    uint32_t n = 0;
    vkEnumerateInstanceLayerProperties(&n, NULL);
    VkLayerProperties *props = calloc(n ? n : 1, sizeof *props);
    vkEnumerateInstanceLayerProperties(&n, props);
    int found = 0;
    for (uint32_t i = 0; i < n; i++) if (strcmp(props[i].layerName, name) == 0) found = 1;
    free(props);
    return found;
}

VKH_EXPORT int vkh_create(vkh_ctx **out, char *err, int errlen) {
    *out = NULL;
    vkh_ctx *ctx = calloc(1, sizeof *ctx);
    const char *validation = getenv("VKH_VALIDATION");
    int validate = validation && strcmp(validation, "1") == 0 && has_layer("VK_LAYER_KHRONOS_validation");
    const char *layers[] = { "VK_LAYER_KHRONOS_validation" };
    const char *instance_ext[] = { VK_EXT_DEBUG_UTILS_EXTENSION_NAME };
    VkApplicationInfo app = { .sType = VK_STRUCTURE_TYPE_APPLICATION_INFO, .pApplicationName = "vkhost",
        .apiVersion = VK_API_VERSION_1_2 };
    VkInstanceCreateInfo ici = { .sType = VK_STRUCTURE_TYPE_INSTANCE_CREATE_INFO, .pApplicationInfo = &app,
        .enabledLayerCount = validate ? 1u : 0u, .ppEnabledLayerNames = layers,
        .enabledExtensionCount = validate ? 1u : 0u, .ppEnabledExtensionNames = instance_ext };
    VkResult r = vkCreateInstance(&ici, NULL, &ctx->instance);
    if (r != VK_SUCCESS) { set_error(err, errlen, "vkCreateInstance", r); free(ctx); return (int)r; }
    if (validate) {
        PFN_vkCreateDebugUtilsMessengerEXT create = (PFN_vkCreateDebugUtilsMessengerEXT)
            vkGetInstanceProcAddr(ctx->instance, "vkCreateDebugUtilsMessengerEXT");
        VkDebugUtilsMessengerCreateInfoEXT mci = { .sType = VK_STRUCTURE_TYPE_DEBUG_UTILS_MESSENGER_CREATE_INFO_EXT,
            .messageSeverity = VK_DEBUG_UTILS_MESSAGE_SEVERITY_WARNING_BIT_EXT | VK_DEBUG_UTILS_MESSAGE_SEVERITY_ERROR_BIT_EXT,
            .messageType = VK_DEBUG_UTILS_MESSAGE_TYPE_GENERAL_BIT_EXT | VK_DEBUG_UTILS_MESSAGE_TYPE_VALIDATION_BIT_EXT,
            .pfnUserCallback = on_message, .pUserData = ctx };
        if (create) create(ctx->instance, &mci, NULL, &ctx->messenger);
    }
    uint32_t count = 1;
    r = vkEnumeratePhysicalDevices(ctx->instance, &count, &ctx->physical);
    if ((r != VK_SUCCESS && r != VK_INCOMPLETE) || count == 0) {
        set_error(err, errlen, "vkEnumeratePhysicalDevices (no Vulkan device)", r);
        vkDestroyInstance(ctx->instance, NULL); free(ctx); return -1;
    }
    vkGetPhysicalDeviceMemoryProperties(ctx->physical, &ctx->memory);
    vkGetPhysicalDeviceProperties(ctx->physical, &ctx->properties);

    uint32_t families = 0;
    vkGetPhysicalDeviceQueueFamilyProperties(ctx->physical, &families, NULL);
    VkQueueFamilyProperties *fam = calloc(families, sizeof *fam);
    vkGetPhysicalDeviceQueueFamilyProperties(ctx->physical, &families, fam);
    ctx->queue_family = UINT32_MAX;
    for (uint32_t i = 0; i < families; i++)
        if (fam[i].queueFlags & VK_QUEUE_COMPUTE_BIT) { ctx->queue_family = i; break; }
    free(fam);
    if (ctx->queue_family == UINT32_MAX) {
        set_error(err, errlen, "no compute queue", VK_ERROR_FEATURE_NOT_PRESENT);
        vkDestroyInstance(ctx->instance, NULL); free(ctx); return -1;
    }

    /* Every core feature the driver has (robust buffer access among them: out-of-range reads return 0, as on D3D). */
    VkPhysicalDeviceVulkan12Features f12 = { .sType = VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_VULKAN_1_2_FEATURES };
    VkPhysicalDeviceVulkan11Features f11 = { .sType = VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_VULKAN_1_1_FEATURES, .pNext = &f12 };
    VkPhysicalDeviceFeatures2 features = { .sType = VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_FEATURES_2, .pNext = &f11 };
    vkGetPhysicalDeviceFeatures2(ctx->physical, &features);

    float priority = 1.0f;
    VkDeviceQueueCreateInfo qci = { .sType = VK_STRUCTURE_TYPE_DEVICE_QUEUE_CREATE_INFO,
        .queueFamilyIndex = ctx->queue_family, .queueCount = 1, .pQueuePriorities = &priority };
    const char *device_ext[] = { VK_KHR_PUSH_DESCRIPTOR_EXTENSION_NAME };
    VkDeviceCreateInfo dci = { .sType = VK_STRUCTURE_TYPE_DEVICE_CREATE_INFO, .pNext = &features,
        .queueCreateInfoCount = 1, .pQueueCreateInfos = &qci, .enabledExtensionCount = 1, .ppEnabledExtensionNames = device_ext };
    r = vkCreateDevice(ctx->physical, &dci, NULL, &ctx->device);
    if (r != VK_SUCCESS) { set_error(err, errlen, "vkCreateDevice (needs VK_KHR_push_descriptor)", r); vkDestroyInstance(ctx->instance, NULL); free(ctx); return (int)r; }
    vkGetDeviceQueue(ctx->device, ctx->queue_family, 0, &ctx->queue);
    ctx->push_descriptors = (PFN_vkCmdPushDescriptorSetKHR)vkGetDeviceProcAddr(ctx->device, "vkCmdPushDescriptorSetKHR");

    VkCommandPoolCreateInfo pci = { .sType = VK_STRUCTURE_TYPE_COMMAND_POOL_CREATE_INFO,
        .flags = VK_COMMAND_POOL_CREATE_RESET_COMMAND_BUFFER_BIT, .queueFamilyIndex = ctx->queue_family };
    vkCreateCommandPool(ctx->device, &pci, NULL, &ctx->pool);
    VkCommandBufferAllocateInfo cai = { .sType = VK_STRUCTURE_TYPE_COMMAND_BUFFER_ALLOCATE_INFO, .commandPool = ctx->pool,
        .level = VK_COMMAND_BUFFER_LEVEL_PRIMARY, .commandBufferCount = 1 };
    vkAllocateCommandBuffers(ctx->device, &cai, &ctx->cmd);
    VkFenceCreateInfo fci = { .sType = VK_STRUCTURE_TYPE_FENCE_CREATE_INFO };
    vkCreateFence(ctx->device, &fci, NULL, &ctx->fence);
    *out = ctx;
    return 0;
}

/* Sets a variable of the native environment (VK_ICD_FILENAMES must be set before vkh_create; .NET's own
 * Environment.SetEnvironmentVariable does not reach the C library's environment). */
VKH_EXPORT int vkh_setenv(const char *name, const char *value) { return setenv(name, value, 1); }

VKH_EXPORT const char *vkh_device_name(vkh_ctx *ctx) { return ctx->properties.deviceName; }
VKH_EXPORT int vkh_live_buffers(vkh_ctx *ctx) { return ctx->live_buffers; }
VKH_EXPORT int vkh_live_kernels(vkh_ctx *ctx) { return ctx->live_kernels; }
VKH_EXPORT int vkh_validation_messages(vkh_ctx *ctx) { return ctx->validation_messages; }
VKH_EXPORT int vkh_validation_enabled(vkh_ctx *ctx) { return ctx->messenger != VK_NULL_HANDLE; }

VKH_EXPORT int vkh_buffer_create(vkh_ctx *ctx, uint64_t size, vkh_buffer **out, void **mapped) {
    *out = NULL;
    vkh_buffer *b = calloc(1, sizeof *b);
    b->size = size < 16 ? 16 : size;
    VkBufferCreateInfo bci = { .sType = VK_STRUCTURE_TYPE_BUFFER_CREATE_INFO, .size = b->size,
        .usage = VK_BUFFER_USAGE_STORAGE_BUFFER_BIT | VK_BUFFER_USAGE_UNIFORM_BUFFER_BIT | VK_BUFFER_USAGE_INDIRECT_BUFFER_BIT
               | VK_BUFFER_USAGE_TRANSFER_SRC_BIT | VK_BUFFER_USAGE_TRANSFER_DST_BIT,
        .sharingMode = VK_SHARING_MODE_EXCLUSIVE };
    VkResult r = vkCreateBuffer(ctx->device, &bci, NULL, &b->buffer);
    if (r != VK_SUCCESS) { free(b); return (int)r; }
    VkMemoryRequirements req;
    vkGetBufferMemoryRequirements(ctx->device, b->buffer, &req);
    uint32_t want = VK_MEMORY_PROPERTY_HOST_VISIBLE_BIT | VK_MEMORY_PROPERTY_HOST_COHERENT_BIT, type = UINT32_MAX;
    for (uint32_t i = 0; i < ctx->memory.memoryTypeCount; i++)
        if ((req.memoryTypeBits & (1u << i)) && (ctx->memory.memoryTypes[i].propertyFlags & want) == want) { type = i; break; }
    if (type == UINT32_MAX) { vkDestroyBuffer(ctx->device, b->buffer, NULL); free(b); return -1; }
    VkMemoryAllocateInfo mai = { .sType = VK_STRUCTURE_TYPE_MEMORY_ALLOCATE_INFO, .allocationSize = req.size, .memoryTypeIndex = type };
    r = vkAllocateMemory(ctx->device, &mai, NULL, &b->memory);
    if (r != VK_SUCCESS) { vkDestroyBuffer(ctx->device, b->buffer, NULL); free(b); return (int)r; }
    vkBindBufferMemory(ctx->device, b->buffer, b->memory, 0);
    vkMapMemory(ctx->device, b->memory, 0, VK_WHOLE_SIZE, 0, &b->mapped);
    memset(b->mapped, 0, (size_t)b->size);
    ctx->live_buffers++;
    *out = b;
    *mapped = b->mapped;
    return 0;
}

VKH_EXPORT void vkh_buffer_destroy(vkh_ctx *ctx, vkh_buffer *b) {
    if (!b) return;
    vkUnmapMemory(ctx->device, b->memory);
    vkDestroyBuffer(ctx->device, b->buffer, NULL);
    vkFreeMemory(ctx->device, b->memory, NULL);
    ctx->live_buffers--;
    free(b);
}

/* kinds[i]: 0 = storage buffer, 1 = uniform buffer, for set 0 binding bindings[i]. */
VKH_EXPORT int vkh_kernel_create(vkh_ctx *ctx, const uint32_t *spirv, uint64_t bytes, const char *entry, int count,
    const int *bindings, const int *kinds, vkh_kernel **out, char *err, int errlen) {
    *out = NULL;
    if (count > VKH_MAX_BINDINGS) { set_error(err, errlen, "too many bindings", VK_ERROR_TOO_MANY_OBJECTS); return -1; }
    vkh_kernel *k = calloc(1, sizeof *k);
    VkShaderModuleCreateInfo smci = { .sType = VK_STRUCTURE_TYPE_SHADER_MODULE_CREATE_INFO, .codeSize = (size_t)bytes, .pCode = spirv };
    VkResult r = vkCreateShaderModule(ctx->device, &smci, NULL, &k->module);
    if (r != VK_SUCCESS) { set_error(err, errlen, "vkCreateShaderModule", r); free(k); return (int)r; }
    VkDescriptorSetLayoutBinding lb[VKH_MAX_BINDINGS];
    k->bindings = count;
    for (int i = 0; i < count; i++) {
        k->binding[i] = (uint32_t)bindings[i];
        k->type[i] = kinds[i] == 1 ? VK_DESCRIPTOR_TYPE_UNIFORM_BUFFER : VK_DESCRIPTOR_TYPE_STORAGE_BUFFER;
        lb[i] = (VkDescriptorSetLayoutBinding){ .binding = k->binding[i], .descriptorType = k->type[i], .descriptorCount = 1,
            .stageFlags = VK_SHADER_STAGE_COMPUTE_BIT };
    }
    VkDescriptorSetLayoutCreateInfo dl = { .sType = VK_STRUCTURE_TYPE_DESCRIPTOR_SET_LAYOUT_CREATE_INFO,
        .flags = VK_DESCRIPTOR_SET_LAYOUT_CREATE_PUSH_DESCRIPTOR_BIT_KHR, .bindingCount = (uint32_t)count, .pBindings = lb };
    vkCreateDescriptorSetLayout(ctx->device, &dl, NULL, &k->set_layout);
    VkPipelineLayoutCreateInfo pl = { .sType = VK_STRUCTURE_TYPE_PIPELINE_LAYOUT_CREATE_INFO, .setLayoutCount = 1, .pSetLayouts = &k->set_layout };
    vkCreatePipelineLayout(ctx->device, &pl, NULL, &k->layout);
    VkComputePipelineCreateInfo cpi = { .sType = VK_STRUCTURE_TYPE_COMPUTE_PIPELINE_CREATE_INFO,
        .stage = { .sType = VK_STRUCTURE_TYPE_PIPELINE_SHADER_STAGE_CREATE_INFO, .stage = VK_SHADER_STAGE_COMPUTE_BIT,
                   .module = k->module, .pName = entry },
        .layout = k->layout };
    r = vkCreateComputePipelines(ctx->device, VK_NULL_HANDLE, 1, &cpi, NULL, &k->pipeline);
    if (r != VK_SUCCESS) {
        set_error(err, errlen, "vkCreateComputePipelines", r);
        vkDestroyPipelineLayout(ctx->device, k->layout, NULL);
        vkDestroyDescriptorSetLayout(ctx->device, k->set_layout, NULL);
        vkDestroyShaderModule(ctx->device, k->module, NULL);
        free(k); return (int)r;
    }
    ctx->live_kernels++;
    *out = k;
    return 0;
}

VKH_EXPORT void vkh_kernel_destroy(vkh_ctx *ctx, vkh_kernel *k) {
    if (!k) return;
    vkDestroyPipeline(ctx->device, k->pipeline, NULL);
    vkDestroyPipelineLayout(ctx->device, k->layout, NULL);
    vkDestroyDescriptorSetLayout(ctx->device, k->set_layout, NULL);
    vkDestroyShaderModule(ctx->device, k->module, NULL);
    ctx->live_kernels--;
    free(k);
}

static void begin_if_needed(vkh_ctx *ctx) {
    if (ctx->recording) return;
    VkCommandBufferBeginInfo bi = { .sType = VK_STRUCTURE_TYPE_COMMAND_BUFFER_BEGIN_INFO, .flags = VK_COMMAND_BUFFER_USAGE_ONE_TIME_SUBMIT_BIT };
    vkBeginCommandBuffer(ctx->cmd, &bi);
    ctx->recording = 1;
    ctx->recorded = 0;
}

/*
 * Records one dispatch of kernel k with buffers[i] (byte range offsets[i] .. offsets[i] + ranges[i]) at the kernel's
 * i-th binding. With indirect != NULL the group counts are read on the device from indirect at indirect_offset.
 */
VKH_EXPORT int vkh_dispatch(vkh_ctx *ctx, vkh_kernel *k, int count, vkh_buffer **buffers, const uint64_t *offsets,
    const uint64_t *ranges, uint32_t gx, uint32_t gy, uint32_t gz, vkh_buffer *indirect, uint64_t indirect_offset) {
    if (count != k->bindings) return -1;
    begin_if_needed(ctx);
    VkDescriptorBufferInfo info[VKH_MAX_BINDINGS];
    VkWriteDescriptorSet writes[VKH_MAX_BINDINGS];
    for (int i = 0; i < count; i++) {
        if (!buffers[i]) return -2;
        info[i] = (VkDescriptorBufferInfo){ .buffer = buffers[i]->buffer, .offset = offsets[i], .range = ranges[i] ? ranges[i] : VK_WHOLE_SIZE };
        writes[i] = (VkWriteDescriptorSet){ .sType = VK_STRUCTURE_TYPE_WRITE_DESCRIPTOR_SET, .dstBinding = k->binding[i],
            .descriptorCount = 1, .descriptorType = k->type[i], .pBufferInfo = &info[i] };
    }
    vkCmdBindPipeline(ctx->cmd, VK_PIPELINE_BIND_POINT_COMPUTE, k->pipeline);
    if (count > 0)
        ctx->push_descriptors(ctx->cmd, VK_PIPELINE_BIND_POINT_COMPUTE, k->layout, 0, (uint32_t)count, writes);
    if (indirect)
        vkCmdDispatchIndirect(ctx->cmd, indirect->buffer, indirect_offset);
    else if (gx > 0 && gy > 0 && gz > 0)
        vkCmdDispatch(ctx->cmd, gx, gy, gz);
    VkMemoryBarrier barrier = { .sType = VK_STRUCTURE_TYPE_MEMORY_BARRIER,
        .srcAccessMask = VK_ACCESS_SHADER_WRITE_BIT,
        .dstAccessMask = VK_ACCESS_SHADER_READ_BIT | VK_ACCESS_SHADER_WRITE_BIT | VK_ACCESS_INDIRECT_COMMAND_READ_BIT
                       | VK_ACCESS_UNIFORM_READ_BIT | VK_ACCESS_HOST_READ_BIT };
    vkCmdPipelineBarrier(ctx->cmd, VK_PIPELINE_STAGE_COMPUTE_SHADER_BIT,
        VK_PIPELINE_STAGE_COMPUTE_SHADER_BIT | VK_PIPELINE_STAGE_DRAW_INDIRECT_BIT | VK_PIPELINE_STAGE_HOST_BIT,
        0, 1, &barrier, 0, NULL, 0, NULL);
    ctx->recorded++;
    return 0;
}

/* Runs what was recorded and waits; *milliseconds is the wall time from submit to the fence. */
VKH_EXPORT int vkh_submit(vkh_ctx *ctx, double *milliseconds) {
    if (milliseconds) *milliseconds = 0.0;
    if (!ctx->recording) return 0;
    vkEndCommandBuffer(ctx->cmd);
    ctx->recording = 0;
    VkSubmitInfo si = { .sType = VK_STRUCTURE_TYPE_SUBMIT_INFO, .commandBufferCount = 1, .pCommandBuffers = &ctx->cmd };
    struct timespec t0, t1;
    clock_gettime(CLOCK_MONOTONIC, &t0);
    VkResult r = vkQueueSubmit(ctx->queue, 1, &si, ctx->fence);
    if (r != VK_SUCCESS) return (int)r;
    r = vkWaitForFences(ctx->device, 1, &ctx->fence, VK_TRUE, UINT64_MAX);
    clock_gettime(CLOCK_MONOTONIC, &t1);
    vkResetFences(ctx->device, 1, &ctx->fence);
    vkResetCommandBuffer(ctx->cmd, 0);
    if (milliseconds) *milliseconds = (double)(t1.tv_sec - t0.tv_sec) * 1e3 + (double)(t1.tv_nsec - t0.tv_nsec) * 1e-6;
    return (int)r;
}

VKH_EXPORT void vkh_destroy(vkh_ctx *ctx) {
    if (!ctx) return;
    vkDeviceWaitIdle(ctx->device);
    vkDestroyFence(ctx->device, ctx->fence, NULL);
    vkDestroyCommandPool(ctx->device, ctx->pool, NULL);
    vkDestroyDevice(ctx->device, NULL);
    if (ctx->messenger) {
        PFN_vkDestroyDebugUtilsMessengerEXT destroy = (PFN_vkDestroyDebugUtilsMessengerEXT)
            vkGetInstanceProcAddr(ctx->instance, "vkDestroyDebugUtilsMessengerEXT");
        if (destroy) destroy(ctx->instance, ctx->messenger, NULL);
    }
    vkDestroyInstance(ctx->instance, NULL);
    free(ctx);
}
