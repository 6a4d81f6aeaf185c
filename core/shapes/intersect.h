// Ray intersection with the analytic shapes, shared by Embree user geometry (CPU) and the
// intersection shader (GPU). o and d are in the space of the shape's instance; the affine
// map to object space keeps the ray parameter t unchanged (d is not renormalized).
#ifndef TWINRAY_CORE_SHAPES_INTERSECT_H
#define TWINRAY_CORE_SHAPES_INTERSECT_H

#include "core/scene_access.h"
#include "core/shapes/cylinder.h"
#include "core/shapes/disk.h"
#include "core/shapes/sphere.h"
#include "core/transform.h"

TR_NAMESPACE_BEGIN

INLINE bool intersect_shape(uint shape, vec3 o, vec3 d, float tmin, float tmax, OUT(float) t) {
  REF(Shape) s = scene_shape(shape);
  vec3 oo = transform_point(s.to_object[0], s.to_object[1], s.to_object[2], o);
  vec3 od = transform_vector(s.to_object[0], s.to_object[1], s.to_object[2], d);
  if (TR_HAS_SHAPE(SHAPE_SPHERE) && s.type == SHAPE_SPHERE)
    return intersect_unit_sphere(oo, od, tmin, tmax, t);
  if (TR_HAS_SHAPE(SHAPE_DISK) && s.type == SHAPE_DISK)
    return intersect_unit_disk(oo, od, tmin, tmax, t);
  if (TR_HAS_SHAPE(SHAPE_CYLINDER) && s.type == SHAPE_CYLINDER)
    return intersect_unit_cylinder(oo, od, tmin, tmax, t);
  return false;
}

TR_NAMESPACE_END

#endif
