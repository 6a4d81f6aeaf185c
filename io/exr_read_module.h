// The entry point of the module that reads EXR files (io/exr_read_module.cpp), as
// io/exr_read.cpp loads it.
#pragma once

#include <string>

#include "io/image_formats.h"

namespace tr {

// Reads `path` into *out once `*check` has accepted its header; returns false with the
// library's message in *error when the file cannot be read. What `check` throws passes through.
using ReadExrFunction = bool (*)(const char* path, const HeaderCheck* check, Samples* out,
                                 std::string* error);
inline constexpr const char* kReadExrSymbol = "twinray_read_exr";

}  // namespace tr
