// Owen scrambling by hashing (Burley, "Practical Hash-based Owen Scrambling", JCGT 9(4) 2020,
// §3, after Laine & Karras 2011): on the reversed bits of a fixed-point value (bit j the
// 2^-(j+1) digit), a hash whose every output bit is its input bit flipped by a function of the
// input bits below it and of the seed: a nested random permutation of the elementary
// intervals, i.e. an Owen scramble, which keeps every (t, m, s)-net a (t, m, s)-net. The
// constants are pbrt-v4's FastOwenScrambler (Pharr, Jakob & Humphreys, "Physically Based
// Rendering", 4th ed., §8.7.5); it works on reversed bits already, so no reversals here.
#ifndef TWINRAY_CORE_SAMPLERS_OWEN_SCRAMBLE_H
#define TWINRAY_CORE_SAMPLERS_OWEN_SCRAMBLE_H

#include "core/prelude.h"

TR_NAMESPACE_BEGIN

INLINE uint owen_scramble_reversed(uint reversed, uint seed) {
  uint v = reversed;
  v ^= v * 0x3d20adeau;
  v += seed;
  v *= (seed >> 16u) | 1u;
  v ^= v * 0x05526c56u;
  v ^= v * 0x53a22864u;
  return v;
}

TR_NAMESPACE_END

#endif
