#include "cpu_backend/embree_scene.h"

#include <atomic>
#include <cmath>
#include <cstdint>
#include <limits>
#include <stdexcept>
#include <string>

#include "core/alpha_test.h"
#include "core/shapes/bounds.h"
#include "core/shapes/intersect.h"

namespace tr {
namespace {

using UserShape = EmbreeScene::UserShape;

std::atomic<RayRecorder*> new_scene_recorder{nullptr};

// Embree reports errors through this callback (exceptions must not cross its C frames);
// the constructor turns a recorded error into an exception after each commit.
void error_callback(void* user, RTCError code, const char* message) {
  auto* last = static_cast<std::string*>(user);
  if (last->empty())
    *last = "Embree error " + std::to_string(int(code)) + ": " + (message ? message : "");
}

void bounds_callback(const RTCBoundsFunctionArguments* args) {
  const auto* user = static_cast<const UserShape*>(args->geometryUserPtr);
  args->bounds_o->lower_x = user->lower.x;
  args->bounds_o->lower_y = user->lower.y;
  args->bounds_o->lower_z = user->lower.z;
  args->bounds_o->upper_x = user->upper.x;
  args->bounds_o->upper_y = user->upper.y;
  args->bounds_o->upper_z = user->upper.z;
}

void intersect_callback(const RTCIntersectFunctionNArguments* args) {
  if (!args->valid[0]) return;
  const auto* user = static_cast<const UserShape*>(args->geometryUserPtr);
  RTCRayHit* rh = reinterpret_cast<RTCRayHit*>(args->rayhit);
  vec3 o(rh->ray.org_x, rh->ray.org_y, rh->ray.org_z);
  vec3 d(rh->ray.dir_x, rh->ray.dir_y, rh->ray.dir_z);
  float t;
  if (!intersect_shape(user->shape, o, d, rh->ray.tnear, rh->ray.tfar, t)) return;
  rh->ray.tfar = t;
  rh->hit.u = 0.0f;
  rh->hit.v = 0.0f;
  rh->hit.Ng_x = rh->hit.Ng_y = 0.0f;
  rh->hit.Ng_z = 1.0f;
  rh->hit.primID = args->primID;
  rh->hit.geomID = args->geomID;
  rh->hit.instID[0] = args->context->instID[0];
}

void occluded_callback(const RTCOccludedFunctionNArguments* args) {
  if (!args->valid[0]) return;
  const auto* user = static_cast<const UserShape*>(args->geometryUserPtr);
  RTCRay* ray = reinterpret_cast<RTCRay*>(args->ray);
  vec3 o(ray->org_x, ray->org_y, ray->org_z);
  vec3 d(ray->dir_x, ray->dir_y, ray->dir_z);
  float t;
  if (intersect_shape(user->shape, o, d, ray->tnear, ray->tfar, t))
    ray->tfar = -std::numeric_limits<float>::infinity();
}

// Intersection and occlusion filter of an alpha-tested mesh (core/alpha_test.h); the geometry's
// user pointer holds its shape index.
void alpha_test_filter(const RTCFilterFunctionNArguments* args) {
  const uint shape = uint(reinterpret_cast<uintptr_t>(args->geometryUserPtr));
  for (unsigned i = 0; i < args->N; ++i) {
    if (args->valid[i] == 0) continue;
    vec2 b(RTCHitN_u(args->hit, args->N, i), RTCHitN_v(args->hit, args->N, i));
    if (alpha_test_cuts(shape, RTCHitN_primID(args->hit, args->N, i), b)) args->valid[i] = 0;
  }
}

// Bounds of the canonical analytic shape mapped by the shape's to_world.
void analytic_bounds(const Shape& s, vec3& lower, vec3& upper) {
  analytic_shape_bounds(s, lower, upper);
  vec3 pad = 1e-5f * (upper - lower) + vec3(1e-6f);  // bounds must contain rounded hits
  lower -= pad;
  upper += pad;
}

}  // namespace

void EmbreeScene::record_new_scenes(RayRecorder* recorder) { new_scene_recorder = recorder; }

EmbreeScene::EmbreeScene(const SceneBuffers& buffers, bool robust)
    : buffers_(buffers), robust_(robust), recorder_(new_scene_recorder) {
  device_ = rtcNewDevice(nullptr);
  if (!device_) throw std::runtime_error("Embree: cannot create a device");
  rtcSetDeviceErrorFunction(device_, error_callback, &error_);
  root_ = new_scene();
  for (uint i = 0; i < buffers.instances.size(); ++i) {
    const Instance& inst = buffers.instances[i];
    if (i == 0) {
      add_shapes(root_, inst.first_shape, inst.shape_count);
      for (uint s = 0; s < inst.shape_count; ++s) record_root_geometry(s, inst.first_shape + s, 0);
      continue;
    }
    RTCGeometry g = rtcNewGeometry(device_, RTC_GEOMETRY_TYPE_INSTANCE);
    rtcSetGeometryInstancedScene(g, group_scene(inst.first_shape, inst.shape_count));
    float xfm[12];  // RTC_FORMAT_FLOAT3X4_ROW_MAJOR
    for (int r = 0; r < 3; ++r)
      for (int c = 0; c < 4; ++c) xfm[r * 4 + c] = inst.to_world[r][c];
    rtcSetGeometryTransform(g, 0, RTC_FORMAT_FLOAT3X4_ROW_MAJOR, xfm);
    rtcCommitGeometry(g);
    record_root_geometry(rtcAttachGeometry(root_, g), NO_INDEX, i);
    rtcReleaseGeometry(g);
  }
  commit(root_);
  if (recorder_) recorder_->scene_built(*this);
}

RTCScene EmbreeScene::new_scene() {
  RTCScene scene = rtcNewScene(device_);
  rtcSetSceneFlags(scene, robust_ ? RTC_SCENE_FLAG_ROBUST : RTC_SCENE_FLAG_NONE);
  rtcSetSceneBuildQuality(scene, RTC_BUILD_QUALITY_HIGH);
  return scene;
}

void EmbreeScene::commit(RTCScene scene) {
  rtcCommitScene(scene);
  if (!error_.empty()) throw std::runtime_error(error_);
}

RTCScene EmbreeScene::group_scene(uint first_shape, uint shape_count) {
  for (const Group& g : groups_)
    if (g.first_shape == first_shape && g.shape_count == shape_count) return g.scene;
  RTCScene scene = new_scene();
  add_shapes(scene, first_shape, shape_count);
  commit(scene);
  groups_.push_back({first_shape, shape_count, scene});
  return scene;
}

void EmbreeScene::record_root_geometry(uint id, uint shape, uint instance) {
  if (root_geometry_shape_.size() <= id) {
    root_geometry_shape_.resize(id + 1, NO_INDEX);
    root_geometry_instance_.resize(id + 1, NO_INDEX);
  }
  root_geometry_shape_[id] = shape;
  root_geometry_instance_[id] = instance;
}

void EmbreeScene::add_shapes(RTCScene scene, uint first_shape, uint shape_count) {
  for (uint s = first_shape; s < first_shape + shape_count; ++s) {
    const Shape& shape = buffers_.shapes[s];
    RTCGeometry g;
    if (shape.type == SHAPE_MESH) {
      g = rtcNewGeometry(device_, RTC_GEOMETRY_TYPE_TRIANGLE);
      rtcSetSharedGeometryBuffer(
          g, RTC_BUFFER_TYPE_VERTEX, 0, RTC_FORMAT_FLOAT3, buffers_.positions.data(),
          size_t(shape.first_vertex) * sizeof(vec4), sizeof(vec4), shape.vertex_count);
      rtcSetSharedGeometryBuffer(g, RTC_BUFFER_TYPE_INDEX, 0, RTC_FORMAT_UINT3,
                                 buffers_.indices.data(), size_t(shape.first_index) * sizeof(uint),
                                 3 * sizeof(uint), shape.triangle_count);
      if (buffers_.materials[shape.material].flags & MATERIAL_ALPHA_TESTED) {
        rtcSetGeometryUserData(g, reinterpret_cast<void*>(uintptr_t(s)));
        rtcSetGeometryIntersectFilterFunction(g, alpha_test_filter);
        rtcSetGeometryOccludedFilterFunction(g, alpha_test_filter);
      }
    } else {
      auto user = std::make_unique<UserShape>();
      user->shape = s;
      analytic_bounds(shape, user->lower, user->upper);
      g = rtcNewGeometry(device_, RTC_GEOMETRY_TYPE_USER);
      rtcSetGeometryUserPrimitiveCount(g, 1);
      rtcSetGeometryUserData(g, user.get());
      rtcSetGeometryBoundsFunction(g, bounds_callback, nullptr);
      rtcSetGeometryIntersectFunction(g, intersect_callback);
      rtcSetGeometryOccludedFunction(g, occluded_callback);
      user_shapes_.push_back(std::move(user));
    }
    rtcCommitGeometry(g);
    rtcAttachGeometryByID(scene, g, s - first_shape);
    rtcReleaseGeometry(g);
  }
}

EmbreeScene::~EmbreeScene() {
  for (Group& g : groups_) rtcReleaseScene(g.scene);
  if (root_) rtcReleaseScene(root_);
  if (device_) rtcReleaseDevice(device_);
}

Hit EmbreeScene::intersect(const Ray& ray) const {
  Hit hit = trace_closest(ray);
  if (recorder_) recorder_->closest(ray, hit);
  return hit;
}

bool EmbreeScene::occluded(const Ray& ray) const {
  bool blocked = trace_occluded(ray);
  if (recorder_) recorder_->shadow(ray, blocked);
  return blocked;
}

Hit EmbreeScene::trace_closest(const Ray& ray) const {
  RTCIntersectContext context;
  rtcInitIntersectContext(&context);
  RTCRayHit rh = embree_ray_hit(ray);
  rtcIntersect1(root_, &context, &rh);
  if (rh.hit.geomID == RTC_INVALID_GEOMETRY_ID) return miss_hit();
  Hit hit = miss_hit();
  if (rh.hit.instID[0] == RTC_INVALID_GEOMETRY_ID) {
    hit.instance = 0;
    hit.shape = root_geometry_shape_[rh.hit.geomID];
  } else {
    hit.instance = root_geometry_instance_[rh.hit.instID[0]];
    hit.shape = buffers_.instances[hit.instance].first_shape + rh.hit.geomID;
  }
  hit.primitive = rh.hit.primID;
  hit.t = rh.ray.tfar;
  hit.barycentrics = vec2(rh.hit.u, rh.hit.v);
  return hit;
}

bool EmbreeScene::trace_occluded(const Ray& ray) const {
  RTCIntersectContext context;
  rtcInitIntersectContext(&context);
  RTCRay r = embree_ray(ray);
  rtcOccluded1(root_, &context, &r);
  return r.tfar < 0.0f;
}

}  // namespace tr
