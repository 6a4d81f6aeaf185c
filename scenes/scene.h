// The host-side scene: the flat device records of core/scene_types.h, built once by the XML
// loader and consumed unchanged by both backends (the CPU reads the vectors, the GPU uploads
// each vector as one storage buffer).
#pragma once

#include <cstddef>
#include <stdexcept>
#include <string>
#include <vector>

#include "core/scene_types.h"

namespace tr {

static_assert(sizeof(Texture) % 16 == 0 && sizeof(Material) % 16 == 0 && sizeof(Shape) % 16 == 0 &&
                  sizeof(Instance) % 16 == 0 && sizeof(Emitter) % 16 == 0 &&
                  sizeof(AliasEntry) % 16 == 0 && sizeof(Camera) % 16 == 0 &&
                  sizeof(SceneGlobals) % 16 == 0,
              "shared records must keep std430 layout");

struct SceneBuffers {
  SceneGlobals globals{};
  std::vector<Material> materials;
  std::vector<Texture> textures;
  std::vector<vec4> texels;  // linear RGBA, all bitmaps back to back
  std::vector<Emitter> emitters;
  std::vector<AliasEntry> alias;       // every alias table back to back
  std::vector<LightNode> light_nodes;  // EMITTER_SELECTION_BVH: the light BVH
  std::vector<Shape> shapes;
  std::vector<Instance> instances;  // instance 0: the top level, identity transform
  std::vector<vec4> positions;      // world space (object space inside shapegroups)
  std::vector<vec4> normals;
  std::vector<vec2> uvs;
  std::vector<uint> indices;
  std::vector<uint> attributes;  // mesh attributes: per-mesh tables, values as float bits
};

struct Scene {
  SceneBuffers buffers;
  std::string path;             // the XML file it was loaded from
  uint spp = 1;                 // sampler `sample_count`, rounded as Mitsuba (scenes/sampler.h)
  uint seed = 0;                // sampler `seed`
  bool film_half = true;        // hdrfilm `component_format` float16 (Mitsuba's default)
  std::string integrator_name;  // e.g. "path", "moment(path)"
  // Mitsuba `aov`: per output variable (Integrator.aov_types order), its EXR channel names.
  std::vector<std::vector<std::string>> aov_channels;
  std::string sample_count_note;  // how sample_count was rounded, empty when it was not
  // <scene> embree_use_robust_intersections: the CPU's Embree traversal in its robust mode
  // (RTC_SCENE_FLAG_ROBUST, against rays that pass between the triangles of a shared edge).
  // Mitsuba's default is false; twinray's is true (scenes/README.md).
  bool robust_intersections = true;
};

// Bad input: `what()` is one line, "file:line: what and why".
class SceneError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

}  // namespace tr
