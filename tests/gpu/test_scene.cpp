#include "test_scene.h"

#include <cmath>

namespace tr::test {

namespace {

void set_rows(vec4 rows[3], vec3 scale, vec3 translate) {
  rows[0] = vec4(scale.x, 0.0f, 0.0f, translate.x);
  rows[1] = vec4(0.0f, scale.y, 0.0f, translate.y);
  rows[2] = vec4(0.0f, 0.0f, scale.z, translate.z);
}

void set_affine(vec4 to_world[3], vec4 to_object[3], vec3 scale, vec3 translate) {
  set_rows(to_world, scale, translate);
  set_rows(to_object, 1.0f / scale, -translate / scale);
}

Shape analytic(uint type, vec3 scale, vec3 translate) {
  Shape s{};
  s.type = type;
  s.material = 0;
  s.emitter = NO_INDEX;
  set_affine(s.to_world, s.to_object, scale, translate);
  return s;
}

}  // namespace

Scene probe_scene(uint width, uint height) {
  Scene scene;
  SceneBuffers& b = scene.buffers;
  Camera& c = b.globals.camera;
  set_rows(c.to_world, vec3(1.0f), vec3(0.0f));
  c.type = SENSOR_PERSPECTIVE;
  c.width = width;
  c.height = height;
  c.rfilter = RFILTER_BOX;
  c.film_size = vec2(float(width), float(height));
  c.sample_max = c.film_size;
  const float tan_x = std::tan(0.5f * 60.0f * PI / 180.0f);
  c.half_extent = vec2(tan_x, tan_x * float(height) / float(width));
  c.near_clip = 0.01f;
  c.far_clip = 1000.0f;
  b.globals.integrator.type = INTEGRATOR_PATH;
  b.globals.integrator.max_depth = 4;
  b.globals.integrator.rr_depth = 5;
  b.globals.instance_count = 2;

  Emitter sky{};
  sky.type = EMITTER_CONSTANT;
  sky.shape = NO_INDEX;
  sky.texture = NO_INDEX;
  sky.radiance = vec3(1.0f);
  sky.scale = 1.0f;
  set_rows(sky.to_world, vec3(1.0f), vec3(0.0f));
  set_rows(sky.to_local, vec3(1.0f), vec3(0.0f));
  b.emitters.push_back(sky);
  b.alias.push_back(AliasEntry{1.0f, 0u, 1.0f, 0u});
  b.globals.emitter_count = 1;
  b.globals.emitter_alias_offset = 0;
  b.globals.environment = 0;

  Material diffuse{};
  diffuse.type = BSDF_DIFFUSE;
  diffuse.param[0].value = vec3(0.5f);
  diffuse.param[0].texture = NO_INDEX;
  b.materials.push_back(diffuse);

  b.shapes.push_back(analytic(SHAPE_SPHERE, vec3(1.0f), vec3(0.0f, 0.0f, 5.0f)));
  b.shapes[0].area = 4.0f * PI;

  Shape quad{};
  quad.type = SHAPE_MESH;
  quad.material = 0;
  quad.emitter = NO_INDEX;
  quad.first_index = 0;
  quad.triangle_count = 2;
  quad.first_vertex = 0;
  quad.vertex_count = 4;
  set_affine(quad.to_world, quad.to_object, vec3(1.0f), vec3(0.0f));
  quad.area = 40.0f * 40.0f;
  b.shapes.push_back(quad);
  b.positions = {vec4(-20.0f, -20.0f, 8.0f, 1.0f), vec4(20.0f, -20.0f, 8.0f, 1.0f),
                 vec4(20.0f, 20.0f, 8.0f, 1.0f), vec4(-20.0f, 20.0f, 8.0f, 1.0f)};
  b.normals = {vec4(0.0f, 0.0f, -1.0f, 0.0f), vec4(0.0f, 0.0f, -1.0f, 0.0f),
               vec4(0.0f, 0.0f, -1.0f, 0.0f), vec4(0.0f, 0.0f, -1.0f, 0.0f)};
  b.indices = {0, 2, 1, 0, 3, 2};  // wound so that the normal faces the camera (-z)

  b.shapes.push_back(analytic(SHAPE_DISK, vec3(0.5f), vec3(0.0f, 0.0f, 4.5f)));
  b.shapes[2].area = PI * 0.25f;
  b.shapes[2].flags = SHAPE_FLIP_NORMALS;  // face the camera

  Instance top{};
  set_affine(top.to_world, top.to_object, vec3(1.0f), vec3(0.0f));
  top.first_shape = 0;
  top.shape_count = 2;
  Instance group{};
  set_affine(group.to_world, group.to_object, vec3(1.0f), vec3(1.5f, 0.0f, 0.0f));
  group.first_shape = 2;
  group.shape_count = 1;
  b.instances = {top, group};
  scene.spp = 1;
  return scene;
}

}  // namespace tr::test
