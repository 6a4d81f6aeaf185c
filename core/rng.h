// Counter-based random numbers: every value is a pure function of
// (seed, pixel, sample index, dimension), so images do not depend on thread count, tiling or
// dispatch order, and the GPU draws exactly the numbers the CPU draws.
//
// Hash: pcg4d, Jarzynski & Olano, "Hash Functions for GPU Rendering", JCGT 9(3) 2020, §2.4;
// it passes TestU01 BigCrush as a 4D->4D hash. The dimension counter advances by one per
// hash, which yields four 32-bit values; rng_next_1d uses the first, rng_next_2d the first
// two, so consecutive calls never reuse a counter.
//
// The scene's sampler (Rng.sampler_params) decides what a draw is. `independent`: the hash's bits.
// The stratified samplers (core/samplers/) split a pixel's samples into passes of
// sample_count; a draw's point set is fixed per (pixel, pass, dimension, seed) by a second
// hash of (pixel, ~pass, dimension, seed) (~pass keeps it apart from the per-sample hashes of
// the first 2^31 samples), and the per-sample hash supplies the jitter. A 2D draw is one 2D
// point of the sampler, so 1D and 2D draws consume the dimension counter as `independent`.
// `sobol` (core/samplers/sobol.h) hashes (pixel, ~pass, seed) once a sample into Rng.key, and
// the key and the draw into the scrambles of its per-pixel sequence; `zsobol`
// (core/samplers/zsobol.h) correlates the pixels instead: its permutations and scrambles are fixed
// per (pass, dimension, seed) for the whole image.
#ifndef TWINRAY_CORE_RNG_H
#define TWINRAY_CORE_RNG_H

#include "core/samplers/ldsampler.h"
#include "core/samplers/multijitter.h"
#include "core/samplers/orthogonal.h"
#include "core/samplers/sobol.h"
#include "core/samplers/stratified.h"
#include "core/samplers/zsobol.h"

TR_NAMESPACE_BEGIN

struct Rng {
  uint pixel;         // linear pixel index
  uint sample_index;  // sample index within the pixel
  uint seed;
  uint dimension;  // next counter value
  Sampler sampler_params;
  // sobol: the hash of (pixel, pass, seed) its draws' scrambles derive from; zsobol: the pixel's
  // Morton code.
  uint key;
};

INLINE uvec4 pcg4d(uvec4 v) {
  v = v * 1664525u + 1013904223u;
  v.x += v.y * v.w;
  v.y += v.z * v.x;
  v.z += v.x * v.y;
  v.w += v.y * v.z;
  v = v ^ (v >> 16u);
  v.x += v.y * v.w;
  v.y += v.z * v.x;
  v.z += v.x * v.y;
  v.w += v.y * v.z;
  return v;
}

INLINE Rng rng_init(uint pixel, uint sample_index, uint seed) {
  Rng r;
  r.pixel = pixel;
  r.sample_index = sample_index;
  r.seed = seed;
  r.dimension = 0u;
  r.sampler_params.type = SAMPLER_INDEPENDENT;
  r.sampler_params.sample_count = 1u;
  r.sampler_params.resolution = uvec2(1u);
  r.sampler_params.jitter = 1u;
  r.sampler_params.inv_sample_count = 1.0f;
  r.sampler_params.inv_resolution = vec2(1.0f);
  r.key = 0u;
  return r;
}

INLINE Rng rng_init_sampler(uint pixel, uint sample_index, uint seed, Sampler params) {
  Rng r = rng_init(pixel, sample_index, seed);
  r.sampler_params = params;
  if (TR_HAS_SAMPLER(SAMPLER_SOBOL) && params.type == SAMPLER_SOBOL) {
    uint pass = sample_index >> uint(findMSB(params.sample_count));  // a power of 2
    r.key = pcg4d(uvec4(pixel, ~pass, 0xfffffffeu, seed)).x;
  }
  if (TR_HAS_SAMPLER(SAMPLER_ZSOBOL) && params.type == SAMPLER_ZSOBOL) {
    uint y = pixel / params.resolution.x;
    r.key = zsobol_morton(pixel - y * params.resolution.x, y);
  }
  return r;
}

// Top 24 bits scaled by 2^-24: exactly representable, uniform on [0, 1).
INLINE float rng_to_unit_float(uint bits) { return float(bits >> 8u) * 5.9604645e-08f; }

INLINE uvec4 rng_next_bits(INOUT(Rng) r) {
  uvec4 h = pcg4d(uvec4(r.pixel, r.sample_index, r.dimension, r.seed));
  r.dimension += 1u;
  return h;
}

// The hash that fixes the point set of the current pass at the current dimension.
INLINE uvec4 rng_pass_bits(Rng r) {
  uint pass = r.sample_index / r.sampler_params.sample_count;
  return pcg4d(uvec4(r.pixel, ~pass, r.dimension, r.seed));
}

// orthogonal: the row order of the pass, shared by every dimension (the hash of dimension
// 2^32 - 1, which the counter never reaches).
INLINE uint rng_row_permutation(Rng r) {
  uint pass = r.sample_index / r.sampler_params.sample_count;
  return pcg4d(uvec4(r.pixel, ~pass, 0xffffffffu, r.seed)).x;
}

INLINE uint rng_index_in_pass(Rng r) { return r.sample_index % r.sampler_params.sample_count; }

// The same for samplers whose passes are a power of 2 (sobol, zsobol): a mask, not a division.
INLINE uint rng_index_in_binary_pass(Rng r) {
  return r.sample_index & (r.sampler_params.sample_count - 1u);
}

