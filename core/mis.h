// Multiple importance sampling weights.
#ifndef TWINRAY_CORE_MIS_H
#define TWINRAY_CORE_MIS_H

#include "core/prelude.h"

TR_NAMESPACE_BEGIN

// Power heuristic with exponent 2, Veach 1997, eq. 9.13, for one sample of each technique:
// w_a = pdf_a^2 / (pdf_a^2 + pdf_b^2), evaluated as 1 / (1 + (pdf_b / pdf_a)^2) so that huge
// densities (grazing area-light samples) neither overflow nor give inf / inf. Zero when
// pdf_a is zero; 1 when pdf_a is infinite and pdf_b finite.
INLINE float power_heuristic(float pdf_a, float pdf_b) {
  if (!(pdf_a > 0.0f)) return 0.0f;
  float r = pdf_b / pdf_a;
  return 1.0f / (1.0f + r * r);
}

TR_NAMESPACE_END

#endif
