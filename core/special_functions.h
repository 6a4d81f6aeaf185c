// Special functions shared by the core (float, GLSL-compatible).
#ifndef TWINRAY_CORE_SPECIAL_FUNCTIONS_H
#define TWINRAY_CORE_SPECIAL_FUNCTIONS_H

#include "core/prelude.h"

TR_NAMESPACE_BEGIN

// erf(x) = 1 - erfc(x); erfc by the Chebyshev fit of Numerical Recipes in C, 2nd ed., §6.2
// (erfcc), fractional error < 1.2e-7.
INLINE float erf_approx(float x) {
  float z = abs(x);
  float t = 1.0f / (1.0f + 0.5f * z);
  float poly =
      -1.26551223f +
      t * (1.00002368f +
           t * (0.37409196f +
                t * (0.09678418f +
                     t * (-0.18628806f +
                          t * (0.27886807f +
                               t * (-1.13520398f +
                                    t * (1.48851587f + t * (-0.82215223f + t * 0.17087277f))))))));
  float erfc_z = t * exp(-z * z + poly);
  return x >= 0.0f ? 1.0f - erfc_z : erfc_z - 1.0f;
}

// Inverse error function, single-precision fit of Giles, "Approximating the erfinv function",
// GPU Computing Gems Jade Edition, 2011. |x| is kept below 1 so the result stays finite.
INLINE float erfinv_approx(float x) {
  x = clamp(x, -ONE_MINUS_EPSILON, ONE_MINUS_EPSILON);
  float w = -log((1.0f - x) * (1.0f + x));
  float p;
  if (w < 5.0f) {
    w = w - 2.5f;
    p = 2.81022636e-08f;
    p = 3.43273939e-07f + p * w;
    p = -3.5233877e-06f + p * w;
    p = -4.39150654e-06f + p * w;
    p = 0.00021858087f + p * w;
    p = -0.00125372503f + p * w;
    p = -0.00417768164f + p * w;
    p = 0.246640727f + p * w;
    p = 1.50140941f + p * w;
  } else {
    w = sqrt(w) - 3.0f;
    p = -0.000200214257f;
    p = 0.000100950558f + p * w;
    p = 0.00134934322f + p * w;
    p = -0.00367342844f + p * w;
    p = 0.00573950773f + p * w;
    p = -0.0076224613f + p * w;
    p = 0.00943887047f + p * w;
    p = 1.00167406f + p * w;
    p = 2.83297682f + p * w;
  }
  return p * x;
}

// Arctangent with the same float operations on every backend (library atan differs between
// the host's libm and GPU drivers by a few ulps, enough to break CPU/GPU lockstep where a
// direction indexes a texture): Cephes atanf (Moshier, Cephes Math Library, atanf.c),
// range reduction at tan(3pi/8) and tan(pi/8), then an odd polynomial; ~2 ulp.
INLINE float atan_portable(float x) {
  float a = abs(x);
  float y0 = 0.0f;
  if (a > 2.414213562373095f) {
    y0 = 0.5f * PI;
    a = -1.0f / a;
  } else if (a > 0.4142135623730950f) {
    y0 = 0.25f * PI;
    a = (a - 1.0f) / (a + 1.0f);
  }
  float z = a * a;
  float y = (((8.05374449538e-2f * z - 1.38776856032e-1f) * z + 1.99777106478e-1f) * z -
             3.33329491539e-1f) *
                z * a +
            a;
  y += y0;
  return x < 0.0f ? -y : y;
}

// atan2(y, x) in (-pi, pi] from atan_portable.
INLINE float atan2_portable(float y, float x) {
  if (x == 0.0f) return y > 0.0f ? 0.5f * PI : (y < 0.0f ? -0.5f * PI : 0.0f);
  float r = atan_portable(y / x);
  if (x > 0.0f) return r;
  return y >= 0.0f ? r + PI : r - PI;
}

// acos(x) = atan2(sqrt(1 - x^2), x), argument clamped to [-1, 1].
INLINE float acos_portable(float x) {
  x = clamp(x, -1.0f, 1.0f);
  return atan2_portable(sqrt(max(0.0f, (1.0f - x) * (1.0f + x))), x);
}

TR_NAMESPACE_END

#endif
