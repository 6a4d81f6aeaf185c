#include "probe_device.h"

#include "core/bindings.h"
#include "spirv/bsdf_probe.h"

namespace tr::bsdf_gpu {
namespace {

constexpr uint32_t kScene = 0;  // descriptor set of core/bindings.h's bindings
constexpr device_batch::Binding kQueries{1, 0}, kResults{1, 1};

device_batch::KernelLayout probe_layout() {
  device_batch::KernelLayout layout;
  layout.sets = {
      {BINDING_GLOBALS, BINDING_MATERIALS, BINDING_TEXTURES, BINDING_TEXELS, BINDING_EMITTERS,
       BINDING_ALIAS, BINDING_SHAPES, BINDING_INSTANCES, BINDING_POSITIONS, BINDING_NORMALS,
       BINDING_UVS, BINDING_INDICES, BINDING_ATTRIBUTES},
      {kQueries.binding, kResults.binding}};
  layout.queries = kQueries;
  layout.results = kResults;
  layout.workgroup_size = 64;  // local_size_x of bsdf_probe.comp
  return layout;
}

}  // namespace

ProbeDevice::ProbeDevice()
    : kernel_(spirv_bsdf_probe, sizeof(spirv_bsdf_probe), probe_layout(), "", "bsdf_probe.comp") {}

double ProbeDevice::build(const ProbeVariant& variant) {
  // constant_id 0..5: shaders/features.glsl (BSDFs, emitters, shapes, textures, material
  // flags, integrators); 100: the broken variant (bsdf_probe.comp).
  return kernel_.build({{0, variant.bsdf_types},
                        {1, 0u},
                        {2, 0u},
                        {3, variant.texture_types},
                        {4, variant.material_flags},
                        {5, 0u},
                        {100, variant.pdf_off_by_cosine ? 1u : 0u}});
}

void ProbeDevice::evaluate(const ProbeQuery* queries, std::size_t count, const ProbeScene& scene,
                           ProbeResult* results) {
  kernel_.fill({kScene, BINDING_MATERIALS}, *scene.materials);
  kernel_.fill({kScene, BINDING_TEXTURES}, *scene.textures);
  kernel_.fill({kScene, BINDING_TEXELS}, *scene.texels);
  kernel_.evaluate(queries, count, results);
}

}  // namespace tr::bsdf_gpu
