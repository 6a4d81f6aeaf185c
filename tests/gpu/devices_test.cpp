// Device enumeration and the "no usable device" error paths.
#include <gtest/gtest.h>

#include <functional>
#include <string>

#include "gpu_backend/device_info.h"
#include "gpu_backend/gpu_error.h"
#include "gpu_backend/render_gpu.h"
#include "gpu_backend/vk_instance.h"
#include "test_scene.h"

namespace tr {
namespace {

std::string message_of(const std::function<void()>& f) {
  try {
    f();
  } catch (const BackendUnavailable& e) {
    return e.what();
  }
  return "";
}

TEST(GpuDevices, EnumeratesAUsableRayTracingDevice) {
  VulkanInstance instance;
  EXPECT_EQ(instance.validation_enabled(), validation_requested());
  std::vector<DeviceInfo> devices = query_devices(instance.handle());
  ASSERT_FALSE(devices.empty());
  const DeviceInfo& chosen = select_device(devices, "");
  EXPECT_TRUE(chosen.usable());
  EXPECT_NE(describe(chosen).find("usable"), std::string::npos);
  EXPECT_EQ(&select_device(devices, std::to_string(chosen.index)), &chosen);
}

TEST(GpuDevices, UnknownNameIsAClearError) {
  VulkanInstance instance;
  std::vector<DeviceInfo> devices = query_devices(instance.handle());
  std::string m = message_of([&] { select_device(devices, "no-such-device-xyz"); });
  EXPECT_NE(m.find("no-such-device-xyz"), std::string::npos) << m;
  EXPECT_NE(m.find("--backend cpu"), std::string::npos) << m;
  EXPECT_EQ(m.find('\n'), std::string::npos) << m;
  m = message_of([&] { select_device(devices, "999"); });
  EXPECT_NE(m.find("index 999"), std::string::npos) << m;
}

TEST(GpuDevices, DeviceWithoutRayTracingNamesWhatIsMissing) {
  DeviceInfo cpu_only;
  cpu_only.index = 0;
  cpu_only.name = "Software Rasterizer";
  cpu_only.type = "CPU";
  cpu_only.api_version = "1.3.0";
  cpu_only.missing = {"extension VK_KHR_ray_tracing_pipeline", "feature rayTracingPipeline"};
  std::vector<DeviceInfo> devices = {cpu_only};
  for (const std::string& selector : {std::string(), std::string("0"), std::string("raster")}) {
    std::string m = message_of([&] { select_device(devices, selector); });
    EXPECT_NE(m.find("VK_KHR_ray_tracing_pipeline"), std::string::npos) << m;
    EXPECT_NE(m.find("rayTracingPipeline"), std::string::npos) << m;
    EXPECT_NE(m.find("--backend cpu"), std::string::npos) << m;
  }
  EXPECT_NE(message_of([] { select_device({}, ""); }).find("no Vulkan device"), std::string::npos);
}

TEST(GpuDevices, RenderOnMissingDeviceThrowsInsteadOfCrashing) {
  Scene scene = test::probe_scene(8, 6);
  RenderOptions options;
  options.device = "no-such-device-xyz";
  std::string m = message_of([&] { render_gpu(scene, options); });
  EXPECT_NE(m.find("--backend cpu"), std::string::npos) << m;
}

TEST(GpuDevices, DevicesCommand) {
  char help[] = "--help";
  char bogus[] = "--bogus";
  char* with_help[] = {help};
  char* bad[] = {bogus};
  EXPECT_EQ(devices_command(0, nullptr), 0);
  EXPECT_EQ(devices_command(1, with_help), 0);
  EXPECT_EQ(devices_command(1, bad), 2);
}

}  // namespace
}  // namespace tr
