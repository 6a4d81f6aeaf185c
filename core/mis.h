// Multiple importance sampling weights.
#ifndef TWINRAY_CORE_MIS_H
#define TWINRAY_CORE_MIS_H

#include "core/prelude.h"

TR_NAMESPACE_BEGIN

// Power heuristic with exponent 2, Veach 1997, eq. 9.13, for one sample of each technique:
// w_a = pdf_a^2 / (pdf_a^2 + pdf_b^2). Zero when pdf_a is zero (never NaN).
INLINE float power_heuristic(float pdf_a, float pdf_b) {
  float a2 = pdf_a * pdf_a;
  float b2 = pdf_b * pdf_b;
  return pdf_a > 0.0f ? a2 / (a2 + b2) : 0.0f;
}

TR_NAMESPACE_END

#endif
