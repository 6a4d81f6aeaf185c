// Test-only stand-in for core/texture.h, used by tests/bsdf_unit only while the real header
// is absent from the checkout: constant parameters only.
#ifndef TWINRAY_CORE_TEXTURE_H
#define TWINRAY_CORE_TEXTURE_H

#include "core/scene_types.h"

TR_NAMESPACE_BEGIN

INLINE vec3 eval_textured(TexturedValue v, vec2 uv) {
  if (v.texture != NO_INDEX) return vec3(-1.0f);  // textures are not supported here
  return v.value;
}

TR_NAMESPACE_END

#endif
