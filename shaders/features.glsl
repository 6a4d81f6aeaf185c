// Scene feature masks as specialization constants (issue 4: the pipeline models only what
// the scene requires). Included by every stage before core/: bit t of a mask is set when the
// scene uses type t (BSDF_*, EMITTER_*, SHAPE_*, TEXTURE_*, INTEGRATOR_*). The defaults keep
// every feature, so an unspecialized pipeline is the all-features pipeline. core/ code guards
// each type's branch with TR_HAS_*; after specialization the driver folds the guards and drops
// the code of unused types. The host side is scenes/scene_features.h.
#ifndef TWINRAY_SHADERS_FEATURES_GLSL
#define TWINRAY_SHADERS_FEATURES_GLSL

layout(constant_id = 0) const uint SPEC_BSDF_TYPES = 0xffffffffu;
layout(constant_id = 1) const uint SPEC_EMITTER_TYPES = 0xffffffffu;
layout(constant_id = 2) const uint SPEC_SHAPE_TYPES = 0xffffffffu;
layout(constant_id = 3) const uint SPEC_TEXTURE_TYPES = 0xffffffffu;
layout(constant_id = 4) const uint SPEC_MATERIAL_FLAGS = 0xffffffffu;
layout(constant_id = 5) const uint SPEC_INTEGRATOR_TYPES = 0xffffffffu;
layout(constant_id = 6) const uint SPEC_AOV_TYPES = 0xffffffffu;
layout(constant_id = 7) const uint SPEC_SAMPLER_TYPES = 0xffffffffu;
// Bit k: some leaf material textures its parameter slot k (bit MATERIAL_PARAM_COUNT: its mask
// opacity); material_at looks up only these.
layout(constant_id = 8) const uint SPEC_TEXTURED_SLOTS = 0xffffffffu;
// Bit s: the scene chooses emitters by EMITTER_SELECTION_s (core/emitter.h).
layout(constant_id = 9) const uint SPEC_EMITTER_SELECTIONS = 0xffffffffu;

#define TR_HAS_BSDF(type) ((SPEC_BSDF_TYPES & (1u << (type))) != 0u)
#define TR_HAS_EMITTER(type) ((SPEC_EMITTER_TYPES & (1u << (type))) != 0u)
#define TR_HAS_SHAPE(type) ((SPEC_SHAPE_TYPES & (1u << (type))) != 0u)
#define TR_HAS_TEXTURE(type) ((SPEC_TEXTURE_TYPES & (1u << (type))) != 0u)
#define TR_HAS_MATERIAL_FLAG(flag) ((SPEC_MATERIAL_FLAGS & (flag)) != 0u)
#define TR_HAS_INTEGRATOR(type) ((SPEC_INTEGRATOR_TYPES & (1u << (type))) != 0u)
#define TR_HAS_AOV(type) ((SPEC_AOV_TYPES & (1u << (type))) != 0u)
#define TR_HAS_SAMPLER(type) ((SPEC_SAMPLER_TYPES & (1u << (type))) != 0u)
#define TR_HAS_TEXTURED_SLOT(k) ((SPEC_TEXTURED_SLOTS & (1u << (k))) != 0u)
#define TR_HAS_EMITTER_SELECTION(s) ((SPEC_EMITTER_SELECTIONS & (1u << (s))) != 0u)

#endif
