#pragma once

namespace tr {

// `twinray check-bsdf FILE.glsl|FILE.hlsl [options]` (argv[0] is the verb): validates a BSDF
// written in GLSL or HLSL by the user (issue 16, validation/shader_bsdf/README.md) with the
// chi-square, consistency, albedo and extremes suites of validation/bsdf, evaluated on a Vulkan
// device. Exit status: 0 every check passed, 1 a check failed, 2 usage error, 3 the shader file
// does not compile or declares a parameter badly, 4 no usable Vulkan device, 5 the JSON report
// could not be written, 6 internal error.
int check_bsdf_command(int argc, char** argv);

}  // namespace tr
