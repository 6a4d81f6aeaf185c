// Every BSDF through the public interface of core/bsdf.h: sample/pdf/eval consistency,
// sampling against eval (albedo two ways), energy, reciprocity, extremes, known values.
#include "core/bsdf.h"

#include <gtest/gtest.h>

#include <cmath>
#include <functional>
#include <random>
#include <string>
#include <vector>

#include "bsdf_test_support.h"

namespace tr {
namespace {

using namespace tr::test;

struct Case {
  std::string name;
  std::function<Material()> make;  // built lazily: roughplastic tables take a while
  bool reciprocal;                 // f(wi, wo) = f(wo, wi) for reflection
  bool lossless;  // reflectances 1: the albedo (in power) is 1 up to the model's own loss
  bool bounded;   // albedo <= 1; the Disney sheen and clearcoat lobes add energy
};

void PrintTo(const Case& c, std::ostream* os) { *os << c.name; }

// Mitsuba's principled defaults (base_color 0.5, roughness 0.5, specular 0.5, the rest 0).
PrincipledParams principled_defaults() {
  PrincipledParams p;
  p.base_color = vec3(0.5f);
  p.roughness = 0.5f;
  p.metallic = 0.0f;
  p.spec_tint = 0.0f;
  p.anisotropic = 0.0f;
  p.sheen = 0.0f;
  p.sheen_tint = 0.0f;
  p.clearcoat = 0.0f;
  p.clearcoat_gloss = 0.0f;
  p.spec_trans = 0.0f;
  p.flatness = 0.0f;
  p.eta = 2.0f / (1.0f - std::sqrt(0.08f * 0.5f)) - 1.0f;
  p.diffuse_rate = 1.0f;
  p.specular_rate = 1.0f;
  p.clearcoat_rate = 1.0f;
  return p;
}

// Every principled weight of issue 3 at `value`, one at a time (index 0..9), or all (-1).
PrincipledParams principled_with(int index, float value) {
  PrincipledParams p = principled_defaults();
  float* fields[] = {&p.roughness,  &p.metallic,    &p.spec_tint, &p.anisotropic,
                     &p.sheen,      &p.sheen_tint,  &p.clearcoat, &p.clearcoat_gloss,
                     &p.spec_trans, &p.base_color.y};
  for (int i = 0; i < 10; ++i) {
    if (index < 0 || index == i) *fields[i] = value;
  }
  return p;
}

std::vector<Case> all_cases() {
  std::vector<Case> cases;
  auto add = [&](std::string name, std::function<Material()> make, bool reciprocal, bool lossless) {
    cases.push_back({std::move(name), make, reciprocal, lossless, true});
  };
  auto add_unbounded = [&](std::string name, std::function<Material()> make) {
    cases.push_back({std::move(name), make, false, false, false});
  };
  const uint kBeckmann = MATERIAL_BECKMANN;
  const uint kVisible = MATERIAL_SAMPLE_VISIBLE;
  const vec3 kGoldEta(0.143f, 0.374f, 1.442f);
  const vec3 kGoldK(3.983f, 2.385f, 1.603f);
  add(
      "diffuse", [] { return diffuse(vec3(0.2f, 0.5f, 0.8f)); }, true, false);
  add(
      "diffuse_white", [] { return diffuse(vec3(1.0f)); }, true, true);
  add(
      "conductor_gold", [=] { return conductor(kGoldEta, kGoldK); }, true, false);
  add(
      "conductor_mirror", [] { return conductor(vec3(0.0f), vec3(1.0f)); }, true, true);
  add(
      "dielectric_1.5", [] { return dielectric(1.5f); }, true, true);
  add(
      "dielectric_inv1.5", [] { return dielectric(1.0f / 1.5f); }, true, true);
  add(
      "dielectric_1.0001", [] { return dielectric(1.0001f); }, true, true);
  for (uint dist : {0u, kBeckmann}) {
    std::string dn = dist ? "beckmann" : "ggx";
    for (uint vis : {kVisible, 0u}) {
      std::string vn = dn + (vis ? "_vis" : "_novis");
      uint f = dist | vis;
      add(
          "roughconductor_" + vn + "_0.1",
          [=] { return rough_conductor(f, 0.1f, 0.1f, kGoldEta, kGoldK); }, true, false);
      add(
          "roughconductor_" + vn + "_0.5",
          [=] { return rough_conductor(f, 0.5f, 0.5f, kGoldEta, kGoldK); }, true, false);
      add(
          "roughconductor_" + vn + "_aniso",
          [=] { return rough_conductor(f, 0.15f, 0.6f, kGoldEta, kGoldK); }, true, false);
      for (float eta : {1.5f, 1.0f / 1.33f}) {
        std::string en = vn + (eta > 1.0f ? "_1.5" : "_inv1.33");
        add(
            "roughdielectric_" + en + "_0.1", [=] { return rough_dielectric(f, 0.1f, 0.1f, eta); },
            true, false);
        add(
            "roughdielectric_" + en + "_0.6", [=] { return rough_dielectric(f, 0.6f, 0.6f, eta); },
            true, false);
        add(
            "roughdielectric_" + en + "_aniso",
            [=] { return rough_dielectric(f, 0.1f, 0.4f, eta); }, true, false);
      }
    }
  }
  for (bool nl : {false, true}) {
    std::string n = nl ? "_nonlinear" : "";
    add(
        "plastic" + n, [=] { return plastic(vec3(0.1f, 0.27f, 0.36f), 1.9f, nl); }, true, false);
    add(
        "plastic_white" + n, [=] { return plastic(vec3(1.0f), 1.5f, nl); }, true, false);
    add(
        "roughplastic_beckmann" + n,
        [=] { return rough_plastic(kBeckmann | kVisible, 0.1f, vec3(0.5f), 1.49f, nl); }, true,
        false);
    add(
        "roughplastic_ggx" + n,
        [=] { return rough_plastic(kVisible, 0.3f, vec3(0.2f, 0.6f, 0.9f), 1.5f, nl); }, true,
        false);
  }
  add(
      "roughplastic_ggx_novis",
      [] { return rough_plastic(0u, 0.3f, vec3(0.2f, 0.6f, 0.9f), 1.5f, false); }, true, false);
  add(
      "roughplastic_black",
      [=] { return rough_plastic(kBeckmann | kVisible, 0.05f, vec3(0.0f), 1.49f, false); }, true,
      false);
  add(
      "principled_default", [] { return principled(principled_defaults()); }, false, false);
  add_unbounded("principled_all_half", [] { return principled(principled_with(-1, 0.5f)); });
  add(
      "principled_glass",
      [] {
        PrincipledParams p = principled_defaults();
        p.spec_trans = 1.0f;
        p.roughness = 0.3f;
        p.eta = 1.5f;
        return principled(p);
      },
      false, false);
  add_unbounded("principled_scene_like", [] {
    PrincipledParams p = principled_defaults();
    p.base_color = vec3(0.2f, 0.8f, 0.1f);
    p.roughness = 0.15f;
    p.anisotropic = 0.8f;
    p.metallic = 0.1f;
    p.clearcoat = 0.9f;
    p.sheen = 0.9f;
    p.eta = 2.0f / (1.0f - std::sqrt(0.08f * 0.7f)) - 1.0f;
    return principled(p);
  });
  add_unbounded("principled_mixed_rates", [] {
    PrincipledParams p = principled_with(-1, 0.5f);
    p.eta = 1.0f / 1.4f;
    p.diffuse_rate = 0.3f;
    p.specular_rate = 2.0f;
    p.clearcoat_rate = 0.7f;
    return principled(p);
  });
  add(
      "twosided_diffuse",
      [] {
        Material m = diffuse(vec3(0.7f));
        m.flags |= MATERIAL_TWOSIDED;
        return m;
      },
      true, false);
  add(
      "masked_diffuse",
      [] {
        Material m = diffuse(vec3(0.7f));
        m.flags |= MATERIAL_MASKED;
        m.opacity = constant(0.3f);
        return m;
      },
      true, false);
  return cases;
}

bool is_finite(vec3 v) { return std::isfinite(v.x) && std::isfinite(v.y) && std::isfinite(v.z); }
bool is_nonnegative(vec3 v) { return v.x >= 0.0f && v.y >= 0.0f && v.z >= 0.0f; }
bool is_smooth(uint lobe) { return (lobe & BSDF_SMOOTH) != 0u; }
bool is_transmission(vec3 wi, vec3 wo) { return wi.z * wo.z < 0.0f; }

float rel_diff(float a, float b) { return std::abs(a - b) / std::max(std::abs(b), 1e-6f); }

const float kCosines[] = {1.0f, 0.8f, 0.5f, 0.2f, 0.05f, -0.3f, -0.9f};

class BsdfCase : public ::testing::TestWithParam<Case> {};

TEST_P(BsdfCase, SampleAgreesWithPdfAndEval) {
  const Case& c = GetParam();
  const Material material = c.make();
  std::mt19937 rng(11);
  std::uniform_real_distribution<float> uni(0.0f, 1.0f);
  int checked = 0;
  for (float cos_i : kCosines) {
    for (int i = 0; i < 2000; ++i) {
      vec3 wi = direction(cos_i, 2.0f * float(M_PI) * uni(rng));
      vec2 uv(uni(rng), uni(rng));
      BsdfSample s = bsdf_sample(material, uv, wi, uni(rng), vec2(uni(rng), uni(rng)));
      if (s.pdf == 0.0f) {
        EXPECT_EQ(s.weight, vec3(0.0f));
        continue;
      }
      ASSERT_TRUE(is_finite(s.weight) && is_nonnegative(s.weight)) << c.name;
      ASSERT_NEAR(length(s.wo), 1.0f, 1e-4f) << c.name;
      EXPECT_TRUE((bsdf_flags(material, uv) & s.lobe) != 0u) << c.name;
      EXPECT_EQ(s.eta == 1.0f, !is_transmission(wi, s.wo) || s.lobe == BSDF_NULL) << c.name;
      if (!is_smooth(s.lobe)) continue;
      float pdf = bsdf_pdf(material, uv, wi, s.wo);
      vec3 f = bsdf_eval(material, uv, wi, s.wo);
      EXPECT_LT(rel_diff(s.pdf, pdf), 1e-3f) << c.name << " cos " << cos_i;
      for (int k = 0; k < 3; ++k) {
        EXPECT_NEAR(s.weight[k], f[k] / pdf, 1e-3f * std::max(1.0f, s.weight[k])) << c.name;
      }
      ++checked;
    }
  }
  if ((bsdf_flags(material, vec2(0.5f)) & BSDF_SMOOTH) != 0u) {
    EXPECT_GT(checked, 0);
  }
}

TEST_P(BsdfCase, EvalPositiveOnlyWherePdfPositive) {
  const Case& c = GetParam();
  const Material material = c.make();
  std::mt19937 rng(12);
  std::uniform_real_distribution<float> uni(0.0f, 1.0f);
  for (float cos_i : kCosines) {
    for (int i = 0; i < 2000; ++i) {
      vec3 wi = direction(cos_i, 2.0f * float(M_PI) * uni(rng));
      vec3 wo = square_to_uniform_sphere(vec2(uni(rng), uni(rng)));
      vec3 f = bsdf_eval(material, vec2(0.5f), wi, wo);
      float pdf = bsdf_pdf(material, vec2(0.5f), wi, wo);
      ASSERT_TRUE(is_finite(f) && is_nonnegative(f) && std::isfinite(pdf) && pdf >= 0.0f);
      if (max_component(f) > 0.0f) {
        EXPECT_GT(pdf, 0.0f) << c.name;
      }
    }
  }
}

// Albedo of the smooth lobes two ways: E[weight 1{smooth}] under the BSDF's own sampling and
// E[eval / p] under uniform sphere sampling. Both estimate \int_smooth f |cos| dwo.
TEST_P(BsdfCase, SampledAlbedoMatchesIntegratedEval) {
  const Case& c = GetParam();
  const Material material = c.make();
  std::mt19937 rng(13);
  std::uniform_real_distribution<float> uni(0.0f, 1.0f);
  const int n = 100000;
  for (float cos_i : {0.9f, 0.4f, -0.6f}) {
    vec3 wi = direction(cos_i, 0.7f);
    double s1 = 0, s1_sq = 0, s2 = 0, s2_sq = 0;
    for (int i = 0; i < n; ++i) {
      BsdfSample s = bsdf_sample(material, vec2(0.5f), wi, uni(rng), vec2(uni(rng), uni(rng)));
      double a = (s.pdf > 0.0f && is_smooth(s.lobe)) ? luminance(s.weight) : 0.0;
      s1 += a;
      s1_sq += a * a;
      vec3 wo = square_to_uniform_sphere(vec2(uni(rng), uni(rng)));
      double b = luminance(bsdf_eval(material, vec2(0.5f), wi, wo)) / INV_FOUR_PI;
      s2 += b;
      s2_sq += b * b;
    }
    double m1 = s1 / n, m2 = s2 / n;
    double var = (s1_sq / n - m1 * m1) / n + (s2_sq / n - m2 * m2) / n;
    EXPECT_NEAR(m1, m2, 5.0 * std::sqrt(var) + 1e-4) << c.name << " cos " << cos_i;
  }
}

// Energy: the sampled throughput, with the radiance scaling of refraction (1 / eta^2)
// removed, never exceeds 1 — and reaches 1 for lossless models.
TEST_P(BsdfCase, AlbedoAtMostOne) {
  const Case& c = GetParam();
  const Material material = c.make();
  std::mt19937 rng(14);
  std::uniform_real_distribution<float> uni(0.0f, 1.0f);
  const int n = 50000;
  for (float cos_i : {1.0f, 0.6f, 0.1f, -0.5f}) {
    vec3 wi = direction(cos_i, 0.3f);
    double sum = 0, sum_sq = 0;
    for (int i = 0; i < n; ++i) {
      BsdfSample s = bsdf_sample(material, vec2(0.5f), wi, uni(rng), vec2(uni(rng), uni(rng)));
      double a = max_component(s.weight) * s.eta * s.eta;
      sum += a;
      sum_sq += a * a;
    }
    double mean = sum / n;
    double sigma = std::sqrt(std::max(sum_sq / n - mean * mean, 0.0) / n);
    if (c.bounded) {
      EXPECT_LE(mean, 1.0 + 5.0 * sigma + 1e-5) << c.name << " cos " << cos_i;
    }
    uint transmits =
        bsdf_flags(material, vec2(0.5f)) & (BSDF_DELTA_TRANSMISSION | BSDF_GLOSSY_TRANSMISSION);
    bool lit = cos_i > 0.0f || (material.flags & MATERIAL_TWOSIDED) != 0u || transmits != 0u;
    if (c.lossless && lit) {
      EXPECT_NEAR(mean, 1.0, 5.0 * sigma + 1e-5) << c.name << " cos " << cos_i;
    }
  }
}

TEST_P(BsdfCase, ReflectionIsReciprocal) {
  const Case& c = GetParam();
  const Material material = c.make();
  if (!c.reciprocal) GTEST_SKIP() << "not reciprocal in Mitsuba either";
  std::mt19937 rng(15);
  std::uniform_real_distribution<float> uni(0.0f, 1.0f);
  for (int i = 0; i < 5000; ++i) {
    vec3 a = square_to_cosine_hemisphere(vec2(uni(rng), uni(rng)));
    vec3 b = square_to_cosine_hemisphere(vec2(uni(rng), uni(rng)));
    if (a.z < 1e-3f || b.z < 1e-3f) continue;
    vec3 fab = bsdf_eval(material, vec2(0.5f), a, b) / b.z;
    vec3 fba = bsdf_eval(material, vec2(0.5f), b, a) / a.z;
    for (int k = 0; k < 3; ++k) {
      EXPECT_NEAR(fab[k], fba[k], 1e-3f * std::max(1.0f, fab[k])) << c.name;
    }
  }
}

INSTANTIATE_TEST_SUITE_P(All, BsdfCase, ::testing::ValuesIn(all_cases()),
                         [](const ::testing::TestParamInfo<Case>& info) {
                           std::string n = info.param.name;
                           for (char& ch : n)
                             if (!std::isalnum(static_cast<unsigned char>(ch))) ch = '_';
                           return n;
                         });

// ---- Extremes: no NaN, Inf or negative value anywhere on the grid of issue 3 -------------

const float kAlphas[] = {1e-4f, 1e-3f, 0.01f, 0.1f, 0.5f, 1.0f};
const float kEtas[] = {1.0f, 1.0001f, 1.33f, 1.5f, 2.42f, 4.0f, 1.0f / 1.5f};
const float kExtremeCosines[] = {1.0f, 0.5f, 1e-2f, 1e-4f, 1e-6f, 0.0f, -1e-6f, -0.5f, -1.0f};

std::vector<Material> extreme_materials() {
  std::vector<Material> ms;
  for (float r : {0.0f, 1.0f}) {
    ms.push_back(diffuse(vec3(r)));
    ms.push_back(conductor(vec3(r), vec3(r)));
  }
  ms.push_back(conductor(vec3(0.0f), vec3(1.0f)));
  for (uint flags : {0u, 4u, 8u, 12u}) {
    for (float alpha : kAlphas) {
      ms.push_back(rough_conductor(flags, alpha, alpha, vec3(0.0f), vec3(1.0f)));
      ms.push_back(rough_conductor(flags, alpha, 0.3f, vec3(0.2f), vec3(3.0f)));
      ms.push_back(rough_conductor(flags, alpha, alpha, vec3(0.0f), vec3(0.0f)));
      ms.push_back(rough_conductor(flags, alpha, 1.0f, vec3(1.0f), vec3(0.0f)));
      for (float eta : kEtas) {
        ms.push_back(rough_dielectric(flags, alpha, alpha, eta));
        ms.push_back(rough_dielectric(flags, alpha, 0.2f, eta));
      }
    }
  }
  for (float eta : kEtas) {
    ms.push_back(dielectric(eta));
    ms.push_back(thin_dielectric(eta));
    Material zero = dielectric(eta);
    zero.param[DIELECTRIC_SPECULAR_REFLECTANCE] = constant(0.0f);
    zero.param[DIELECTRIC_SPECULAR_TRANSMITTANCE] = constant(0.0f);
    ms.push_back(zero);
  }
  for (float eta : {1.0001f, 1.33f, 1.5f, 2.42f, 4.0f, 1.0f / 1.5f}) {
    for (float r : {0.0f, 1.0f}) {
      for (bool nonlinear : {false, true}) {
        ms.push_back(plastic(vec3(r), eta, nonlinear));
        Material zero_specular = plastic(vec3(r), eta, nonlinear);
        zero_specular.param[PLASTIC_SPECULAR_REFLECTANCE] = constant(0.0f);
        zero_specular.extra = 0.0f;
        ms.push_back(zero_specular);
      }
    }
  }
  for (float alpha : {1e-4f, 0.5f, 1.0f}) {
    for (uint flags : {0u, 12u}) {
      for (float eta : {1.0001f, 1.5f, 4.0f}) {
        ms.push_back(rough_plastic(flags, alpha, vec3(1.0f), eta, true));
        ms.push_back(rough_plastic(flags, alpha, vec3(0.0f), eta, false));
      }
    }
  }
  for (int index = -1; index < 10; ++index) {
    for (float value : {0.0f, 0.5f, 1.0f}) {
      for (float eta : kEtas) {
        PrincipledParams p = principled_with(index, value);
        p.eta = eta;
        ms.push_back(principled(p));
      }
    }
  }
  std::vector<Material> wrapped;
  for (const Material& m : ms) {
    Material t = m;
    t.flags |= MATERIAL_TWOSIDED;
    wrapped.push_back(t);
    for (float alpha : {0.0f, 0.5f, 1.0f}) {
      Material k = m;
      k.flags |= MATERIAL_MASKED;
      k.opacity = constant(alpha);
      wrapped.push_back(k);
    }
  }
  ms.insert(ms.end(), wrapped.begin(), wrapped.end());
  return ms;
}

TEST(BsdfExtremes, NoNanInfOrNegative) {
  std::mt19937 rng(16);
  std::uniform_real_distribution<float> uni(0.0f, 1.0f);
  for (const Material& m : extreme_materials()) {
    for (float cos_i : kExtremeCosines) {
      for (float cos_o : kExtremeCosines) {
        vec3 wi = direction(cos_i, 0.4f);
        vec3 wo = direction(cos_o, 0.4f + float(M_PI) * uni(rng));
        vec3 f = bsdf_eval(m, vec2(0.5f), wi, wo);
        float pdf = bsdf_pdf(m, vec2(0.5f), wi, wo);
        ASSERT_TRUE(is_finite(f) && is_nonnegative(f)) << m.type << " " << cos_i << " " << cos_o;
        ASSERT_TRUE(std::isfinite(pdf) && pdf >= 0.0f) << m.type << " " << cos_i << " " << cos_o;
      }
      for (int i = 0; i < 200; ++i) {
        vec3 wi = direction(cos_i, 2.0f * float(M_PI) * uni(rng));
        float u1 = i == 0 ? 0.0f : (i == 1 ? ONE_MINUS_EPSILON : uni(rng));
        vec2 u2 =
            i == 0 ? vec2(0.0f) : (i == 1 ? vec2(ONE_MINUS_EPSILON) : vec2(uni(rng), uni(rng)));
        BsdfSample s = bsdf_sample(m, vec2(0.5f), wi, u1, u2);
        ASSERT_TRUE(is_finite(s.weight) && is_nonnegative(s.weight)) << m.type << " " << cos_i;
        ASSERT_TRUE(std::isfinite(s.pdf) && s.pdf >= 0.0f) << m.type << " " << cos_i;
        ASSERT_TRUE(is_finite(s.wo) && std::isfinite(s.eta) && s.eta > 0.0f) << m.type;
      }
    }
  }
}

// At grazing incidence the lobe is pressed against the horizon and part of the sampled
// directions leave the hemisphere: the mass of pdf() must equal the fraction of samples that
// succeed. pdf() is integrated over the sphere in polar coordinates around the mirror
// direction, where the lobe sits, with nodes packed toward it (GGX's tails reach far).
TEST(BsdfGrazing, PdfMassEqualsSampleSuccessRate) {
  std::mt19937 rng(17);
  std::uniform_real_distribution<float> uni(0.0f, 1.0f);
  for (uint flags : {0u, 4u, 8u, 12u}) {
    for (float degrees : {85.0f, 89.9f}) {
      Material m = rough_conductor(flags, 0.05f, 0.05f, vec3(0.0f), vec3(1.0f));
      float theta = degrees * float(M_PI) / 180.0f;
      vec3 wi = direction(std::cos(theta), 0.349f);
      vec3 r(-wi.x, -wi.y, wi.z);
      vec3 t1 = normalize(cross(r, vec3(0.0f, 0.0f, 1.0f)));
      vec3 t2 = cross(r, t1);
      const int n_angle = 3000, n_phi = 360;
      double mass = 0.0;
      for (int i = 0; i < n_angle; ++i) {
        double s = (i + 0.5) / n_angle;
        double angle = M_PI * s * s * s;
        double d_angle = 3.0 * M_PI * s * s / n_angle;
        for (int j = 0; j < n_phi; ++j) {
          double phi = 2.0 * M_PI * (j + 0.5) / n_phi;
          vec3 wo = float(std::cos(angle)) * r + float(std::sin(angle) * std::cos(phi)) * t1 +
                    float(std::sin(angle) * std::sin(phi)) * t2;
          mass += bsdf_pdf(m, vec2(0.5f), wi, normalize(wo)) * std::sin(angle) * d_angle *
                  (2.0 * M_PI / n_phi);
        }
      }
      const int n = 100000;
      int succeeded = 0;
      for (int i = 0; i < n; ++i) {
        if (bsdf_sample(m, vec2(0.5f), wi, uni(rng), vec2(uni(rng), uni(rng))).pdf > 0.0f)
          ++succeeded;
      }
      double rate = double(succeeded) / n;
      double sigma = std::sqrt(std::max(rate * (1.0 - rate), 1e-4) / n);
      EXPECT_NEAR(mass, rate, 5.0 * sigma + 1e-3) << "flags " << flags << " at " << degrees;
    }
  }
}

// ---- Known values ------------------------------------------------------------------------

TEST(BsdfValues, DiffuseIsLambertian) {
  Material m = diffuse(vec3(0.25f, 0.5f, 0.75f));
  vec3 wi = direction(0.6f, 0.0f);
  vec3 wo = direction(0.3f, 2.0f);
  vec3 f = bsdf_eval(m, vec2(0.0f), wi, wo);
  EXPECT_NEAR(f.y, 0.5f / float(M_PI) * 0.3f, 1e-6f);
  EXPECT_NEAR(bsdf_pdf(m, vec2(0.0f), wi, wo), 0.3f / float(M_PI), 1e-6f);
  EXPECT_EQ(bsdf_eval(m, vec2(0.0f), wi, direction(-0.3f, 2.0f)), vec3(0.0f));
  EXPECT_EQ(bsdf_eval(m, vec2(0.0f), direction(-0.6f, 0.0f), wo), vec3(0.0f));
  BsdfSample s = bsdf_sample(m, vec2(0.0f), wi, 0.5f, vec2(0.3f, 0.8f));
  EXPECT_EQ(s.weight, vec3(0.25f, 0.5f, 0.75f));
  EXPECT_EQ(s.lobe, BSDF_DIFFUSE_REFLECTION);
}

TEST(BsdfValues, TwosidedDiffuseFromBelow) {
  Material m = diffuse(vec3(0.5f));
  m.flags |= MATERIAL_TWOSIDED;
  vec3 wi = direction(-0.6f, 0.0f);
  vec3 wo = direction(-0.3f, 2.0f);
  EXPECT_NEAR(bsdf_eval(m, vec2(0.0f), wi, wo).x, 0.5f / float(M_PI) * 0.3f, 1e-6f);
  EXPECT_EQ(bsdf_eval(m, vec2(0.0f), wi, direction(0.3f, 2.0f)), vec3(0.0f));
  BsdfSample s = bsdf_sample(m, vec2(0.0f), wi, 0.5f, vec2(0.3f, 0.8f));
  EXPECT_LT(s.wo.z, 0.0f);
  EXPECT_EQ(s.weight, vec3(0.5f));
}

TEST(BsdfValues, ConductorMirror) {
  Material m = conductor(vec3(0.0f), vec3(1.0f));
  vec3 wi = direction(0.3f, 1.0f);
  BsdfSample s = bsdf_sample(m, vec2(0.0f), wi, 0.5f, vec2(0.5f));
  EXPECT_EQ(s.lobe, BSDF_DELTA_REFLECTION);
  EXPECT_NEAR(distance(s.wo, vec3(-wi.x, -wi.y, wi.z)), 0.0f, 1e-7f);
  EXPECT_NEAR(s.weight.x, 1.0f, 1e-6f);
  EXPECT_EQ(bsdf_eval(m, vec2(0.0f), wi, s.wo), vec3(0.0f));
  EXPECT_EQ(bsdf_pdf(m, vec2(0.0f), wi, s.wo), 0.0f);
  EXPECT_EQ(bsdf_sample(m, vec2(0.0f), direction(-0.3f, 1.0f), 0.5f, vec2(0.5f)).pdf, 0.0f);
}

TEST(BsdfValues, DielectricChoosesByFresnel) {
  Material m = dielectric(1.5f);
  vec3 wi = direction(1.0f, 0.0f);
  BsdfSample r = bsdf_sample(m, vec2(0.0f), wi, 0.01f, vec2(0.5f));
  EXPECT_EQ(r.lobe, BSDF_DELTA_REFLECTION);
  EXPECT_NEAR(r.pdf, 0.04f, 1e-6f);
  EXPECT_EQ(r.weight, vec3(1.0f));
  BsdfSample t = bsdf_sample(m, vec2(0.0f), wi, 0.5f, vec2(0.5f));
  EXPECT_EQ(t.lobe, BSDF_DELTA_TRANSMISSION);
  EXPECT_NEAR(t.pdf, 0.96f, 1e-6f);
  EXPECT_NEAR(t.weight.x, 1.0f / 2.25f, 1e-6f);  // radiance scaled by (n_i / n_t)^2
  EXPECT_FLOAT_EQ(t.eta, 1.5f);
  EXPECT_NEAR(t.wo.z, -1.0f, 1e-6f);
  // Total internal reflection from inside beyond the critical angle.
  BsdfSample tir = bsdf_sample(m, vec2(0.0f), direction(-0.5f, 0.0f), 0.999f, vec2(0.5f));
  EXPECT_EQ(tir.lobe, BSDF_DELTA_REFLECTION);
  EXPECT_EQ(tir.weight, vec3(1.0f));
  EXPECT_LT(tir.wo.z, 0.0f);
}

TEST(BsdfValues, PlasticLayers) {
  Material m = plastic(vec3(0.5f), 1.5f, false);
  float w = 1.0f / 1.5f;  // specular sampling weight for mean(R_d) = 0.5
  vec3 wi = direction(1.0f, 0.0f);
  vec3 wo = direction(0.5f, 1.0f);
  float f_o = fresnel_dielectric_reflectance(0.5f, 1.5f);
  float fdr_int = fresnel_diffuse_reflectance(1.0f / 1.5f);
  float expected = 0.5f / (1.0f - fdr_int) * 0.96f * (1.0f - f_o) * 0.5f / (float(M_PI) * 2.25f);
  EXPECT_NEAR(bsdf_eval(m, vec2(0.0f), wi, wo).x, expected, 1e-6f);
  float p_specular = 0.04f * w / (0.04f * w + 0.96f * (1.0f - w));
  EXPECT_NEAR(bsdf_pdf(m, vec2(0.0f), wi, wo), (1.0f - p_specular) * 0.5f / float(M_PI), 1e-6f);
  BsdfSample s = bsdf_sample(m, vec2(0.0f), wi, 0.5f * p_specular, vec2(0.5f));
  EXPECT_EQ(s.lobe, BSDF_DELTA_REFLECTION);
  EXPECT_NEAR(s.pdf, p_specular, 1e-6f);
  EXPECT_NEAR(s.weight.x, 0.04f / p_specular, 1e-5f);
  // nonlinear: R_d / (1 - R_d F_dr).
  Material nl = plastic(vec3(0.5f), 1.5f, true);
  EXPECT_NEAR(bsdf_eval(nl, vec2(0.0f), wi, wo).x,
              expected * (1.0f - fdr_int) / (1.0f - 0.5f * fdr_int), 1e-6f);
}

// Parameters come through eval_textured: a checkerboard switches them across uv.
TEST(BsdfValues, TexturedParameters) {
  TestScene& scene = test_scene();
  Texture checker{};
  checker.type = TEXTURE_CHECKERBOARD;
  checker.color0 = vec4(0.2f, 0.2f, 0.2f, 1.0f);
  checker.color1 = vec4(0.8f, 0.4f, 0.1f, 1.0f);
  checker.to_uv[0] = vec4(1.0f, 0.0f, 0.0f, 0.0f);
  checker.to_uv[1] = vec4(0.0f, 1.0f, 0.0f, 0.0f);
  uint index = uint(scene.textures.size());
  scene.textures.push_back(checker);
  Material m = diffuse(vec3(0.5f));
  m.param[DIFFUSE_REFLECTANCE].texture = index;
  m.flags |= MATERIAL_TEXTURED;
  vec3 wi = direction(0.8f, 0.0f);
  BsdfSample s0 = bsdf_sample(m, vec2(0.25f, 0.25f), wi, 0.5f, vec2(0.5f));
  BsdfSample s1 = bsdf_sample(m, vec2(0.75f, 0.25f), wi, 0.5f, vec2(0.5f));
  EXPECT_NEAR(distance(s0.weight, vec3(0.2f)), 0.0f, 1e-6f);
  EXPECT_NEAR(distance(s1.weight, vec3(0.8f, 0.4f, 0.1f)), 0.0f, 1e-6f);
  // Scalar parameters read the first channel of a (grey, loader-reduced) texture.
  Texture grey = checker;
  grey.color0 = vec4(0.2f, 0.2f, 0.2f, 1.0f);
  grey.color1 = vec4(0.45f, 0.45f, 0.45f, 1.0f);
  uint grey_index = uint(scene.textures.size());
  scene.textures.push_back(grey);
  Material rough = rough_conductor(0u, 0.1f, 0.1f, vec3(0.0f), vec3(1.0f));
  rough.param[CONDUCTOR_ALPHA_U].texture = grey_index;
  rough.param[CONDUCTOR_ALPHA_V].texture = grey_index;
  rough.flags |= MATERIAL_TEXTURED;
  vec3 wo = direction(0.7f, 3.0f);
  for (float u : {0.25f, 0.75f}) {
    float alpha = u < 0.5f ? 0.2f : 0.45f;
    Material ref = rough_conductor(0u, alpha, alpha, vec3(0.0f), vec3(1.0f));
    EXPECT_NEAR(bsdf_eval(rough, vec2(u, 0.25f), wi, wo).x,
                bsdf_eval(ref, vec2(u, 0.25f), wi, wo).x, 1e-5f)
        << u;
  }
}

TEST(BsdfValues, MaskPassesThrough) {
  Material m = diffuse(vec3(0.5f));
  m.flags |= MATERIAL_MASKED;
  m.opacity = constant(0.25f);
  vec3 wi = direction(0.6f, 0.0f);
  vec3 wo = direction(0.3f, 2.0f);
  EXPECT_NEAR(bsdf_eval(m, vec2(0.0f), wi, wo).x, 0.25f * 0.5f / float(M_PI) * 0.3f, 1e-7f);
  EXPECT_NEAR(bsdf_pdf(m, vec2(0.0f), wi, wo), 0.25f * 0.3f / float(M_PI), 1e-7f);
  BsdfSample null = bsdf_sample(m, vec2(0.0f), wi, 0.5f, vec2(0.5f));
  EXPECT_EQ(null.lobe, BSDF_NULL);
  EXPECT_EQ(null.wo, -wi);
  EXPECT_EQ(null.weight, vec3(1.0f));
  EXPECT_NEAR(null.pdf, 0.75f, 1e-7f);
  EXPECT_TRUE((bsdf_flags(m, vec2(0.0f)) & BSDF_NULL) != 0u);
  BsdfSample nested = bsdf_sample(m, vec2(0.0f), wi, 0.1f, vec2(0.5f));
  EXPECT_EQ(nested.lobe, BSDF_DIFFUSE_REFLECTION);
  EXPECT_EQ(nested.weight, vec3(0.5f));
}

}  // namespace
}  // namespace tr
