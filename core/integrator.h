// The integrators, Mitsuba 3's `path` and `direct` and pbrt-v4's `ambientocclusion`
// (core/integrators/ambient_occlusion.h), as one vertex routine every backend drives
// identically:
//
//   PathState s = integrator_begin(pixel, sample_index, seed);
//   while (integrator_alive(s)) {
//     Hit hit = <closest hit of s.ray, or miss_hit()>;
//     ShadowRay sr = integrator_step(s, hit);
//     if (sr.enabled != 0u && <sr.ray unoccluded>) integrator_add_unoccluded(s, sr);
//   }
//   vec3 L = integrator_result(s);   // reject (count, score 0) if !radiance_is_finite(L)
//   <accumulate L with the positive or, if integrator_negative(s), the negative samples>
//
// `path` (src/integrators/path.cpp): unidirectional path tracing; at each vertex one emitter
// sample and one BSDF sample combined by the power heuristic (Veach 1997 §9.2), Russian
// roulette from `rr_depth` on with Mitsuba's survival probability, `max_depth` counting
// scattering events plus one (1: emitters seen directly, 2: direct illumination, -1:
// unbounded), `hide_emitters` letting camera rays pass through area emitters. Beyond Mitsuba,
// `min_depth` (default 1) keeps only the light of paths of at least that many segments, the
// same count as max_depth's: a path of d segments ends on an emitter after d - 1 scattering
// events, found either by the BSDF sample leaving vertex d - 1 or by the emitter sample at it;
// both techniques of a length are kept or dropped together, so their MIS weights still sum to
// one (Veach 1997 §9.2.2, condition W1) and the estimate is the sum over the lengths in
// [min_depth, max_depth].
// Also beyond Mitsuba 3, `strict_normals` (default false) is Mitsuba 0.6's strictNormals of
// `path` and `direct` (strict_normals_* below): a path ends where the geometric and the shading
// normal put the incident direction on different sides, and a direction they put on different
// sides is dropped by both sampling techniques (so their MIS weights still sum to one on the
// directions kept).
// `direct` (src/integrators/direct.cpp): at the camera ray's hit, `emitter_samples` emitter
// samples and `bsdf_samples` BSDF samples combined by the power heuristic with sample counts
// (Veach 1997 eq. 9.13 with n_i p_i). One call scores what the last ray found and then runs
// one sampling round at the shading point: round k traces emitter sample k's shadow ray
// (k < emitter_samples) and BSDF sample k's ray (k < bsdf_samples); rounds past the last
// BSDF sample trace an empty ray (tmax = 0). Unlike Mitsuba, delta emitter samples are
// averaged over `emitter_samples` like the others (Mitsuba weights each of them 1, which
// over-counts point and directional lights when emitter_samples > 1).
//
// Both integrators share one code path, so each BSDF, emitter and surface routine is
// inlined once into a GPU kernel. Random numbers come from the counter-based RNG keyed by
// (seed, pixel, sample index).
#ifndef TWINRAY_CORE_INTEGRATOR_H
#define TWINRAY_CORE_INTEGRATOR_H

#include "core/bsdf.h"
#include "core/camera.h"
#include "core/emitter.h"
#include "core/film.h"
#include "core/integrators/ambient_occlusion.h"
#include "core/integrators/path_state.h"
#include "core/interaction.h"
#include "core/mis.h"

TR_NAMESPACE_BEGIN

INLINE PathState integrator_begin(uvec2 pixel, uint sample_index, uint seed) {
  REF(SceneGlobals) g = scene_globals();
  REF(Camera) c = g.camera;
  PathState s;
  s.rng = rng_init_sampler(pixel.y * c.width + pixel.x, sample_index, seed, g.sampler_params);
  vec2 film = sample_film_position(c, pixel, rng_next_2d(s.rng), s.film_sign);
  s.ray = camera_ray(c, film, rng_next_2d(s.rng));
  s.throughput = vec3(1.0f);
  s.eta = 1.0f;
  s.radiance = vec3(0.0f);
  s.prev_bsdf_pdf = 1.0f;
  s.prev_p = s.ray.o;
  s.prev_bsdf_delta = 1u;
  s.depth = 0u;
  s.alive = (g.integrator.type == INTEGRATOR_PATH && g.integrator.max_depth == 0) ? 0u : 1u;
  s.stage = 0u;
  s.anchor.frame = frame_from_normal(vec3(0.0f, 0.0f, 1.0f));
  s.anchor.p = vec3(0.0f);
  s.anchor.material = 0u;
  s.anchor.ng = vec3(0.0f, 0.0f, 1.0f);
  s.anchor.pad0 = 0u;
  s.anchor.wi = vec3(0.0f, 0.0f, 1.0f);
  s.anchor.pad1 = 0.0f;
  s.anchor.tex = tex_coord(vec2(0.0f));
  s.anchor.dp_du = vec3(1.0f, 0.0f, 0.0f);
  s.anchor.dp_dv = vec3(0.0f, 1.0f, 0.0f);
  return s;
}

