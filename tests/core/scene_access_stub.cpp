// The core tests here call no scene data but the film tests' camera (film_test_camera.h); the
// other accessors exist only to satisfy the linker (core headers declare them) and fail loudly
// if reached.
#include <cstdio>
#include <cstdlib>

#include "core/scene_access.h"
#include "film_test_camera.h"

namespace tr {
namespace {
[[noreturn]] void unreachable(const char* what) {
  std::fprintf(stderr, "core test touched scene data (%s)\n", what);
  std::abort();
}
Camera g_camera{};
}  // namespace
void bind_film_test_camera(const Camera& c) { g_camera = c; }
const SceneGlobals& scene_globals() { unreachable("globals"); }
const Material& scene_material(uint) { unreachable("material"); }
const Texture& scene_texture(uint) { unreachable("texture"); }
vec4 scene_texel(uint) { unreachable("texel"); }
const Emitter& scene_emitter(uint) { unreachable("emitter"); }
AliasEntry scene_alias(uint) { unreachable("alias"); }
const LightNode& scene_light_node(uint) { unreachable("light node"); }
const Shape& scene_shape(uint) { unreachable("shape"); }
const Instance& scene_instance(uint) { unreachable("instance"); }
vec3 scene_position(uint) { unreachable("position"); }
vec3 scene_normal(uint) { unreachable("normal"); }
vec2 scene_uv(uint) { unreachable("uv"); }
uint scene_index(uint) { unreachable("index"); }
uint scene_attribute(uint) { unreachable("attribute"); }
float scene_filter_table(uint i) { return g_camera.filter_table[i >> 2u][i & 3u]; }
float scene_filter_cdf(uint k) { return g_camera.filter_cdf[k >> 2u][k & 3u]; }
}  // namespace tr
