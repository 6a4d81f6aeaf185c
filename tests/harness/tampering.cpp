#include "tampering.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>

#include "core/material_slots.h"

namespace tr {
namespace testing {

uint find_diffuse_material(const Scene& scene, vec3 rgb) {
  const std::vector<Material>& ms = scene.buffers.materials;
  uint found = NO_INDEX;
  for (uint i = 0; i < ms.size(); ++i) {
    const TexturedValue& r = ms[i].param[DIFFUSE_REFLECTANCE];
    if (ms[i].type != BSDF_DIFFUSE || ms[i].flags != 0u || r.texture != NO_INDEX) continue;
    if (std::abs(r.value.x - rgb.x) > 1e-6f || std::abs(r.value.y - rgb.y) > 1e-6f ||
        std::abs(r.value.z - rgb.z) > 1e-6f)
      continue;
    if (found != NO_INDEX) throw std::runtime_error("more than one matching diffuse material");
    found = i;
  }
  if (found == NO_INDEX) throw std::runtime_error("no matching diffuse material");
  return found;
}

void scale_diffuse_reflectance(Scene& scene, uint material, float factor) {
  scene.buffers.materials.at(material).param[DIFFUSE_REFLECTANCE].value *= factor;
}

namespace {

const Shape& only_mesh_using(const Scene& scene, uint material) {
  const Shape* found = nullptr;
  for (const Shape& s : scene.buffers.shapes) {
    if (s.material != material) continue;
    if (found || s.type != SHAPE_MESH) throw std::runtime_error("material not on exactly one mesh");
    found = &s;
  }
  if (!found) throw std::runtime_error("no shape uses the material");
  if ((found->flags & SHAPE_HAS_UVS) == 0u || (found->flags & SHAPE_HAS_NORMALS) == 0u)
    throw std::runtime_error("the mesh needs uvs and shading normals");
  return *found;
}

vec3 only_point_light(const Scene& scene) {
  const Emitter* found = nullptr;
  for (const Emitter& e : scene.buffers.emitters) {
    if (found) throw std::runtime_error("the scene must have exactly one emitter");
    found = &e;
  }
  if (!found || found->type != EMITTER_POINT)
    throw std::runtime_error("the scene must have exactly one point light");
  return found->position;
}

}  // namespace

void drop_diffuse_cosine(Scene& scene, uint material, int width, int height, float min_cos) {
  SceneBuffers& b = scene.buffers;
  if (b.globals.integrator.max_depth != 2)
    throw std::runtime_error("drop_diffuse_cosine needs direct lighting only (max_depth 2)");
  const Shape& mesh = only_mesh_using(scene, material);
  vec3 light = only_point_light(scene);
  vec3 rho = b.materials[material].param[DIFFUSE_REFLECTANCE].value;

  std::vector<vec4> texels(size_t(width) * height, vec4(rho, 1.0f));
  for (uint t = 0; t < mesh.triangle_count; ++t) {
    uint v[3];
    for (int k = 0; k < 3; ++k) v[k] = mesh.first_vertex + b.indices[mesh.first_index + 3 * t + k];
    // Triangle corners in texel coordinates: texel (i, j) covers [i, i+1) x [j, j+1).
    vec2 q[3];
    for (int k = 0; k < 3; ++k) q[k] = b.uvs[v[k]] * vec2(float(width), float(height));
    float det = (q[1].x - q[0].x) * (q[2].y - q[0].y) - (q[2].x - q[0].x) * (q[1].y - q[0].y);
    if (std::abs(det) < 1e-12f) continue;
    int i0 = std::max(0, int(std::floor(std::min({q[0].x, q[1].x, q[2].x}))));
    int i1 = std::min(width - 1, int(std::ceil(std::max({q[0].x, q[1].x, q[2].x}))));
    int j0 = std::max(0, int(std::floor(std::min({q[0].y, q[1].y, q[2].y}))));
    int j1 = std::min(height - 1, int(std::ceil(std::max({q[0].y, q[1].y, q[2].y}))));
    for (int j = j0; j <= j1; ++j)
      for (int i = i0; i <= i1; ++i) {
        vec2 c(float(i) + 0.5f, float(j) + 0.5f);
        float b1 = ((c.x - q[0].x) * (q[2].y - q[0].y) - (q[2].x - q[0].x) * (c.y - q[0].y)) / det;
        float b2 = ((q[1].x - q[0].x) * (c.y - q[0].y) - (c.x - q[0].x) * (q[1].y - q[0].y)) / det;
        float b0 = 1.0f - b1 - b2;
        if (b0 < 0.0f || b1 < 0.0f || b2 < 0.0f) continue;
        vec3 p = b0 * vec3(b.positions[v[0]]) + b1 * vec3(b.positions[v[1]]) +
                 b2 * vec3(b.positions[v[2]]);
        vec3 n = normalize(b0 * vec3(b.normals[v[0]]) + b1 * vec3(b.normals[v[1]]) +
                           b2 * vec3(b.normals[v[2]]));
        if ((mesh.flags & SHAPE_FLIP_NORMALS) != 0u) n = -n;
        float cos_i = dot(n, normalize(light - p));
        if (cos_i > 0.0f)
          texels[size_t(j) * width + i] = vec4(rho / std::max(cos_i, min_cos), 1.0f);
      }
  }

  Texture tex{};
  tex.type = TEXTURE_BITMAP;
  tex.filter_mode = FILTER_BILINEAR;
  tex.wrap_mode = WRAP_REPEAT;
  tex.texel_offset = uint(b.texels.size());
  tex.width = uint(width);
  tex.height = uint(height);
  tex.to_uv[0] = vec4(1.0f, 0.0f, 0.0f, 0.0f);
  tex.to_uv[1] = vec4(0.0f, 1.0f, 0.0f, 0.0f);
  b.texels.insert(b.texels.end(), texels.begin(), texels.end());
  b.materials[material].param[DIFFUSE_REFLECTANCE].texture = uint(b.textures.size());
  b.materials[material].flags |= MATERIAL_TEXTURED;
  b.textures.push_back(tex);
}

void scale_patch(RgbImage& img, int x0, int y0, int size, double factor) {
  for (int y = y0; y < y0 + size; ++y)
    for (int x = x0; x < x0 + size; ++x)
      for (int c = 0; c < 3; ++c) img.at(x, y, c) *= factor;
}

}  // namespace testing
}  // namespace tr