INLINE bool integrator_alive(PathState s) { return s.alive != 0u; }

INLINE ShadingPoint shading_point(IN(SurfaceInteraction) si) {
  ShadingPoint sp;
  sp.frame = si.frame;
  sp.p = si.p;
  sp.material = si.material;
  sp.ng = si.ng;
  sp.pad0 = 0u;
  sp.wi = si.wi;
  sp.pad1 = 0.0f;
  sp.tex = surface_tex_coord(si);
  sp.dp_du = si.dp_du;
  sp.dp_dv = si.dp_dv;
  return sp;
}

// The surface a BSDF sees in its local frame; only `bumpmap` reads more than the flat one.
INLINE BsdfSurface bsdf_surface(IN(ShadingPoint) sp, IN(Material) m) {
  BsdfSurface g = bsdf_surface_flat();
  if (!bsdf_is_bumpmap(m)) return g;
  g.dp_du = frame_to_local(sp.frame, sp.dp_du);
  g.dp_dv = frame_to_local(sp.frame, sp.dp_dv);
  g.ng = frame_to_local(sp.frame, sp.ng);
  return g;
}

// ---- Mitsuba 0.6's strictNormals (Mitsuba 0.6.0, github.com/mitsuba-renderer/mitsuba @ 10af06f,
// src/integrators/path/path.cpp, MIPathTracer::Li; src/integrators/direct/direct.cpp,
// MIDirectIntegrator::Li, applies the same three rules to its single vertex):
//  (a) path.cpp:156-165 (direct.cpp:175-187): at a surface hit, after its emission is added,
//        if ((rRec.depth >= m_maxDepth && m_maxDepth > 0)
//            || (m_strictNormals && dot(ray.d, its.geoFrame.n) * Frame::cosTheta(its.wi) >= 0))
//            break;                               // direct: return Li;
//      i.e. the path ends unless the geometric and shading normals put the incident direction
//      strictly on the same side (cosTheta(its.wi) = dot(-ray.d, shading normal)).
//  (b) path.cpp:186-188 (direct.cpp:232-233): an emitter sample counts only if
//        !bsdfVal.isZero() && (!m_strictNormals
//            || dot(its.geoFrame.n, dRec.d) * Frame::cosTheta(bRec.wo) > 0)
//  (c) path.cpp:215-219 (direct.cpp:267-271): after BSDF sampling (a zero weight has already
//      ended the path, path.cpp:210-211),
//        const Vector wo = its.toWorld(bRec.wo);
//        Float woDotGeoN = dot(its.geoFrame.n, wo);
//        if (m_strictNormals && woDotGeoN * Frame::cosTheta(bRec.wo) <= 0)
//            break;                               // direct: continue; (that sample scores 0)
//      before the ray is traced, so the emission it would find is not counted either.
// (b) and (c) drop the same directions (> 0 and <= 0 complement each other), so both MIS
// techniques cover the same domain. Mitsuba 0.6 orients a mesh's geometric normal towards its
// interpolated shading normal (include/mitsuba/render/skdtree.h:388-392, "Ensure that the
// geometric & shading normals face the same direction"); twinray's ng follows the winding
// (and flip_normals), so the rules use it turned the same way. Shapes without shading normals
// (shading normal = geometric normal) lose only directions exactly in the tangent plane. A
// bumpmap or normalmap perturbs only inside the BSDF there as here: the rules use the
// interaction's shading frame.
INLINE vec3 strict_normals_ng(IN(ShadingPoint) sp) {
  return dot(sp.ng, sp.frame.n) < 0.0f ? -sp.ng : sp.ng;
}