// zsobol: the key of the current (pass, dimension, seed), shared by every pixel; its passes
// are a power of 2.
INLINE uvec4 rng_zsobol_key(Rng r) {
  uint pass = r.sample_index >> uint(findMSB(r.sampler_params.sample_count));
  return pcg4d(uvec4(0x9e3779b9u, ~pass, r.dimension, r.seed));
}

INLINE float rng_next_1d(INOUT(Rng) r) {
  uint type = r.sampler_params.type;
  if ((TR_HAS_SAMPLER(SAMPLER_STRATIFIED) && type == SAMPLER_STRATIFIED) ||
      (TR_HAS_SAMPLER(SAMPLER_MULTIJITTER) && type == SAMPLER_MULTIJITTER)) {
    uvec4 pass_bits = rng_pass_bits(r);
    uint index = rng_index_in_pass(r);
    float j = rng_to_unit_float(rng_next_bits(r).x);
    return stratified_1d(r.sampler_params, index, pass_bits.x, j);
  }
  if (TR_HAS_SAMPLER(SAMPLER_ORTHOGONAL) && type == SAMPLER_ORTHOGONAL) {
    uint dimension = r.dimension;
    uvec4 pass_bits = rng_pass_bits(r);
    uint index = rng_index_in_pass(r);
    float j = rng_to_unit_float(rng_next_bits(r).x);
    return orthogonal_1d(r.sampler_params, index, dimension, rng_row_permutation(r), pass_bits, j);
  }
  if (TR_HAS_SAMPLER(SAMPLER_LDSAMPLER) && type == SAMPLER_LDSAMPLER) {
    uvec4 pass_bits = rng_pass_bits(r);
    uint index = rng_index_in_pass(r);
    r.dimension += 1u;
    return ldsampler_1d(r.sampler_params, index, pass_bits.x, pass_bits.y);
  }
  if (TR_HAS_SAMPLER(SAMPLER_SOBOL) && type == SAMPLER_SOBOL) {
    uint draw = r.dimension;
    r.dimension += 1u;
    return sobol_1d(r.sampler_params, rng_index_in_binary_pass(r), draw, r.key);
  }
  if (TR_HAS_SAMPLER(SAMPLER_ZSOBOL) && type == SAMPLER_ZSOBOL) {
    uvec4 key = rng_zsobol_key(r);
    r.dimension += 1u;
    return zsobol_1d(r.sampler_params, r.key, rng_index_in_binary_pass(r), key);
  }
  return rng_to_unit_float(rng_next_bits(r).x);
}

INLINE vec2 rng_next_2d(INOUT(Rng) r) {
  uint type = r.sampler_params.type;
  if (TR_HAS_SAMPLER(SAMPLER_STRATIFIED) && type == SAMPLER_STRATIFIED) {
    uvec4 pass_bits = rng_pass_bits(r);
    uint index = rng_index_in_pass(r);
    uvec4 h = rng_next_bits(r);
    vec2 j = vec2(rng_to_unit_float(h.x), rng_to_unit_float(h.y));
    return stratified_2d(r.sampler_params, index, pass_bits.x, j);
  }
  if (TR_HAS_SAMPLER(SAMPLER_MULTIJITTER) && type == SAMPLER_MULTIJITTER) {
    uvec4 pass_bits = rng_pass_bits(r);
    uint index = rng_index_in_pass(r);
    uvec4 h = rng_next_bits(r);
    vec2 j = vec2(rng_to_unit_float(h.x), rng_to_unit_float(h.y));
    return multijitter_2d(r.sampler_params, index, uvec3(pass_bits.x, pass_bits.y, pass_bits.z), j);
  }
  if (TR_HAS_SAMPLER(SAMPLER_ORTHOGONAL) && type == SAMPLER_ORTHOGONAL) {
    uint dimension = r.dimension;
    uvec4 pass_bits = rng_pass_bits(r);
    uint index = rng_index_in_pass(r);
    uvec4 h = rng_next_bits(r);
    vec2 j = vec2(rng_to_unit_float(h.x), rng_to_unit_float(h.y));
    return orthogonal_2d(r.sampler_params, index, dimension, rng_row_permutation(r), pass_bits, j);
  }
  if (TR_HAS_SAMPLER(SAMPLER_LDSAMPLER) && type == SAMPLER_LDSAMPLER) {
    uvec4 pass_bits = rng_pass_bits(r);
    uint index = rng_index_in_pass(r);
    r.dimension += 1u;
    return ldsampler_2d(r.sampler_params, index, pass_bits.x, uvec2(pass_bits.y, pass_bits.z));
  }
  if (TR_HAS_SAMPLER(SAMPLER_SOBOL) && type == SAMPLER_SOBOL) {
    uint draw = r.dimension;
    r.dimension += 1u;
    return sobol_2d(r.sampler_params, rng_index_in_binary_pass(r), draw, r.key);
  }
  if (TR_HAS_SAMPLER(SAMPLER_ZSOBOL) && type == SAMPLER_ZSOBOL) {
    uvec4 key = rng_zsobol_key(r);
    r.dimension += 1u;
    return zsobol_2d(r.sampler_params, r.key, rng_index_in_binary_pass(r), key);
  }
  uvec4 h = rng_next_bits(r);
  return vec2(rng_to_unit_float(h.x), rng_to_unit_float(h.y));
}

TR_NAMESPACE_END

#endif
