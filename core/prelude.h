// Language bridge for the polyglot core: every header in core/ compiles as C++17 (with GLM
// supplying the GLSL vocabulary) and as GLSL 4.60 (through GL_GOOGLE_include_directive).
//
// Rules for core/ code, enforced by tests/glsl_core_compile: no references, pointers,
// templates, classes, constructors, recursion or overloading on parameter qualifiers.
// Output parameters use OUT(T)/INOUT(T); functions are declared with INLINE; float
// literals carry an `f` suffix; structs are built field by field.
#ifndef TWINRAY_CORE_PRELUDE_H
#define TWINRAY_CORE_PRELUDE_H

#ifdef __cplusplus
#include <cstdint>
#include <glm/glm.hpp>
#include <glm/gtc/type_ptr.hpp>

#define TR_NAMESPACE_BEGIN namespace tr {
#define TR_NAMESPACE_END }
// A translation unit that compiles the core with feature guards of its own (below), beside
// units that compile it with others, defines TR_FEATURE_VARIANT: its core functions then have
// internal linkage, so that each unit keeps its own instead of the linker merging the
// differently specialized bodies of one name.
#ifdef TR_FEATURE_VARIANT
#define INLINE static inline
#else
#define INLINE inline
#endif
#define OUT(T) T&
#define INOUT(T) T&
// A read-only parameter (IN) or local/returned view (REF) of a scene record: a reference on the
// CPU, where copying the larger records (Material 240 B, SceneGlobals 704 B) at every call cost
// store-forwarding stalls; a value in GLSL, whose calls are inlined and copy nothing.
#define IN(T) const T&
#define REF(T) const T&
#define PRECISE

TR_NAMESPACE_BEGIN
using namespace glm;
using uint = std::uint32_t;
// GLSL's findMSB of a uint through the compiler's intrinsic (GLM's generic version costs about
// as much as a zsobol draw's digit permutations, core/samplers/zsobol.h).
inline int findMSB(uint x) { return x == 0u ? -1 : 31 - __builtin_clz(x); }
TR_NAMESPACE_END

#else  // GLSL

#define TR_NAMESPACE_BEGIN
#define TR_NAMESPACE_END
#define INLINE
#define OUT(T) out T
#define INOUT(T) inout T
#define IN(T) T
#define REF(T) T
#define PRECISE precise
#extension GL_EXT_control_flow_attributes : enable

#endif

// UNROLL asks the shader compiler to unroll a loop of constant trip count (GLSL [[unroll]],
// GL_EXT_control_flow_attributes). The loops that keep one inlined copy of a helper
// (material_at, the texel and attribute fetches) index arrays and struct members with the loop
// counter; unrolled, the indices are constants and the values stay in registers instead of
// local memory (2-3x the H200's throughput on textured scenes). A build with TR_KEEP_LOOPS keeps
// them loops ([[dont_unroll]]): the one for CPU devices (lavapipe), whose LLVM compiles it in half
// the time and runs it as fast (gpu_backend/render_gpu.cpp, BENCHMARKS.md).
#if defined(__cplusplus)
#define UNROLL
#elif defined(TR_KEEP_LOOPS)
#define UNROLL [[dont_unroll]]
#else
#define UNROLL [[unroll]]
#endif

// PRECISE marks a value the shader compiler must compute exactly as written (GLSL `precise`,
// SPIR-V NoContraction): no fused multiply-add and no algebraic rewriting across its uses. A
// sampled direction that is then handed to pdf()/eval() needs it: otherwise the compiler may
// simplify e.g. wi + (2 (wi.m) m - wi) to 2 (wi.m) m and evaluate the density at the exact
// half vector instead of at the rounded direction returned, which at grazing angles (wi + wo
// nearly cancelling) differs from pdf(wi, wo) by far more than rounding (found by tests/bsdf_gpu
// on lavapipe). C++ compilers do not rewrite float algebra without fast-math flags.

// Feature guards: a backend that specializes its code to a scene (the GPU pipeline, through
// specialization constants in shaders/features.glsl) defines these before including core/;
// everywhere else every feature is compiled in.
#ifndef TR_HAS_BSDF
#define TR_HAS_BSDF(type) true
#endif
#ifndef TR_HAS_EMITTER
#define TR_HAS_EMITTER(type) true
#endif
#ifndef TR_HAS_SHAPE
#define TR_HAS_SHAPE(type) true
#endif
#ifndef TR_HAS_TEXTURE
#define TR_HAS_TEXTURE(type) true
#endif
#ifndef TR_HAS_MATERIAL_FLAG
#define TR_HAS_MATERIAL_FLAG(flag) true
#endif
#ifndef TR_HAS_INTEGRATOR
#define TR_HAS_INTEGRATOR(type) true
#endif
#ifndef TR_HAS_AOV
#define TR_HAS_AOV(type) true
#endif
#ifndef TR_HAS_SAMPLER
#define TR_HAS_SAMPLER(type) true
#endif
#ifndef TR_HAS_TEXTURED_SLOT
#define TR_HAS_TEXTURED_SLOT(k) true
#endif
#ifndef TR_HAS_EMITTER_SELECTION
#define TR_HAS_EMITTER_SELECTION(s) true
#endif

TR_NAMESPACE_BEGIN

const float PI = 3.14159265358979323846f;
const float INV_PI = 0.31830988618379067154f;
const float INV_TWO_PI = 0.15915494309189533577f;
const float INV_FOUR_PI = 0.07957747154594766788f;
const float FLOAT_MAX = 3.402823466e+38f;
const float ONE_MINUS_EPSILON = 0.99999994f;  // largest float below 1
const uint NO_INDEX = 0xffffffffu;

INLINE float sqr(float x) { return x * x; }

// sqrt/acos guarded against arguments pushed out of their domain by rounding.
INLINE float safe_sqrt(float x) { return sqrt(max(x, 0.0f)); }
INLINE float safe_acos(float x) { return acos(clamp(x, -1.0f, 1.0f)); }
INLINE float safe_asin(float x) { return asin(clamp(x, -1.0f, 1.0f)); }

INLINE float max_component(vec3 v) { return max(v.x, max(v.y, v.z)); }
INLINE float luminance(vec3 rgb) {
  // Rec. 709 / linear sRGB luminance weights (ITU-R BT.709-6, item 3.3).
  return dot(rgb, vec3(0.212671f, 0.715160f, 0.072169f));
}

TR_NAMESPACE_END

#endif
