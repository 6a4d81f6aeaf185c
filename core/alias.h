// Sampling a discrete distribution from an alias table in the scene's alias buffer.
// Walker 1977; table layout and construction: Vose, "A Linear Algorithm for Generating
// Random Numbers with a Given Distribution", IEEE TSE 17(9) 1991 (scenes/alias_table.cpp).
#ifndef TWINRAY_CORE_ALIAS_H
#define TWINRAY_CORE_ALIAS_H

#include "core/scene_access.h"

TR_NAMESPACE_BEGIN

// Draws an index in [0, count) of the table at `offset`: u.x picks the bin, u.y decides
// between the bin and its alias (a separate number, so large tables keep full resolution).
// Returns the index and its probability in pmf.
INLINE uint alias_sample(uint offset, uint count, vec2 u, OUT(float) pmf) {
  uint bin = min(uint(u.x * float(count)), count - 1u);
  AliasEntry e = scene_alias(offset + bin);
  uint index = u.y < e.q ? bin : e.alias;
  pmf = index == bin ? e.pmf : scene_alias(offset + index).pmf;
  return index;
}

// Tables up to this size may be sampled with one number and its remainder reused: the
// remainder keeps at least 16 of a draw's 24 bits.
const uint ALIAS_REUSE_MAX_COUNT = 256u;

// Draws an index with the single number u and returns in u_remapped what is left of u, again
// uniform on [0, 1) and independent of the index: pbrt-v4's AliasTable::Sample (Pharr, Jakob &
// Humphreys, 4th ed., §A.1). The remainder has about 24 - log2(count) bits: for small tables.
INLINE uint alias_sample_reuse(uint offset, uint count, float u, OUT(float) pmf,
                               OUT(float) u_remapped) {
  float x = u * float(count);
  uint bin = min(uint(x), count - 1u);
  float up = min(x - float(bin), ONE_MINUS_EPSILON);
  AliasEntry e = scene_alias(offset + bin);
  if (up < e.q) {
    pmf = e.pmf;
    u_remapped = min(up / e.q, ONE_MINUS_EPSILON);
    return bin;
  }
  pmf = scene_alias(offset + e.alias).pmf;
  u_remapped = min((up - e.q) / (1.0f - e.q), ONE_MINUS_EPSILON);
  return e.alias;
}

INLINE float alias_pmf(uint offset, uint index) { return scene_alias(offset + index).pmf; }

TR_NAMESPACE_END

#endif
