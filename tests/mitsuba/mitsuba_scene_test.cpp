// One Mitsuba test scene of a suite file, rendered on the CPU with the suite's spp and seed
// and judged by the acceptance rule of shared/mitsuba-tests/README.md (its per-pixel and
// per-block tests at family-wise alpha 0.01 each), a failure judged again by a confirmation
// render (validation/harness/mitsuba_acceptance.h); no sample may be NaN or infinite. The gain
// test is printed for information.
// usage: mitsuba_scene_test SUITE NAME   (exit 0 pass, 1 fail, 2 bad input)
#include <cstdio>
#include <exception>

#include "app/run_backend.h"
#include "validation/harness/mitsuba_acceptance.h"
#include "validation/harness/scene_render.h"
#include "validation/harness/suite.h"

int main(int argc, char** argv) {
  if (argc != 3) {
    std::fprintf(stderr, "usage: mitsuba_scene_test SUITE NAME\n");
    return 2;
  }
  try {
    std::vector<tr::SuiteEntry> suite = tr::read_suite(argv[1]);
    const tr::SuiteEntry& e = tr::find_entry(suite, argv[2]);
    tr::Scene scene = tr::load_entry_scene(e);
    const std::uint32_t spp = tr::entry_spp(e, scene), seed = tr::entry_seed(e, scene);
    tr::RgbImage ref = tr::read_rgb(e.reference), var = tr::read_rgb(e.variance);
    // Renders at (n, s) and prints the rule's tests; 1 when they pass, 0 when they fail, -1 when
    // a sample was NaN or infinite (issue 12: every bundled scene renders without one).
    auto judge = [&](std::uint32_t n, std::uint32_t s, const char* what) {
      tr::SceneRender r = tr::render_scene(tr::run_backend, "cpu", scene, n, s);
      tr::AcceptanceResult a = tr::mitsuba_acceptance(r.mean, n, ref, var, e.reference_spp);
      std::printf("%s%s: %s, cpu, %ux%u, %u spp, seed %u, %.2f s\n", e.name.c_str(), what,
                  e.scene.c_str(), r.result.width, r.result.height, n, s, r.result.stats.seconds);
      std::printf("  %s\n  %s\n  %s (information only)\n", tr::describe_test(a.pixel_z).c_str(),
                  tr::describe_test(a.block_z).c_str(), tr::describe_test(a.gain_z).c_str());
      const std::uint64_t nonfinite = r.result.stats.rejected_nonfinite;
      std::printf("  NaN/Inf samples: %llu\n", static_cast<unsigned long long>(nonfinite));
      return nonfinite != 0 ? -1 : a.passed ? 1 : 0;
    };
    int verdict = judge(spp, seed, "");
    if (verdict == 0) {
      std::printf("%s: failed; confirmation render (mitsuba_acceptance.h)\n", e.name.c_str());
      verdict =
          judge(spp * tr::kConfirmationSppFactor, tr::confirmation_seed(seed), " (confirmation)");
    }
    std::printf("%s: %s\n", e.name.c_str(), verdict == 1 ? "PASS" : "FAIL");
    return verdict == 1 ? 0 : 1;
  } catch (const std::exception& ex) {
    std::fprintf(stderr, "mitsuba_scene_test: %s\n", ex.what());
    return 2;
  }
}
