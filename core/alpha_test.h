// twinray's `alphatest` wrapper (MATERIAL_ALPHA_TESTED): the alpha testing of rasterizers and
// real-time ray tracers (glTF 2.0 §3.9.4 alphaMode MASK; DXR/Vulkan any-hit shaders). Where the
// opacity at a hit is below alpha_cutoff the surface is absent for every ray — camera, BSDF and
// shadow rays alike — and elsewhere it is the nested BSDF, fully opaque. Backends call
// alpha_test_cuts from their traversal (an Embree filter function, an any-hit shader) to drop
// such a hit before the closest one is chosen.
//
// This is a different estimator from Mitsuba's `mask` (core/bsdf.h), which passes a ray through
// with probability 1 - opacity as a null BSDF lobe and whose shadow rays see the surface as
// opaque: with a 0/1 opacity texture the two agree for camera and BSDF rays, not for shadow rays.
// Meshes only (scenes/build_shapes.cpp refuses analytic shapes and emitters).
#ifndef TWINRAY_CORE_ALPHA_TEST_H
#define TWINRAY_CORE_ALPHA_TEST_H

#include "core/hit.h"
#include "core/scene_access.h"
#include "core/texture.h"

TR_NAMESPACE_BEGIN

// The mesh uv at barycentrics (b1, b2) of a triangle: the interpolated vertex uvs, or (b1, b2)
// for a mesh without uvs as Mitsuba (src/render/mesh.cpp) and surface_interaction.
INLINE vec2 mesh_hit_uv(IN(Shape) shape, uint primitive, vec2 b) {
  if ((shape.flags & SHAPE_HAS_UVS) == 0u) return b;
  uint base = shape.first_index + 3u * primitive;
  vec2 uv0 = scene_uv(shape.first_vertex + scene_index(base));
  vec2 uv1 = scene_uv(shape.first_vertex + scene_index(base + 1u));
  vec2 uv2 = scene_uv(shape.first_vertex + scene_index(base + 2u));
  return (1.0f - b.x - b.y) * uv0 + b.x * uv1 + b.y * uv2;
}

// Whether a candidate hit on shape `shape` is cut away by its material's alpha test.
INLINE bool alpha_test_cuts(uint shape_index, uint primitive, vec2 barycentrics) {
  if (!TR_HAS_MATERIAL_FLAG(MATERIAL_ALPHA_TESTED)) return false;
  REF(Shape) shape = scene_shape(shape_index);
  REF(Material) m = scene_material(shape.material);
  if ((m.flags & MATERIAL_ALPHA_TESTED) == 0u) return false;
  vec2 uv = mesh_hit_uv(shape, primitive, barycentrics);
  TexCoord c = tex_coord_mesh(uv, shape_index, primitive, barycentrics);
  return eval_textured(m.opacity, c).x < m.alpha_cutoff;
}

TR_NAMESPACE_END

#endif
