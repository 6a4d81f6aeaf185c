// lowbias32, a 32-bit integer hash of low bias found by search (Wellons, "Prospecting for Hash
// Functions", 2018): every output bit depends on every input bit. zsobol hashes its digits with
// it, sobol its per-dimension scramble seeds (core/samplers/sobol.h).
#ifndef TWINRAY_CORE_SAMPLERS_LOWBIAS32_H
#define TWINRAY_CORE_SAMPLERS_LOWBIAS32_H

#include "core/prelude.h"

TR_NAMESPACE_BEGIN

INLINE uint lowbias32(uint h) {
  h ^= h >> 16u;
  h *= 0x7feb352du;
  h ^= h >> 15u;
  h *= 0x846ca68bu;
  h ^= h >> 16u;
  return h;
}

TR_NAMESPACE_END

#endif
