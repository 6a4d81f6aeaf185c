#include "gpu_backend/vulkan_api.h"

#include <dlfcn.h>

#include <mutex>
#include <string>

#include "render/render.h"

#define TWINRAY_DEFINE_VULKAN_FUNCTION(name) PFN_##name name = nullptr;
TWINRAY_VULKAN_FUNCTIONS(TWINRAY_DEFINE_VULKAN_FUNCTION)
#undef TWINRAY_DEFINE_VULKAN_FUNCTION

namespace tr {

namespace {

// The loader's soname (Vulkan loader interface, Linux).
const char* const kLoader = "libvulkan.so.1";

std::string load_functions() {
  void* loader = dlopen(kLoader, RTLD_NOW | RTLD_LOCAL);
  if (!loader) return std::string("cannot load the Vulkan loader: ") + dlerror();
#define TWINRAY_LOAD_VULKAN_FUNCTION(name)                   \
  name = reinterpret_cast<PFN_##name>(dlsym(loader, #name)); \
  if (!name) return std::string("the Vulkan loader ") + kLoader + " lacks " + #name;
  TWINRAY_VULKAN_FUNCTIONS(TWINRAY_LOAD_VULKAN_FUNCTION)
#undef TWINRAY_LOAD_VULKAN_FUNCTION
  return "";
}

}  // namespace

void load_vulkan() {
  static std::once_flag once;
  static std::string failure;
  std::call_once(once, [] { failure = load_functions(); });
  if (!failure.empty()) throw BackendUnavailable(failure + "; use --backend cpu");
}

}  // namespace tr
