// Test-only stand-in for core/texture.h, on the include path of tests/bsdf only while the real
// header is absent from the checkout. The chi-square suite uses constant parameters; a texture
// lookup here is a test bug and throws.
#ifndef TWINRAY_CORE_TEXTURE_H
#define TWINRAY_CORE_TEXTURE_H

#include <stdexcept>

#include "core/scene_types.h"

TR_NAMESPACE_BEGIN

inline vec3 eval_textured(TexturedValue v, vec2 uv) {
  if (v.texture != NO_INDEX) throw std::logic_error("tests/bsdf: textures are not available");
  return v.value;
}

TR_NAMESPACE_END

#endif
