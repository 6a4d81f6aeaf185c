// The BSDF/warp validation suite on the GLSL build of core/: every family of tests/bsdf
// (chi-square, consistency, albedo and extremes) with core/ evaluated by bsdf_probe.comp, one
// pipeline per family specialized to the family's BSDFs. Prints the report with p-values, the
// pipeline's compile time and how the device's values compare with the C++ build's at the same
// arguments.
#include <gtest/gtest.h>

#include <chrono>
#include <iomanip>
#include <iostream>
#include <sstream>

#include "cases.h"
#include "core/bsdf/common.h"
#include "gpu_backend/gpu_error.h"
#include "gpu_core_calls.h"
#include "materials.h"
#include "probe_device.h"
#include "scene_access_local.h"
#include "suite_size.h"

namespace tr::bsdf_gpu {
namespace {
namespace tv = twinray::validation;
using namespace bsdf_suite;

std::vector<std::string> families() {
  std::vector<std::string> all = statistical_families();
  for (const std::string& f : extremes_families()) {
    if (std::find(all.begin(), all.end(), f) == all.end()) all.push_back(f);
  }
  return all;
}

void add_features(ProbeVariant& v, const Material& m) {
  v.bsdf_types |= 1u << m.type;
  v.material_flags |= m.flags;
  auto texture = [&](const TexturedValue& t) {
    if (t.texture != NO_INDEX) v.texture_types |= 1u << local_textures().at(t.texture).type;
  };
  texture(m.opacity);
  for (const TexturedValue& p : m.param) texture(p);
}

// The pipeline of a family compiles only the BSDFs, flags and textures its materials use.
ProbeVariant variant_of(const std::string& family) {
  ProbeVariant v;
  for (const StatisticalCase& c : statistical_cases()) {
    if (c.family == family && c.material) add_features(v, c.material());
  }
  for (const ExtremesCase& c : extremes_cases()) {
    if (c.family == family) add_features(v, c.material());
  }
  return v;
}

// Opens the device (a missing one fails the test with what is missing) and builds the pipeline.
#define OPEN_DEVICE_OR_FAIL(device, variant, compile_seconds)                                     \
  std::unique_ptr<ProbeDevice> device;                                                            \
  try {                                                                                           \
    device = std::make_unique<ProbeDevice>();                                                     \
  } catch (const std::runtime_error& e) {                                                         \
    FAIL() << "the GPU BSDF suite needs a usable Vulkan device (lavapipe will do): " << e.what(); \
  }                                                                                               \
  compile_seconds = device->build(variant);                                                       \
  std::cout << "device: " << device->device_name()                                                \
            << "; bsdf_probe.comp specialized to BSDF mask 0x" << std::hex << variant.bsdf_types  \
            << ", flags 0x" << variant.material_flags << ", textures 0x" << variant.texture_types \
            << std::dec << ": pipeline compiled in " << compile_seconds << " s\n";

class GpuFamily : public testing::TestWithParam<std::string> {};

TEST_P(GpuFamily, PassesAtSidakLevelOnDevice) {
  const std::string family = GetParam();
  auto start = std::chrono::steady_clock::now();
  double compile_seconds = 0.0;
  const ProbeVariant variant = variant_of(family);
  OPEN_DEVICE_OR_FAIL(device, variant, compile_seconds);
  GpuCoreCalls calls(*device);

  // Every statistical case runs on the device: the Šidák level is the CPU suite's.
  const double alpha = alpha_per_test();
  std::cout << (full_size() ? "full" : "fast") << " size; " << statistical_test_count()
            << " statistical tests at overall significance " << kSignificance
            << ", Sidak level per test alpha = " << alpha << "\n";
  tv::Report report;
  Lockstep statistical;
  std::ostringstream per_case;
  std::size_t number = 0;
  for (const StatisticalCase& c : statistical_cases()) {
    ++number;
    if (c.family != family) continue;
    tv::Report r = run_statistical_case(c, number, alpha, gpu_suite_size(), calls);
    Lockstep l = calls.take_lockstep();
    per_case << "  " << std::left << std::setw(46) << r.checks.front().bsdf << l.differences()
             << "\n";
    statistical.merge(l);
    report.append(r);
  }
  tv::Report extremes;
  number = 0;
  for (const ExtremesCase& c : extremes_cases()) {
    ++number;
    if (c.family == family) extremes.append(run_extremes_case(c, number, gpu_suite_size(), calls));
  }
  Lockstep extreme = calls.take_lockstep();

  report.print(std::cout);
  tv::Report failed_extremes;
  for (const tv::CheckResult& c : extremes.checks) {
    if (!c.passed) failed_extremes.checks.push_back(c);
  }
  std::cout << "extremes: " << extremes.checks.size() << " parameter settings, "
            << failed_extremes.checks.size() << " failing\n";
  failed_extremes.print(std::cout);
  std::cout << "GPU vs C++ (the same core/ compiled as C++) at the same arguments, per case:\n"
            << per_case.str();
  std::cout << "statistical checks: " << statistical.summary() << "\n";
  std::cout << "extremes checks: " << extreme.summary() << "\n";
  std::cout << "family " << family << ": pipeline " << compile_seconds << " s, total "
            << std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count()
            << " s\n";

  EXPECT_FALSE(report.checks.empty() && extremes.checks.empty());
  EXPECT_TRUE(report.passed()) << "see the FAIL rows above";
  EXPECT_TRUE(failed_extremes.checks.empty()) << "see the FAIL rows above";
  EXPECT_EQ(statistical.non_finite + extreme.non_finite, 0u)
      << "the device returned NaN or Inf: " << statistical.first_non_finite
      << extreme.first_non_finite;
}

INSTANTIATE_TEST_SUITE_P(Suite, GpuFamily, testing::ValuesIn(families()),
                         [](const testing::TestParamInfo<std::string>& i) { return i.param; });

// The deliberately broken variant of the shader (every smooth density off by |cos theta_o|)
// must fail the chi-square through the same path, at the suite's own level.
TEST(GpuBrokenBsdf, PdfOffByCosineFailsChiSquare) {
  ProbeVariant variant;
  variant.bsdf_types = 1u << BSDF_DIFFUSE;
  variant.pdf_off_by_cosine = true;
  double compile_seconds = 0.0;
  OPEN_DEVICE_OR_FAIL(device, variant, compile_seconds);
  GpuCoreCalls calls(*device);
  tv::ValidationOptions o = validation_options(gpu_suite_size(), alpha_per_test());
  o.run_check = [&calls](const std::function<void()>& check) { calls.run_check(check); };
  const std::vector<glm::vec3> incident = {tv::direction_from_angles(30.0, 20.0),
                                           tv::direction_from_angles(85.0, 20.0)};
  tv::Report r = tv::validate_bsdf(
      core_bsdf("GPU diffuse, pdf off by cos", diffuse(vec3(0.8f)), calls), incident, o);
  r.print(std::cout);
  std::cout << calls.take_lockstep().summary() << "\n";
  std::size_t chi2_failures = 0;
  for (const tv::CheckResult& c : r.checks) chi2_failures += c.check == "chi2" && !c.passed;
  EXPECT_EQ(chi2_failures, incident.size());
}

}  // namespace
}  // namespace tr::bsdf_gpu
