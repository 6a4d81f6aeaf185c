// lowbias32, a 32-bit integer hash of low bias found by search (Wellons, "Prospecting for Hash
// Functions", 2018): every output bit depends on every input bit. pcg4d's (core/rng.h) low
// output bits depend on few input bits; a hash whose low bits matter (a seed of
// core/samplers/owen_scramble.h, whose top digit is the seed's lowest bit) goes through this.
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
