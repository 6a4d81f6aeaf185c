#include <iostream>
#include <string>

#include "gpu_backend/device_info.h"
#include "gpu_backend/gpu_error.h"
#include "gpu_backend/render_gpu.h"
#include "gpu_backend/vk_instance.h"

namespace tr {

int devices_command(int argc, char** argv) {
  for (int i = 0; i < argc; ++i) {
    std::string arg = argv[i];
    if (arg == "--help" || arg == "-h") {
      std::cout << "usage: twinray devices\n"
                   "Lists the Vulkan devices and whether the GPU backend can use them.\n";
      return 0;
    }
    std::cerr << "twinray devices: unknown argument '" << arg << "'\n";
    return 2;
  }
  try {
    VulkanInstance instance;
    bool any_usable = false;
    for (const DeviceInfo& d : query_devices(instance.handle())) {
      std::cout << describe(d) << "\n";
      any_usable = any_usable || d.usable();
    }
    if (!any_usable) {
      std::cerr << "twinray devices: no Vulkan device supports ray tracing; use --backend cpu\n";
      return 1;
    }
    return 0;
  } catch (const std::runtime_error& e) {  // GpuError, BackendUnavailable
    std::cerr << "twinray devices: " << e.what() << "\n";
    return 1;
  }
}

}  // namespace tr
