// Meaning of Material.param[i] for each BSDF type (Mitsuba 3 parameter names). The loader
// (scenes/) writes these slots, the BSDFs (core/bsdf/) read them; scalar parameters use
// value.x. Roughness slots hold Mitsuba's alpha (already squared from principled roughness
// where the BSDF defines it so).
#ifndef TWINRAY_CORE_MATERIAL_SLOTS_H
#define TWINRAY_CORE_MATERIAL_SLOTS_H

#include "core/prelude.h"

TR_NAMESPACE_BEGIN

// diffuse
const uint DIFFUSE_REFLECTANCE = 0u;

// conductor, roughconductor
const uint CONDUCTOR_ETA = 0u;  // real part of the complex IOR (per RGB channel)
const uint CONDUCTOR_K = 1u;    // imaginary part
const uint CONDUCTOR_SPECULAR_REFLECTANCE = 2u;
const uint CONDUCTOR_ALPHA_U = 3u;  // roughconductor only
const uint CONDUCTOR_ALPHA_V = 4u;

// dielectric, roughdielectric, thindielectric (relative IOR in Material.eta)
const uint DIELECTRIC_SPECULAR_REFLECTANCE = 0u;
const uint DIELECTRIC_SPECULAR_TRANSMITTANCE = 1u;
const uint DIELECTRIC_ALPHA_U = 2u;  // roughdielectric only
const uint DIELECTRIC_ALPHA_V = 3u;

// plastic, roughplastic (relative IOR in Material.eta)
const uint PLASTIC_DIFFUSE_REFLECTANCE = 0u;
const uint PLASTIC_SPECULAR_REFLECTANCE = 1u;
const uint PLASTIC_ALPHA = 2u;  // roughplastic only

// pplastic (diffuse and specular reflectance in the plastic slots above)
const uint PPLASTIC_ALPHA_U = 2u;
const uint PPLASTIC_ALPHA_V = 3u;
const uint PPLASTIC_ETA = 4u;  // relative IOR, a texture in Mitsuba (`eta`)

// principled (Material.eta holds `eta`)
const uint PRINCIPLED_BASE_COLOR = 0u;
const uint PRINCIPLED_ROUGHNESS = 1u;
const uint PRINCIPLED_METALLIC = 2u;
const uint PRINCIPLED_FLATNESS = 3u;
const uint PRINCIPLED_SPEC_TINT = 4u;
const uint PRINCIPLED_ANISOTROPIC = 5u;
const uint PRINCIPLED_SHEEN = 6u;
const uint PRINCIPLED_SHEEN_TINT = 7u;
const uint PRINCIPLED_CLEARCOAT = 8u;
const uint PRINCIPLED_CLEARCOAT_GLOSS = 9u;
const uint PRINCIPLED_SPEC_TRANS = 10u;
// value = (diffuse_reflectance_sampling_rate, main_specular_sampling_rate,
//          clearcoat_sampling_rate), never textured
const uint PRINCIPLED_SAMPLING_RATES = 11u;

// blendbsdf: weight (scalar texture); child material indices in value.x (exact as floats)
const uint BLEND_WEIGHT = 0u;
const uint BLEND_BSDF_0 = 1u;
const uint BLEND_BSDF_1 = 2u;
const uint BLEND_MAX_DEPTH = 7u;  // levels of nested blends (core/bsdf/blend.h's stack)

// normalmap: the normal texture (RGB, n = 2 rgb - 1); the child material index in value.x;
// value = (flip_invalid_normals, use_shadowing_function, 0) as 0 / 1, never textured
const uint NORMALMAP_NORMALMAP = 0u;
const uint NORMALMAP_BSDF = 1u;
const uint NORMALMAP_OPTIONS = 2u;

// bumpmap: the height texture (scalar, read through its uv gradient); the child material index
// in value.x; value = (flip_invalid_normals, use_shadowing_function, scale), never textured.
// The child and option slots are normalmap's (core/bsdf.h reads both adapters alike).
const uint BUMPMAP_HEIGHT = 0u;
const uint BUMPMAP_BSDF = 1u;
const uint BUMPMAP_OPTIONS = 2u;

TR_NAMESPACE_END

#endif
