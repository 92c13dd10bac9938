#include "flags/cli_common.h"
#include "cli/commands.h"
#include "io/image_io.h"
#include "core/memory_budget.h"
#include <cstdio>

namespace tf {

int run_info(const std::vector<std::string>& argv)
{
    std::vector<FlagSpec> specs = device_flags();
    Args args = parse_args("info", argv, specs, 0);
    if (args.has("--help")) {
        std::fputs(format_help("texfilter info [--device NAME|INDEX] [--validate]", specs).c_str(), stdout);
        return 0;
    }
    ContextOptions options = context_options_from(args);
    VkDebugUtilsMessengerEXT messenger = VK_NULL_HANDLE;
    VkInstance instance = create_instance(options.validate, &messenger);
    std::vector<DeviceInfo> devices = list_devices(instance);
    if (messenger)
        vkDestroyDebugUtilsMessengerEXT(instance, messenger, nullptr);
    destroy_instance(instance);

    std::printf("image I/O: %s\n", image_io_available() ? "OpenImageIO" : "left out of this build");
    for (const DeviceInfo& d : devices) {
        std::printf("[%d] %s (%s)\n", d.index, d.name.c_str(), d.type.c_str());
        std::printf("    driver %s, %s; Vulkan %s\n", d.driver_name.c_str(), d.driver_info.c_str(),
                    version_string(d.api_version).c_str());
        std::printf("    subTexelPrecisionBits %u, mipmapPrecisionBits %u, maxSamplerAnisotropy %g%s, "
                    "maxSamplerLodBias %g, maxImageDimension2D %u\n",
                    d.sub_texel_precision_bits, d.mipmap_precision_bits, d.max_sampler_anisotropy,
                    d.sampler_anisotropy ? "" : " (feature off)", d.max_sampler_lod_bias, d.max_image_dimension_2d);
        std::printf("    device-local heap %u: %s, maxMemoryAllocationSize %s\n", d.device_local_heap_index,
                    format_bytes(d.device_local_heap_size).c_str(), format_bytes(d.max_memory_allocation_size).c_str());
        std::printf("    subgroup size %u, quad ops: fragment %s, compute %s\n", d.subgroup_size,
                    d.quad_ops_fragment ? "yes" : "no", d.quad_ops_compute ? "yes" : "no");
        if (!d.usable)
            std::printf("    not usable: %s\n", d.why_not_usable.c_str());
    }
    int chosen = select_device(devices, options.device);
    std::printf("texfilter would use: [%d] %s\n", chosen, devices[size_t(chosen)].name.c_str());
    check_validation_clean();
    return 0;
}

} // namespace tf