// Rule (a): whether the normals put the incident direction `d` (travelling towards sp) on the
// same side (sp.wi = -d in the shading frame).
INLINE bool strict_normals_incident_ok(IN(ShadingPoint) sp, vec3 d) {
  return dot(d, strict_normals_ng(sp)) * sp.wi.z < 0.0f;
}

// Rules (b) and (c): whether they put the outgoing direction (world `wo_world`, local `wo`) on
// the same side.
INLINE bool strict_normals_outgoing_ok(IN(ShadingPoint) sp, vec3 wo_world, vec3 wo) {
  return dot(strict_normals_ng(sp), wo_world) * wo.z > 0.0f;
}

// Russian roulette with Mitsuba's survival probability min(max(throughput) eta^2, 0.95);
// survivors are divided by it (pbrt-v4 §14.1.4).
INLINE bool russian_roulette_survives(INOUT(PathState) s, IN(Integrator) it) {
  float throughput_max = max_component(s.throughput);
  if (int(s.depth) >= it.rr_depth) {
    float q = min(throughput_max * s.eta * s.eta, 0.95f);
    if (!(rng_next_1d(s.rng) < q)) return false;
    s.throughput /= q;
  }
  return throughput_max != 0.0f;
}

INLINE ShadowRay integrator_step(INOUT(PathState) s, IN(Hit) hit) {
  REF(Integrator) it = scene_globals().integrator;
  if (TR_HAS_INTEGRATOR(INTEGRATOR_AMBIENT_OCCLUSION) && it.type == INTEGRATOR_AMBIENT_OCCLUSION)
    return ambient_occlusion_step(s, hit, it);
  bool direct = TR_HAS_INTEGRATOR(INTEGRATOR_DIRECT) && it.type == INTEGRATOR_DIRECT;
  bool first = direct ? s.stage == 0u : s.depth == 0u;
  // Sample counts of the two techniques (path: one each) and the BSDF technique's weight.
  float n_bsdf = direct ? float(it.bsdf_samples) : 1.0f;
  float n_emitter = direct ? float(it.emitter_samples) : 1.0f;
  float frac_bsdf = n_bsdf / (n_bsdf + n_emitter);
  float frac_emitter = n_emitter / (n_bsdf + n_emitter);

  // ---- What the ray found: emission, weighted against emitter sampling from prev_p. The
  // path so far has s.depth scattering events, so s.depth + 1 segments (path; direct keeps
  // min_depth 1 and depth 0). The emitter-sampling density is needed only for the MIS weight of
  // emission that counts (a tree walk under the light BVH): not for the camera ray's, nor after
  // a delta lobe, nor for zero emission (an emitter seen from behind).
  bool counts = int(s.depth) + 1 >= it.min_depth && any(notEqual(s.throughput, vec3(0.0f)));
  bool weighted = counts && !first && s.prev_bsdf_delta == 0u;
  bool found_surface = hit.shape != NO_INDEX;
  vec3 le = vec3(0.0f);
  float em_pdf = 0.0f;
  if (found_surface) {
    SurfaceInteraction si = surface_interaction(s.ray, hit);
    if (si.emitter != NO_INDEX) {
      if (first && it.hide_emitters != 0u) {
        s.ray = spawn_ray(si.p, si.ng, s.ray.d);
        return no_shadow_ray();
      }
      le = eval_emitter_surface(si);
      if (weighted && any(notEqual(le, vec3(0.0f)))) em_pdf = pdf_emitter_surface(s.prev_p, si);
    }
    // Where the next samples start: the path's new vertex, or the direct integrator's first
    // hit, which its later rounds keep. (A path that ends below leaves it unread.)
    if (!direct || first) s.anchor = shading_point(si);
  } else if (!(first && it.hide_emitters != 0u)) {
    le = eval_environment(s.ray.d);
    if (weighted && any(notEqual(le, vec3(0.0f)))) em_pdf = pdf_environment(s.ray.d);
  }
  if (counts && any(notEqual(le, vec3(0.0f)))) {
    float weight =
        first ? 1.0f : power_heuristic(s.prev_bsdf_pdf * frac_bsdf, em_pdf * frac_emitter) / n_bsdf;
    s.radiance += s.throughput * le * weight;
  }

  // ---- Whether to sample from s.anchor, and which round of the direct integrator.
  uint round = 0u;
  if (direct) {
    if (first && !found_surface) {
      s.alive = 0u;
      return no_shadow_ray();
    }
    round = s.stage;
    s.stage += 1u;
    if (round >= max(it.emitter_samples, it.bsdf_samples)) {
      s.alive = 0u;
      return no_shadow_ray();
    }
  } else {
    if (!found_surface || !(it.max_depth < 0 || int(s.depth) + 1 < it.max_depth)) {
      s.alive = 0u;
      return no_shadow_ray();
    }
  }
  REF(ShadingPoint) sp = s.anchor;
  // strictNormals rule (a) at the path's new vertex, or at the direct integrator's first hit
  // (s.ray is still the ray that found it).
  if (it.strict_normals != 0u && (!direct || first) && !strict_normals_incident_ok(sp, s.ray.d)) {
    s.alive = 0u;
    return no_shadow_ray();
  }
  REF(Material) m = scene_material(sp.material);
  BsdfRoot root = bsdf_root(bsdf_surface(sp, m), m, sp.tex, sp.wi);
  REF(Material) tree = scene_material(root.perturbed != 0u ? normalmap_child(m) : sp.material);
  vec3 base = direct ? vec3(1.0f) : s.throughput;

  // ---- Emitter sampling.
  ShadowRay sr = no_shadow_ray();
  // The emitter sample adds one scattering event here: s.depth + 2 segments.
  if (round < uint(n_emitter) && int(s.depth) + 2 >= it.min_depth &&
      (bsdf_tree_flags(tree, sp.tex) & BSDF_SMOOTH) != 0u) {
    EmitterSample es = sample_emitter(sp.p, s.rng);
    if (es.pdf > 0.0f) {
      vec3 wo = frame_to_local(sp.frame, es.d);
      BsdfEvalPdf bsdf = bsdf_root_eval_pdf(root, tree, sp.tex, sp.wi, wo);
      float mis =
          es.delta != 0u ? 1.0f : power_heuristic(es.pdf * frac_emitter, bsdf.pdf * frac_bsdf);
      sr.contribution = base * bsdf.f * es.weight * (mis / n_emitter);
      // strictNormals rule (b).
      bool kept = it.strict_normals == 0u || strict_normals_outgoing_ok(sp, es.d, wo);
      if (kept && any(notEqual(sr.contribution, vec3(0.0f)))) {
        sr.enabled = 1u;
        sr.ray = shadow_ray_to(sp.p, sp.ng, es.p, es.n, es.d, es.dist);
      }
    }
  }

  // ---- BSDF sampling: the next ray.
  s.throughput = vec3(0.0f);
  s.ray = make_ray(sp.p, sp.frame.n, 0.0f);
  s.prev_p = sp.p;
  if (round < uint(n_bsdf)) {
    float u1 = rng_next_1d(s.rng);
    BsdfSample bs = bsdf_root_sample(root, tree, sp.tex, sp.wi, u1, rng_next_2d(s.rng));
    vec3 wo_world = frame_to_world(sp.frame, bs.wo);
    // strictNormals rule (c): path ends; direct's sample scores nothing (s.throughput stays 0,
    // s.ray the empty ray).
    if (it.strict_normals != 0u && !strict_normals_outgoing_ok(sp, wo_world, bs.wo)) {
      if (!direct) s.alive = 0u;
      return sr;
    }
    s.ray = spawn_ray(sp.p, sp.ng, wo_world);
    s.throughput = base * bs.weight;
    s.eta *= bs.eta;
    s.prev_bsdf_pdf = bs.pdf;
    s.prev_bsdf_delta = (bs.lobe & BSDF_DELTA) != 0u ? 1u : 0u;
    if (!direct) {
      s.depth += 1u;
      bool survives = russian_roulette_survives(s, it);
      s.alive = (survives && bs.pdf > 0.0f) ? 1u : 0u;
    }
  }
  return sr;
}

INLINE void integrator_add_unoccluded(INOUT(PathState) s, ShadowRay sr) {
  s.radiance += sr.contribution;
}

INLINE vec3 integrator_result(PathState s) { return s.radiance; }

// Whether the sample enters its pixel's estimate with a negative sign (a negative lobe of the
// reconstruction filter, core/film.h); the backends keep such samples apart.
INLINE bool integrator_negative(PathState s) { return s.film_sign < 0.0f; }

INLINE bool radiance_is_finite(vec3 L) { return !any(isnan(L)) && !any(isinf(L)); }

TR_NAMESPACE_END

#endif
