// Embree 3 acceleration structures for a SceneBuffers: triangle geometry for meshes, user
// geometry (core/shapes/intersect.h) for analytic shapes, one child scene per shapegroup
// placed by instance geometries. Answers the two queries the integrators need.
#pragma once

#include <embree3/rtcore.h>

#include <memory>
#include <string>
#include <vector>

#include "core/hit.h"
#include "core/ray.h"
#include "scenes/scene.h"

namespace tr {

class EmbreeScene {
 public:
  explicit EmbreeScene(const SceneBuffers& buffers);
  ~EmbreeScene();
  EmbreeScene(const EmbreeScene&) = delete;
  EmbreeScene& operator=(const EmbreeScene&) = delete;

  Hit intersect(const Ray& ray) const;
  bool occluded(const Ray& ray) const;

  // An analytic shape as Embree user geometry: its index and bounds in instance space.
  struct UserShape {
    uint shape;
    vec3 lower, upper;
  };

 private:
  struct Group {
    uint first_shape;
    uint shape_count;
    RTCScene scene;
  };
  RTCScene new_scene();
  RTCScene group_scene(uint first_shape, uint shape_count);
  // Attaches shapes [first, first + count) to `scene`, geometry IDs in shape order.
  void add_shapes(RTCScene scene, uint first_shape, uint shape_count);
  void record_root_geometry(uint id, uint shape, uint instance);
  void commit(RTCScene scene);

  const SceneBuffers& buffers_;
  RTCDevice device_ = nullptr;
  RTCScene root_ = nullptr;
  std::vector<Group> groups_;
  std::vector<std::unique_ptr<UserShape>> user_shapes_;
  std::string error_;                         // first error Embree reported
  std::vector<uint> root_geometry_shape_;     // root geometry ID -> shape (NO_INDEX: instance)
  std::vector<uint> root_geometry_instance_;  // root geometry ID -> Instance record
};

}  // namespace tr
