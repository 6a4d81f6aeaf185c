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

class EmbreeScene;

// A Ray as Embree's closest-hit query, no hit yet (EmbreeScene::intersect).
inline RTCRayHit embree_ray_hit(const Ray& ray) {
  RTCRayHit rh;
  rh.ray.org_x = ray.o.x;
  rh.ray.org_y = ray.o.y;
  rh.ray.org_z = ray.o.z;
  rh.ray.tnear = ray.tmin;
  rh.ray.dir_x = ray.d.x;
  rh.ray.dir_y = ray.d.y;
  rh.ray.dir_z = ray.d.z;
  rh.ray.time = 0.0f;
  rh.ray.tfar = ray.tmax;
  rh.ray.mask = 0xffffffffu;
  rh.ray.id = 0;
  rh.ray.flags = 0;
  rh.hit.geomID = RTC_INVALID_GEOMETRY_ID;
  rh.hit.instID[0] = RTC_INVALID_GEOMETRY_ID;
  return rh;
}

// A Ray as Embree's occlusion query (EmbreeScene::occluded); occluded when tfar < 0 after it.
inline RTCRay embree_ray(const Ray& ray) { return embree_ray_hit(ray).ray; }

// Sees every query an EmbreeScene answers, with its answer: how bench/ray_replay.cpp records a
// render's rays. Called concurrently from the rendering threads.
class RayRecorder {
 public:
  virtual ~RayRecorder() = default;
  virtual void scene_built(const EmbreeScene& scene) = 0;
  virtual void closest(const Ray& ray, const Hit& hit) = 0;
  virtual void shadow(const Ray& ray, bool occluded) = 0;
};

class EmbreeScene {
 public:
  // robust: Embree's robust traversal (RTC_SCENE_FLAG_ROBUST), Scene::robust_intersections.
  EmbreeScene(const SceneBuffers& buffers, bool robust);
  ~EmbreeScene();
  EmbreeScene(const EmbreeScene&) = delete;
  EmbreeScene& operator=(const EmbreeScene&) = delete;

  bool robust() const { return robust_; }
  Hit intersect(const Ray& ray) const;
  bool occluded(const Ray& ray) const;

  // Scenes constructed from now on report to `recorder` (nullptr: to none; the default). A
  // process-wide setting because renderers build their EmbreeScene internally; a scene keeps
  // the recorder it was built with, and without one a query costs one untaken branch.
  static void record_new_scenes(RayRecorder* recorder);
  // The root Embree scene, for tracing the recorded queries again (bench/ray_replay.cpp).
  RTCScene rtc_scene() const { return root_; }

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
  Hit trace_closest(const Ray& ray) const;
  bool trace_occluded(const Ray& ray) const;

  const SceneBuffers& buffers_;
  bool robust_;
  RayRecorder* recorder_ = nullptr;
  RTCDevice device_ = nullptr;
  RTCScene root_ = nullptr;
  std::vector<Group> groups_;
  std::vector<std::unique_ptr<UserShape>> user_shapes_;
  std::string error_;                         // first error Embree reported
  std::vector<uint> root_geometry_shape_;     // root geometry ID -> shape (NO_INDEX: instance)
  std::vector<uint> root_geometry_instance_;  // root geometry ID -> Instance record
};

}  // namespace tr
