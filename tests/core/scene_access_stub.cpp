// The core tests here call no scene data; the accessors exist only to satisfy the linker
// (core headers declare them) and fail loudly if reached.
#include <cstdio>
#include <cstdlib>

#include "core/scene_access.h"

namespace tr {
namespace {
[[noreturn]] void unreachable(const char* what) {
  std::fprintf(stderr, "core test touched scene data (%s)\n", what);
  std::abort();
}
}  // namespace
SceneGlobals scene_globals() { unreachable("globals"); }
Material scene_material(uint) { unreachable("material"); }
Texture scene_texture(uint) { unreachable("texture"); }
vec4 scene_texel(uint) { unreachable("texel"); }
Emitter scene_emitter(uint) { unreachable("emitter"); }
AliasEntry scene_alias(uint) { unreachable("alias"); }
Shape scene_shape(uint) { unreachable("shape"); }
Instance scene_instance(uint) { unreachable("instance"); }
vec3 scene_position(uint) { unreachable("position"); }
vec3 scene_normal(uint) { unreachable("normal"); }
vec2 scene_uv(uint) { unreachable("uv"); }
uint scene_index(uint) { unreachable("index"); }
}  // namespace tr
