// Every intersection of a ray with the surface of one shape (not only the closest): the
// density of an area emitter's sampler at a direction sums over all the surface points that
// lie along it, occluded or not. Double precision, brute force over a mesh's triangles.
#pragma once

#include <glm/vec3.hpp>
#include <vector>

#include "scenes/scene.h"

namespace tr {

struct SurfaceHit {
  glm::dvec3 p;  // world-space point
  glm::dvec3 n;  // the normal the emitter sampler reports there (flip_normals applied)
};

// Hits at t > 0 of the ray o + t d with shape `s` of `buffers`.
std::vector<SurfaceHit> surface_hits(const SceneBuffers& buffers, const Shape& s,
                                     const glm::dvec3& o, const glm::dvec3& d);

}  // namespace tr
