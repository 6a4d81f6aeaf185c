// Mitsuba 3's `aov` integrator (src/integrators/aov.cpp): output variables of the surface the
// camera ray hits first, one vec3 per variable and camera sample, entering its pixel's estimate
// like the colour does (with the sample's film sign, core/film.h), so each AOV is the
// filter-weighted mean over the pixel as Mitsuba's film channels are. Where the ray misses,
// every variable is zero (Mitsuba zeroes the invalid SurfaceInteraction). The variables draw
// no random numbers: the nested integrator sees the numbers it sees without them.
//
//   if (scene_globals().integrator.aov_count > 0u) {
//     Hit hit = <closest hit of s.ray right after integrator_begin, or miss_hit()>;
//     AovPoint a = aov_point(s.ray, hit);
//     for i < aov_count: <accumulate aov_value(scene_aov_type(i), a) like the radiance>
//   }
#ifndef TWINRAY_CORE_INTEGRATORS_AOV_H
#define TWINRAY_CORE_INTEGRATORS_AOV_H

#include "core/bsdf.h"
#include "core/interaction.h"

TR_NAMESPACE_BEGIN

// The camera ray's first hit as the AOVs read it.
struct AovPoint {
  Hit hit;
  SurfaceInteraction si;
};

INLINE AovPoint aov_point(IN(Ray) ray, IN(Hit) hit) {
  AovPoint a;
  a.hit = hit;
  if (hit.shape != NO_INDEX) a.si = surface_interaction(ray, hit);
  return a;
}

// Mitsuba's shape_index: 1 + the position in Scene::shapes() of the shape hit, or of the
// instance holding it (0 is the background); see Shape.scene_index.
INLINE float aov_shape_index(IN(Hit) hit) {
  if (hit.instance != 0u) return float(scene_instance(hit.instance).scene_index + 1u);
  return float(scene_shape(hit.shape).scene_index + 1u);
}

// The value of an AOV_* variable; unused components are zero.
INLINE vec3 aov_value(uint type, AovPoint a) {
  if (a.hit.shape == NO_INDEX) return vec3(0.0f);
  SurfaceInteraction si = a.si;
  if (TR_HAS_AOV(AOV_ALBEDO) && type == AOV_ALBEDO)
    return bsdf_diffuse_reflectance(scene_material(si.material), surface_tex_coord(si), si.wi);
  if (TR_HAS_AOV(AOV_DEPTH) && type == AOV_DEPTH) return vec3(si.t, 0.0f, 0.0f);
  if (TR_HAS_AOV(AOV_POSITION) && type == AOV_POSITION) return si.p;
  if (TR_HAS_AOV(AOV_UV) && type == AOV_UV) return vec3(si.uv, 0.0f);
  if (TR_HAS_AOV(AOV_GEO_NORMAL) && type == AOV_GEO_NORMAL) return si.ng;
  if (TR_HAS_AOV(AOV_SH_NORMAL) && type == AOV_SH_NORMAL) return si.frame.n;
  if (TR_HAS_AOV(AOV_PRIM_INDEX) && type == AOV_PRIM_INDEX) {
    uint offset = scene_shape(a.hit.shape).prim_offset;
    return vec3(offset == NO_INDEX ? 0.0f : float(offset + a.hit.primitive), 0.0f, 0.0f);
  }
  if (TR_HAS_AOV(AOV_SHAPE_INDEX) && type == AOV_SHAPE_INDEX)
    return vec3(aov_shape_index(a.hit), 0.0f, 0.0f);
  return vec3(0.0f);
}

TR_NAMESPACE_END

#endif
