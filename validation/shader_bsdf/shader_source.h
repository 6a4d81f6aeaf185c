// The user's shader file for `twinray check-bsdf` (issue 16): read, scanned for its parameter
// declarations, wrapped in a compute shader and compiled with glslangValidator at run time.
// See README.md for the user's contract.
#pragma once

#include <cstdint>
#include <stdexcept>
#include <string>
#include <vector>

namespace tr::shader_bsdf {

// The shader does not compile: `message` holds glslang's errors, each as "FILE:LINE: what".
struct ShaderCompileError : std::runtime_error {
  using std::runtime_error::runtime_error;
};

// A parameter the user's file declares with `#pragma twinray_param NAME DEFAULT`.
struct ShaderParameter {
  std::string name;
  float default_value = 0.0f;
};

// The user's file, read and scanned for its parameter declarations. Throws std::runtime_error
// "FILE:LINE: what" for an unreadable file or a malformed declaration.
struct ShaderSource {
  std::string path;
  std::string text;
  std::vector<ShaderParameter> parameters;  // in declaration order
  bool hlsl = false;                        // FILE.hlsl: glslang's HLSL front end
};
ShaderSource read_shader_source(const std::string& path);

// The generated compute shader around the user's file (exposed for the README and tests).
std::string wrapper_source(const ShaderSource& source, const std::string& include_name);

// Compiles the wrapped file to SPIR-V (vulkan1.2) with glslangValidator (the path configured at
// build time, or $TWINRAY_GLSLANG_VALIDATOR). Throws ShaderCompileError with glslang's errors.
std::vector<uint32_t> compile_shader(const ShaderSource& source);

}  // namespace tr::shader_bsdf
