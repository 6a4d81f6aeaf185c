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

INLINE float alias_pmf(uint offset, uint index) { return scene_alias(offset + index).pmf; }

TR_NAMESPACE_END

#endif
