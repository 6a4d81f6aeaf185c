// principled against the values Mitsuba 3's own regression test pins down
// (src/bsdfs/tests/test_principled.py, test05_eval_pdf: "the true values are defined by the
// first implementation"), for one parameter set with every lobe active.
#include "core/bsdf/principled.h"

#include <gtest/gtest.h>

#include <cmath>

namespace tr {
namespace {

const double kPdfTrue[20] = {
    0.17007458209991455,  0.15398569405078888,  0.14061447978019714,  0.12924496829509735,
    0.1193309798836708,   0.1104581207036972,   0.10231398791074753,  0.09466464817523956,
    0.08733665198087692,  0.08020336925983429,  0.07317451387643814,  0.06618815660476685,
    0.0592045858502388,   0.052201706916093826, 0.045171335339546204, 0.03811638057231903,
    0.031048627570271492, 0.02398696169257164,  0.016955917701125145, 0.009984553791582584};
const double kEvalTrue[20] = {
    0.06804995983839035,  0.06425636261701584,  0.060901228338479996, 0.057847555726766586,
    0.05498623475432396,  0.05223095044493675,  0.049513764679431915, 0.04678140580654144,
    0.04399249702692032,  0.04111534729599953,  0.03812596574425697,  0.03500543162226677,
    0.031735487282276154, 0.02829158864915371,  0.024633212015032768, 0.02069348469376564,
    0.01637275144457817,  0.011544802226126194, 0.006091561634093523, 4.703659982886835e-18};

TEST(Principled, MatchesMitsubaRegressionValues) {
  PrincipledParams p;
  p.base_color = vec3(0.5f);
  p.roughness = 0.5f;
  p.metallic = 0.3f;
  p.spec_tint = 0.6f;
  p.anisotropic = 0.3f;
  p.sheen = 0.9f;
  p.sheen_tint = 0.9f;
  p.clearcoat = 0.3f;
  p.clearcoat_gloss = 0.5f;
  p.spec_trans = 0.5f;
  p.flatness = 0.5f;
  p.eta = 2.0f / (1.0f - std::sqrt(0.08f * 0.4f)) - 1.0f;  // specular = 0.4
  p.diffuse_rate = 1.0f;
  p.specular_rate = 1.0f;
  p.clearcoat_rate = 1.0f;
  vec3 wi(1.0f, 0.0f, 1.0f);  // unnormalised, exactly as in Mitsuba's test
  for (int i = 0; i < 20; ++i) {
    // Python computes the direction in double before Mitsuba rounds it to float.
    double theta = i / 19.0 * (M_PI / 2.0);
    vec3 wo(float(std::sin(theta)), 0.0f, float(std::cos(theta)));
    BsdfEvalPdf v = principled_eval_pdf_params(p, wi, wo);
    double pdf = v.pdf;
    double value = v.f.x;
    EXPECT_NEAR(pdf, kPdfTrue[i], 1e-5 * kPdfTrue[i] + 1e-8) << "pdf, wo " << i;
    EXPECT_NEAR(value, kEvalTrue[i], 1e-5 * kEvalTrue[i] + 1e-8) << "eval, wo " << i;
  }
}

}  // namespace
}  // namespace tr
