// Counter-based random permutation of [0, n): Kensler, "Correlated Multi-Jittered Sampling",
// Pixar Technical Memo 13-01 (2013), §3 permute(i, l, p). A hash that is a bijection on the
// w-bit integers (w = the bits of n - 1) walks the cycle until it lands inside [0, n); the
// result is the image of i in the permutation selected by p. Mitsuba 3.8 uses the same
// function (include/mitsuba/core/random.h, permute_kensler).
#ifndef TWINRAY_CORE_SAMPLERS_PERMUTE_H
#define TWINRAY_CORE_SAMPLERS_PERMUTE_H

#include "core/prelude.h"

TR_NAMESPACE_BEGIN

INLINE uint permute_kensler(uint i, uint n, uint p) {
  if (n <= 1u) return 0u;
  uint w = n - 1u;
  w |= w >> 1u;
  w |= w >> 2u;
  w |= w >> 4u;
  w |= w >> 8u;
  w |= w >> 16u;
  do {
    i ^= p;
    i *= 0xe170893du;
    i ^= p >> 16u;
    i ^= (i & w) >> 4u;
    i ^= p >> 8u;
    i *= 0x0929eb3fu;
    i ^= p >> 23u;
    i ^= (i & w) >> 1u;
    i *= 1u | (p >> 27u);
    i *= 0x6935fa69u;
    i ^= (i & w) >> 11u;
    i *= 0x74dcb303u;
    i ^= (i & w) >> 2u;
    i *= 0x9e501cc3u;
    i ^= (i & w) >> 2u;
    i *= 0xc860a3dfu;
    i &= w;
    i ^= i >> 5u;
  } while (i >= n);
  return (i + p) % n;
}

TR_NAMESPACE_END

#endif
