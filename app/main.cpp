// twinray: the command line. Verbs: render, devices, compare, validate, converge, conformance,
// convert.
#include <cstdio>
#include <cstring>
#include <string>

#include "app/conformance_command.h"
#include "app/convert_command.h"
#include "app/exit_codes.h"
#include "app/render_command.h"
#ifdef TWINRAY_HAS_GPU
#include "app/check_bsdf_command.h"
#include "gpu_backend/render_gpu.h"
#endif
#include "app/compare_command.h"
#include "app/converge_command.h"
#include "app/validate_command.h"

namespace {

const char* kUsage =
    "usage: twinray <verb> [arguments]\n"
    "  render SCENE [options]       render a Mitsuba 3 XML, .scn or glTF scene (twinray render --help)\n"
    "  devices                      list Vulkan devices and whether the GPU backend can use them\n"
    "  compare A.exr B.exr [opts]   compare two renders (twinray compare --help)\n"
    "  validate SUITE [opts]        render a suite on CPU (and GPU), compare, HTML report\n"
    "  converge SCENE [opts]        error against time for render variants (CSV, plot)\n"
    "  conformance FOLDER [opts]    load and render every scene of a folder, sort the outcomes\n"
    "  convert SCENE -o OUT.xml     write a .scn or glTF scene as Mitsuba 3 XML (twinray convert --help)\n"
    "  check-bsdf FILE.glsl [opts]  chi-square/consistency/extremes suites on a GLSL/HLSL BSDF\n"
    "exit status: 0 ok, 1 check failed, 2 usage error, 3 invalid scene, 4 backend unavailable,\n"
    "             5 output not writable, 6 internal error, 7 render interrupted (outputs hold\n"
    "             the samples so far), 8 checkpoint damaged or of another render\n";

}  // namespace

int main(int argc, char** argv) {
  if (argc < 2 || !std::strcmp(argv[1], "--help") || !std::strcmp(argv[1], "-h")) {
    std::fputs(kUsage, argc < 2 ? stderr : stdout);
    return argc < 2 ? tr::kExitUsage : tr::kExitOk;
  }
  std::string verb = argv[1];
  if (verb == "--version") {
    std::printf("twinray %s\n", TWINRAY_VERSION);
    return tr::kExitOk;
  }
  if (verb == "render") return tr::render_command(argc - 2, argv + 2);
#ifdef TWINRAY_HAS_GPU
  if (verb == "devices") return tr::devices_command(argc - 2, argv + 2);
  if (verb == "check-bsdf") return tr::check_bsdf_command(argc - 1, argv + 1);
#endif
  if (verb == "compare") return tr::compare_command(argc - 1, argv + 1);
  if (verb == "validate") return tr::validate_command(argc - 1, argv + 1);
  if (verb == "converge") return tr::converge_command(argc - 1, argv + 1);
  if (verb == "conformance") return tr::conformance_command(argc - 2, argv + 2);
  if (verb == "convert") return tr::convert_command(argc - 2, argv + 2);
  std::fprintf(stderr, "twinray: unknown verb '%s'\n%s", verb.c_str(), kUsage);
  return tr::kExitUsage;
}
