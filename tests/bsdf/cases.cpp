#include "cases.h"

#include <algorithm>
#include <cmath>
#include <functional>
#include <sstream>

#include "core/microfacet.h"
#include "core/warp.h"
#include "suite_size.h"
#include "support/materials.h"

namespace tr::bsdf_suite {
namespace tv = twinray::validation;
namespace {

// Incident directions of the chi-square grid (degrees from the normal, azimuth 20°): normal,
// oblique, and the grazing 85° and 89.9° the issue asks for; from below for two-sided and
// transmissive BSDFs; one from below for one-sided BSDFs (nothing may be sampled there).
std::vector<glm::vec3> angles(std::initializer_list<double> thetas) {
  std::vector<glm::vec3> result;
  for (double t : thetas) result.push_back(tv::direction_from_angles(t, 20.0));
  return result;
}
const std::vector<glm::vec3> kFront = angles({0.0, 30.0, 60.0, 85.0, 89.9});
const std::vector<glm::vec3> kOneSided = angles({0.0, 30.0, 60.0, 85.0, 89.9, 120.0});
const std::vector<glm::vec3> kBothSides = angles({0.0, 30.0, 60.0, 85.0, 89.9, 150.0, 95.0, 90.1});

std::string fmt(float x) {
  std::ostringstream s;
  s << x;
  return s.str();
}

const char* name_of(Distribution d) { return d == Distribution::ggx ? "ggx" : "beckmann"; }

// ---- Statistical cases -----------------------------------------------------------------

class StatisticalList {
 public:
  std::vector<StatisticalCase> cases;

  void directions(const std::string& family, const std::string& name,
                  std::function<vec3(CoreCalls&, vec2)> sample,
                  std::function<float(CoreCalls&, vec3)> pdf) {
    StatisticalCase c;
    c.family = family;
    c.directions = [name, sample, pdf](CoreCalls& calls) {
      tv::DirectionSampler s;
      s.name = name;
      s.sample = [&calls, sample, pdf](const glm::vec2& u) {
        tv::DirectionSample d;
        d.w = sample(calls, u);
        d.pdf = pdf(calls, d.w);
        return d;
      };
      s.pdf = [&calls, pdf](const glm::vec3& w) { return pdf(calls, w); };
      return s;
    };
    cases.push_back(c);
  }

  void planar(const std::string& family, std::function<tv::PlanarSampler(CoreCalls&)> s) {
    StatisticalCase c;
    c.family = family;
    c.planar = std::move(s);
    cases.push_back(c);
  }

  // A BSDF at the given incident directions; transmissive ones get their albedo tested on
  // energy weights.
  void bsdf(const std::string& family, const std::string& name, std::function<Material()> m,
            const std::vector<glm::vec3>& incident, bool transmissive,
            bool energy_conserving = true, bool reciprocal = true) {
    StatisticalCase c;
    c.energy_conserving = energy_conserving;
    c.reciprocal = reciprocal;
    c.family = family;
    c.bsdf_name = name;
    c.material = std::move(m);
    c.incident = incident;
    c.transmissive = transmissive;
    cases.push_back(c);
  }
};

void add_warps(StatisticalList& list) {
  auto warp = [&list](const std::string& name, Warp w, float parameter) {
    list.directions(
        "warps", name,
        [w, parameter](CoreCalls& calls, vec2 u) { return calls.warp_direction(w, parameter, u); },
        [w, parameter](CoreCalls& calls, vec3 d) {
          return calls.warp_direction_pdf(w, parameter, d);
        });
  };
  warp("square_to_cosine_hemisphere", Warp::cosine_hemisphere, 0.0f);
  warp("square_to_uniform_sphere", Warp::uniform_sphere, 0.0f);
  warp("square_to_uniform_hemisphere", Warp::uniform_hemisphere, 0.0f);
  for (float cos_max : {-0.5f, 0.3f, 0.9f}) {
    warp("square_to_uniform_cone cos_max=" + fmt(cos_max), Warp::uniform_cone, cos_max);
  }
  list.planar("warps", [](CoreCalls& calls) {
    tv::PlanarSampler disk;
    disk.name = "square_to_uniform_disk_concentric";
    disk.sample = [&calls](const glm::vec2& u) {
      return calls.warp_point(Warp::disk_concentric, u);
    };
    disk.pdf = [&calls](const glm::vec2& p) {
      return calls.warp_point_pdf(Warp::disk_concentric, p);
    };
    disk.lower = vec2(-1.0f);
    disk.upper = vec2(1.0f);
    return disk;
  });
  // Uniform triangles through barycentrics: density 1/area inside, 0 outside (a point may sit
  // on an edge up to float rounding of the barycentric combination: 1e-6 slack).
  struct Triangle {
    const char* name;
    vec2 p0, p1, p2;
  };
  for (Triangle t : {Triangle{"right", vec2(0.0f), vec2(1.0f, 0.0f), vec2(0.0f, 1.0f)},
                     Triangle{"skewed", vec2(0.1f, 0.2f), vec2(0.9f, 0.4f), vec2(0.3f, 0.95f)}}) {
    list.planar("warps", [t](CoreCalls& calls) {
      tv::PlanarSampler s;
      s.name = std::string("square_to_uniform_triangle ") + t.name;
      s.sample = [&calls, t](const glm::vec2& u) {
        vec2 b = calls.warp_point(Warp::triangle, u);
        return (1.0f - b.x - b.y) * t.p0 + b.x * t.p1 + b.y * t.p2;
      };
      s.pdf = [t](const glm::vec2& p) {
        auto cross2 = [](vec2 a, vec2 b) { return a.x * b.y - a.y * b.x; };
        float area2 = cross2(t.p1 - t.p0, t.p2 - t.p0);
        float b1 = cross2(p - t.p0, t.p2 - t.p0) / area2;
        float b2 = cross2(t.p1 - t.p0, p - t.p0) / area2;
        bool inside = b1 >= -1e-6f && b2 >= -1e-6f && b1 + b2 <= 1.0f + 1e-6f;
        return inside ? 2.0f / std::abs(area2) : 0.0f;
      };
      s.lower = vec2(0.0f);
      s.upper = vec2(1.0f);
      return s;
    });
  }
}

void add_microfacet_normals(StatisticalList& list) {
  for (bool beckmann : {false, true}) {
    for (vec2 alpha : {vec2(0.3f), vec2(0.1f, 0.5f)}) {
      for (bool visible : {true, false}) {
        Microfacet d = microfacet_make(beckmann, alpha.x, alpha.y, visible);
        vec3 wi = tv::direction_from_angles(60.0, 20.0);
        std::string name = std::string("microfacet ") + (beckmann ? "beckmann" : "ggx") +
                           " a=" + fmt(alpha.x) + "," + fmt(alpha.y) +
                           (visible ? " visible" : " all") + " wi=60";
        list.directions(
            "microfacet_normals", name,
            [d, wi](CoreCalls& calls, vec2 u) { return calls.microfacet_sample(d, wi, u); },
            [d, wi](CoreCalls& calls, vec3 m) { return calls.microfacet_pdf(d, wi, m); });
      }
    }
  }
}

void add_bsdfs(StatisticalList& list) {
  const vec3 gold_eta(0.143f, 0.375f, 1.442f), gold_k(3.983f, 2.386f, 1.603f);
  if (bsdf_available(diffuse(vec3(0.5f)))) {
    list.bsdf(
        "diffuse", "diffuse", [=] { return diffuse(vec3(0.2f, 0.5f, 0.9f)); }, kOneSided, false);
    list.bsdf(
        "twosided", "twosided(diffuse)", [=] { return twosided(diffuse(vec3(0.2f, 0.5f, 0.9f))); },
        kBothSides, false);
    list.bsdf(
        "mask", "mask(diffuse) opacity=0.3", [=] { return masked(diffuse(vec3(0.7f)), 0.3f); },
        kOneSided, false);
  }
  if (bsdf_available(conductor(gold_eta, gold_k, vec3(1.0f)))) {
    list.bsdf(
        "conductor", "conductor gold", [=] { return conductor(gold_eta, gold_k, vec3(1.0f)); },
        kOneSided, false);
  }
  if (bsdf_available(dielectric(1.5f, vec3(1.0f), vec3(1.0f)))) {
    for (float eta : {1.5f, 1.0f / 1.5f, 1.33f}) {
      list.bsdf(
          "dielectric", "dielectric eta=" + fmt(eta),
          [=] { return dielectric(eta, vec3(1.0f), vec3(1.0f)); }, kBothSides, true);
    }
    list.bsdf(
        "mask", "mask(dielectric eta=1.5) opacity=0.6",
        [=] { return masked(dielectric(1.5f, vec3(1.0f), vec3(1.0f)), 0.6f); }, kBothSides, true);
  }
  const Distribution distributions[] = {Distribution::ggx, Distribution::beckmann};
  const vec2 alphas[] = {vec2(0.05f), vec2(0.2f),        vec2(0.5f),
                         vec2(1.0f),  vec2(0.05f, 0.3f), vec2(0.6f, 0.1f)};
  if (bsdf_available(
          roughconductor(Distribution::ggx, 0.1f, 0.1f, true, gold_eta, gold_k, vec3(1.0f)))) {
    for (Distribution d : distributions) {
      for (vec2 a : alphas) {
        for (bool visible : {true, false}) {
          std::string name = std::string("roughconductor ") + name_of(d) + " a=" + fmt(a.x) +
                             (a.x == a.y ? "" : "," + fmt(a.y)) + (visible ? " vis" : " all");
          list.bsdf(
              std::string("roughconductor_") + name_of(d), name,
              [=] { return roughconductor(d, a.x, a.y, visible, gold_eta, gold_k, vec3(1.0f)); },
              kOneSided, false);
        }
      }
      std::string name = std::string("twosided(roughconductor ") + name_of(d) + " a=0.3)";
      list.bsdf(
          "twosided", name,
          [=] {
            return twosided(roughconductor(d, 0.3f, 0.3f, true, gold_eta, gold_k, vec3(1.0f)));
          },
          kBothSides, false);
    }
  }
  if (bsdf_available(
          roughdielectric(Distribution::ggx, 0.1f, 0.1f, true, 1.5f, vec3(1.0f), vec3(1.0f)))) {
    const vec2 rough_alphas[] = {vec2(0.05f), vec2(0.3f), vec2(1.0f), vec2(0.1f, 0.4f)};
    for (Distribution d : distributions) {
      for (vec2 a : rough_alphas) {
        for (float eta : {1.5f, 1.0f / 1.5f, 1.33f}) {
          for (bool visible : {true, false}) {
            if (!visible && eta != 1.5f) continue;
            std::string name = std::string("roughdielectric ") + name_of(d) + " a=" + fmt(a.x) +
                               (a.x == a.y ? "" : "," + fmt(a.y)) + " eta=" + fmt(eta) +
                               (visible ? " vis" : " all");
            list.bsdf(
                std::string("roughdielectric_") + name_of(d), name,
                [=] { return roughdielectric(d, a.x, a.y, visible, eta, vec3(1.0f), vec3(1.0f)); },
                kBothSides, true);
          }
        }
      }
    }
  }
  if (bsdf_available(thindielectric(1.5f, vec3(1.0f), vec3(1.0f)))) {
    for (float eta : {1.5f, 1.33f, 1.0f / 1.5f}) {
      list.bsdf(
          "thindielectric", "thindielectric eta=" + fmt(eta),
          [=] { return thindielectric(eta, vec3(1.0f), vec3(1.0f)); }, kBothSides, false);
    }
  }
  const vec3 plastic_diffuse(0.5f, 0.3f, 0.1f);
  if (bsdf_available(plastic(1.5f, plastic_diffuse, vec3(1.0f), false))) {
    for (float eta : {1.5f, 1.33f}) {
      for (bool nonlinear : {false, true}) {
        list.bsdf(
            "plastic", "plastic eta=" + fmt(eta) + (nonlinear ? " nonlinear" : " linear"),
            [=] { return plastic(eta, plastic_diffuse, vec3(1.0f), nonlinear); }, kOneSided, false);
      }
    }
  }
  if (bsdf_available(
          roughplastic(Distribution::ggx, 0.1f, true, 1.5f, plastic_diffuse, vec3(1.0f), false))) {
    for (Distribution d : distributions) {
      for (float alpha : {0.05f, 0.3f, 1.0f}) {
        for (bool nonlinear : {false, true}) {
          for (bool visible : {true, false}) {
            std::string name = std::string("roughplastic ") + name_of(d) + " a=" + fmt(alpha) +
                               (nonlinear ? " nonlinear" : " linear") + (visible ? " vis" : " all");
            list.bsdf(
                std::string("roughplastic_") + name_of(d), name,
                [=] {
                  return roughplastic(d, alpha, visible, 1.5f, plastic_diffuse, vec3(1.0f),
                                      nonlinear);
                },
                kOneSided, false);
          }
        }
      }
      list.bsdf(
          std::string("roughplastic_") + name_of(d),
          std::string("roughplastic ") + name_of(d) + " a=0.3 eta=1.33 linear vis",
          [=] { return roughplastic(d, 0.3f, true, 1.33f, plastic_diffuse, vec3(1.0f), false); },
          kOneSided, false);
    }
  }
  if (bsdf_type_available(BSDF_PPLASTIC)) {
    // The lobe mixture at several roughnesses, anisotropic, with either reflectance black
    // (one lobe alone is sampled) and at a second eta.
    struct Setting {
      std::string name;
      float alpha_u, alpha_v, eta;
      vec3 diffuse, specular;
    };
    const Setting settings[] = {
        {"a=0.05", 0.05f, 0.05f, 1.49f, plastic_diffuse, vec3(1.0f)},
        {"a=0.3", 0.3f, 0.3f, 1.49f, plastic_diffuse, vec3(1.0f)},
        {"a=1", 1.0f, 1.0f, 1.49f, plastic_diffuse, vec3(1.0f)},
        {"a=0.05,0.6", 0.05f, 0.6f, 1.49f, plastic_diffuse, vec3(1.0f)},
        {"a=0.3 eta=1.2", 0.3f, 0.3f, 1.2f, plastic_diffuse, vec3(0.5f)},
        {"a=0.3 diffuse=0", 0.3f, 0.3f, 1.49f, vec3(0.0f), vec3(1.0f)},
        {"a=0.3 specular=0", 0.3f, 0.3f, 1.49f, plastic_diffuse, vec3(0.0f)},
    };
    for (Distribution d : distributions) {
      for (const Setting& s : settings) {
        for (bool visible : {true, false}) {
          // Sampling all normals is checked on the plain isotropic settings only.
          if (!visible && (s.alpha_u != s.alpha_v || s.diffuse != plastic_diffuse)) continue;
          list.bsdf(
              std::string("pplastic_") + name_of(d),
              std::string("pplastic ") + name_of(d) + " " + s.name + (visible ? " vis" : " all"),
              [=] {
                return pplastic(d, s.alpha_u, s.alpha_v, visible, s.eta, s.diffuse, s.specular);
              },
              kOneSided, false);
        }
      }
    }
  }
  if (bsdf_available(diffuse(vec3(0.5f))) && bsdf_type_available(BSDF_BLEND)) {
    const Material rough_gold =
        roughconductor(Distribution::ggx, 0.3f, 0.3f, true, gold_eta, gold_k, vec3(1.0f));
    const Material rough_glass =
        roughdielectric(Distribution::beckmann, 0.3f, 0.3f, true, 1.5f, vec3(1.0f), vec3(1.0f));
    const Material blue = diffuse(vec3(0.2f, 0.5f, 0.9f));
    for (float w : {0.3f, 0.9f}) {
      list.bsdf(
          "blendbsdf", "blendbsdf(diffuse, roughconductor ggx a=0.3) w=" + fmt(w),
          [=] { return blend(blue, rough_gold, w); }, kOneSided, false);
    }
    list.bsdf(
        "blendbsdf", "blendbsdf(roughdielectric beckmann a=0.3, roughconductor) w=0.6",
        [=] { return blend(rough_glass, rough_gold, 0.6f); }, kBothSides, true);
    list.bsdf(
        "blendbsdf", "twosided(blendbsdf(diffuse, roughconductor)) w=0.5",
        [=] { return twosided(blend(blue, rough_gold, 0.5f)); }, kBothSides, false);
    list.bsdf(
        "blendbsdf", "blendbsdf(blendbsdf(diffuse, roughconductor) w=0.3, roughplastic) w=0.7",
        [=] {
          Material plastic_rough = roughplastic(Distribution::beckmann, 0.2f, true, 1.5f,
                                                vec3(0.5f, 0.3f, 0.1f), vec3(1.0f), false);
          return blend(blend(blue, rough_gold, 0.3f), plastic_rough, 0.7f);
        },
        kOneSided, false);
    list.bsdf(
        "blendbsdf", "blendbsdf(mask(diffuse) opacity=0.4, twosided(roughconductor)) w=0.5",
        [=] { return blend(masked(blue, 0.4f), twosided(rough_gold), 0.5f); }, kBothSides, false);
    list.bsdf(
        "blendbsdf", "blendbsdf(conductor, diffuse) w=0.5",
        [=] { return blend(conductor(gold_eta, gold_k, vec3(1.0f)), blue, 0.5f); }, kOneSided,
        false);
  }
  if (bsdf_available(diffuse(vec3(0.5f))) && bsdf_type_available(BSDF_NORMALMAP)) {
    const Material rough_gold =
        roughconductor(Distribution::ggx, 0.3f, 0.3f, true, gold_eta, gold_k, vec3(1.0f));
    const Material blue = diffuse(vec3(0.2f, 0.5f, 0.9f));
    // Tilted normals: 30, 60 and 80 degrees, one below the horizon (n.z < 0).
    const vec3 n30 = tv::direction_from_angles(30.0, 70.0);
    const vec3 n60 = tv::direction_from_angles(60.0, 200.0);
    const vec3 n80 = tv::direction_from_angles(80.0, 10.0);
    const vec3 below = tv::direction_from_angles(110.0, 45.0);
    // At wi = 89.9 deg with the 60 deg normal, a sampled wo can lie within ~1e-5 of the perturbed
    // horizon, where the round trip of wo through the perturbed frame (as in Mitsuba) changes a
    // microfacet value by over 1% in about one draw in 20000: the consistency check's weight ==
    // eval / pdf is then a float conditioning test, so that case stops at 85 deg.
    const std::vector<glm::vec3> kFrontBelow85 = angles({0.0, 30.0, 60.0, 85.0, 120.0});
    list.bsdf(
        "normalmap", "normalmap(diffuse) n=30deg", [=] { return normalmap(blue, n30, true, true); },
        kOneSided, false, true, false);
    list.bsdf(
        "normalmap", "normalmap(diffuse) n=80deg no shadowing",
        [=] { return normalmap(blue, n80, true, false); }, kOneSided, false, true, false);
    list.bsdf(
        "normalmap", "normalmap(roughconductor ggx a=0.3) n=60deg",
        [=] { return normalmap(rough_gold, n60, true, true); }, kFrontBelow85, false, true, false);
    list.bsdf(
        "normalmap", "normalmap(diffuse) n=110deg (below) flip",
        [=] { return normalmap(blue, below, true, true); }, kOneSided, false, true, false);
    list.bsdf(
        "normalmap", "normalmap(diffuse) n=110deg (below) no flip",
        [=] { return normalmap(blue, below, false, true); }, kOneSided, false, true, false);
    list.bsdf(
        "normalmap", "normalmap(roughdielectric beckmann a=0.3 eta=1.5) n=30deg",
        [=] {
          return normalmap(roughdielectric(Distribution::beckmann, 0.3f, 0.3f, true, 1.5f,
                                           vec3(1.0f), vec3(1.0f)),
                           n30, true, true);
        },
        kBothSides, true, false, false);
    list.bsdf(
        "normalmap", "normalmap(blendbsdf(diffuse, roughconductor) w=0.5) n=60deg",
        [=] { return normalmap(blend(blue, rough_gold, 0.5f), n60, true, true); }, kOneSided, false,
        true, false);
    list.bsdf(
        "normalmap", "twosided(normalmap(diffuse)) n=30deg",
        [=] { return twosided(normalmap(blue, n30, true, true)); }, kBothSides, false, true, false);
  }
  if (bsdf_available(diffuse(vec3(0.5f))) && bsdf_type_available(BSDF_BUMPMAP)) {
    const Material rough_gold =
        roughconductor(Distribution::ggx, 0.3f, 0.3f, true, gold_eta, gold_k, vec3(1.0f));
    const Material blue = diffuse(vec3(0.2f, 0.5f, 0.9f));
    // Height slopes tilting the normal by atan(scale |slope|): 30 deg (scale 0.5), 60 deg
    // (scale 2.5) and 84 deg (scale 10, the flip then acts from wi = 6 deg off the horizon).
    const vec2 slope30(0.9f, -0.7f);   // |slope| = 1.14, tilt atan(0.57) = 29.7 deg
    const vec2 slope60(0.4f, 0.55f);   // |slope| = 0.68, tilt atan(1.70) = 59.6 deg
    const vec2 slope84(-0.8f, 0.45f);  // |slope| = 0.92, tilt atan(9.18) = 83.8 deg
    const std::vector<glm::vec3> kFrontBelow85 = angles({0.0, 30.0, 60.0, 85.0, 120.0});
    list.bsdf(
        "bumpmap", "bumpmap(diffuse) 30deg scale=0.5",
        [=] { return bumpmap(blue, slope30, 0.5f, true, true); }, kOneSided, false, true, false);
    list.bsdf(
        "bumpmap", "bumpmap(diffuse) 84deg scale=10 flip",
        [=] { return bumpmap(blue, slope84, 10.0f, true, true); }, kOneSided, false, true, false);
    list.bsdf(
        "bumpmap", "bumpmap(diffuse) 84deg scale=10 no flip no shadowing",
        [=] { return bumpmap(blue, slope84, 10.0f, false, false); }, kOneSided, false, true, false);
    list.bsdf(
        "bumpmap", "bumpmap(roughconductor ggx a=0.3) 60deg scale=-2.5",
        [=] { return bumpmap(rough_gold, slope60, -2.5f, true, true); }, kFrontBelow85, false, true,
        false);
    list.bsdf(
        "bumpmap", "bumpmap(roughdielectric beckmann a=0.3 eta=1.5) 30deg scale=0.5",
        [=] {
          return bumpmap(roughdielectric(Distribution::beckmann, 0.3f, 0.3f, true, 1.5f, vec3(1.0f),
                                         vec3(1.0f)),
                         slope30, 0.5f, true, true);
        },
        kBothSides, true, false, false);
    list.bsdf(
        "bumpmap", "bumpmap(blendbsdf(diffuse, roughconductor) w=0.5) 60deg scale=2.5",
        [=] { return bumpmap(blend(blue, rough_gold, 0.5f), slope60, 2.5f, true, true); },
        kOneSided, false, true, false);
    list.bsdf(
        "bumpmap", "twosided(bumpmap(diffuse)) 30deg scale=0.5",
        [=] { return twosided(bumpmap(blue, slope30, 0.5f, true, true)); }, kBothSides, false, true,
        false);
  }
  if (bsdf_available(principled(PrincipledParameters{}))) {
    // A grid over the weights: each lobe alone, pairs, and everything at once.
    struct Setting {
      const char* name;
      std::function<void(PrincipledParameters&)> set;
    };
    const Setting settings[] = {
        {"default", [](PrincipledParameters&) {}},
        {"metallic=1", [](PrincipledParameters& p) { p.metallic = 1.0f; }},
        {"metallic=0.5 roughness=0.2",
         [](PrincipledParameters& p) {
           p.metallic = 0.5f;
           p.roughness = 0.2f;
         }},
        {"anisotropic=0.8 metallic=1",
         [](PrincipledParameters& p) {
           p.anisotropic = 0.8f;
           p.metallic = 1.0f;
         }},
        {"flatness=1 roughness=0.8",
         [](PrincipledParameters& p) {
           p.flatness = 1.0f;
           p.roughness = 0.8f;
         }},
        {"sheen=1 sheen_tint=0.5",
         [](PrincipledParameters& p) {
           p.sheen = 1.0f;
           p.sheen_tint = 0.5f;
         }},
        {"clearcoat=1 gloss=0.5",
         [](PrincipledParameters& p) {
           p.clearcoat = 1.0f;
           p.clearcoat_gloss = 0.5f;
         }},
        {"spec_trans=1 roughness=0.3",
         [](PrincipledParameters& p) {
           p.spec_trans = 1.0f;
           p.roughness = 0.3f;
         }},
        {"spec_trans=0.5 eta=1.33",
         [](PrincipledParameters& p) {
           p.spec_trans = 0.5f;
           p.eta = 1.33f;
         }},
        {"specular=1 spec_tint=1 roughness=0.1",
         [](PrincipledParameters& p) {
           p.specular = 1.0f;
           p.spec_tint = 1.0f;
           p.roughness = 0.1f;
         }},
        {"all=0.5",
         [](PrincipledParameters& p) {
           p.metallic = p.spec_tint = p.anisotropic = p.sheen = p.sheen_tint = 0.5f;
           p.clearcoat = p.clearcoat_gloss = p.spec_trans = p.flatness = 0.5f;
         }},
        {"sampling_rates=(0.2,1,2)",
         [](PrincipledParameters& p) {
           p.clearcoat = 0.7f;
           p.sampling_rates = vec3(0.2f, 1.0f, 2.0f);
         }},
    };
    for (const Setting& s : settings) {
      PrincipledParameters p;
      p.base_color = vec3(0.8f, 0.5f, 0.2f);
      s.set(p);
      bool transmissive = p.spec_trans > 0.0f;
      list.bsdf(
          "principled", std::string("principled ") + s.name, [=] { return principled(p); },
          transmissive ? kBothSides : kOneSided, transmissive, false);
    }
  }
}

// ---- Extremes ---------------------------------------------------------------------------

const float kAlphas[] = {1e-4f, 1e-3f, 0.01f, 0.1f, 0.5f, 1.0f};
const float kEtas[] = {1.0f, 1.0001f, 1.33f, 1.5f, 2.42f, 4.0f, 1.0f / 1.5f};
const vec3 kReflectances[] = {vec3(0.0f), vec3(1.0f)};

std::vector<ExtremesCase> build_extremes() {
  std::vector<ExtremesCase> cases;
  auto add = [&](const std::string& family, const std::string& name, const Material& m) {
    if (bsdf_type_available(m.type)) cases.push_back({family, name, [m] { return m; }});
  };
  for (vec3 r : kReflectances) {
    add("diffuse", "diffuse r=" + fmt(r.x), diffuse(r));
    add("twosided", "twosided(diffuse r=" + fmt(r.x) + ")", twosided(diffuse(r)));
    for (float opacity : {0.0f, 0.5f, 1.0f}) {
      add("mask", "mask(diffuse r=" + fmt(r.x) + ") opacity=" + fmt(opacity),
          masked(diffuse(r), opacity));
    }
  }
  const vec2 conductor_iors[] = {vec2(0.0f, 1.0f), vec2(0.2f, 3.9f), vec2(1.5f, 0.0f),
                                 vec2(4.0f, 1e-4f), vec2(1.0f, 0.0f)};
  for (vec2 ior : conductor_iors) {
    for (vec3 r : kReflectances) {
      std::string p = " eta=" + fmt(ior.x) + " k=" + fmt(ior.y) + " r=" + fmt(r.x);
      add("conductor", "conductor" + p, conductor(vec3(ior.x), vec3(ior.y), r));
      for (Distribution d : {Distribution::ggx, Distribution::beckmann}) {
        for (bool visible : {true, false}) {
          for (float a : kAlphas) {
            std::string family = std::string("roughconductor_") + name_of(d);
            std::string v = visible ? " vis" : " all";
            add(family, "roughconductor " + std::string(name_of(d)) + " a=" + fmt(a) + v + p,
                roughconductor(d, a, a, visible, vec3(ior.x), vec3(ior.y), r));
            add(family, "roughconductor " + std::string(name_of(d)) + " a=" + fmt(a) + ",1" + v + p,
                roughconductor(d, a, 1.0f, visible, vec3(ior.x), vec3(ior.y), r));
          }
        }
      }
    }
  }
  for (float eta : kEtas) {
    for (vec3 r : kReflectances) {
      for (vec3 t : kReflectances) {
        std::string p = " eta=" + fmt(eta) + " r=" + fmt(r.x) + " t=" + fmt(t.x);
        add("dielectric", "dielectric" + p, dielectric(eta, r, t));
        add("thindielectric", "thindielectric" + p, thindielectric(eta, r, t));
        add("mask", "mask(dielectric" + p + ") opacity=0.5", masked(dielectric(eta, r, t), 0.5f));
        for (Distribution d : {Distribution::ggx, Distribution::beckmann}) {
          for (bool visible : {true, false}) {
            for (float a : kAlphas) {
              add(std::string("roughdielectric_") + name_of(d),
                  "roughdielectric " + std::string(name_of(d)) + " a=" + fmt(a) +
                      (visible ? " vis" : " all") + p,
                  roughdielectric(d, a, a, visible, eta, r, t));
            }
          }
        }
      }
      for (vec3 diff : kReflectances) {
        for (bool nonlinear : {false, true}) {
          std::string p = " eta=" + fmt(eta) + " d=" + fmt(diff.x) + " s=" + fmt(r.x) +
                          (nonlinear ? " nonlinear" : " linear");
          add("plastic", "plastic" + p, plastic(eta, diff, r, nonlinear));
          for (Distribution d : {Distribution::ggx, Distribution::beckmann}) {
            for (float a : kAlphas) {
              std::string name = "roughplastic " + std::string(name_of(d)) + " a=" + fmt(a) + p;
              if (!bsdf_type_available(BSDF_ROUGHPLASTIC)) continue;
              cases.push_back({std::string("roughplastic_") + name_of(d), name,
                               [=] { return roughplastic(d, a, true, eta, diff, r, nonlinear); }});
            }
          }
        }
      }
    }
  }
  // pplastic: roughness, eta and both reflectances over the extremes.
  for (float eta : kEtas) {
    if (eta == 1.0f) continue;  // refused by the loader: int_ior and ext_ior must differ
    for (vec3 diff : kReflectances) {
      for (vec3 r : kReflectances) {
        for (Distribution d : {Distribution::ggx, Distribution::beckmann}) {
          for (float a : kAlphas) {
            add(std::string("pplastic_") + name_of(d),
                "pplastic " + std::string(name_of(d)) + " a=" + fmt(a) + " eta=" + fmt(eta) +
                    " d=" + fmt(diff.x) + " s=" + fmt(r.x),
                pplastic(d, a, a, true, eta, diff, r));
          }
        }
      }
    }
  }
  if (bsdf_type_available(BSDF_BLEND)) {
    for (float w : {0.0f, 1e-6f, 0.5f, 1.0f - 1e-6f, 1.0f}) {
      for (vec3 r : kReflectances) {
        std::string p = " w=" + fmt(w) + " r=" + fmt(r.x);
        add("blendbsdf", "blendbsdf(diffuse, conductor)" + p,
            blend(diffuse(r), conductor(vec3(0.2f), vec3(3.9f), r), w));
        add("blendbsdf", "blendbsdf(roughdielectric a=1e-3, diffuse)" + p,
            blend(roughdielectric(Distribution::ggx, 1e-3f, 1e-3f, true, 1.5f, r, r), diffuse(r),
                  w));
        add("blendbsdf", "blendbsdf(dielectric, roughconductor a=1e-4)" + p,
            blend(dielectric(1.5f, r, r),
                  roughconductor(Distribution::beckmann, 1e-4f, 1e-4f, true, vec3(0.2f), vec3(3.9f),
                                 r),
                  w));
        add("blendbsdf", "twosided(blendbsdf(blendbsdf(diffuse, plastic), mask(diffuse) 0.5))" + p,
            twosided(blend(blend(diffuse(r), plastic(1.5f, r, r, false), w),
                           masked(diffuse(r), 0.5f), 1.0f - w)));
      }
    }
  }
  if (bsdf_type_available(BSDF_NORMALMAP)) {
    // Normals from the axis to nearly tangent and below the horizon, with flipping on and off;
    // the (1, 0, 0) normal leaves Mitsuba's tangent construction without a direction.
    for (double theta : {0.0, 45.0, 89.9, 90.0, 90.1, 135.0, 180.0}) {
      for (double phi : {0.0, 30.0}) {
        for (bool flip : {true, false}) {
          vec3 n = tv::direction_from_angles(theta, phi);
          std::string p = " n=(" + fmt(float(theta)) + "," + fmt(float(phi)) + ")" +
                          (flip ? " flip" : " noflip");
          add("normalmap", "normalmap(diffuse r=1)" + p,
              normalmap(diffuse(vec3(1.0f)), n, flip, true));
          add("normalmap", "normalmap(dielectric)" + p,
              normalmap(dielectric(1.5f, vec3(1.0f), vec3(1.0f)), n, flip, true));
          add("normalmap", "normalmap(roughconductor a=1e-3)" + p,
              normalmap(roughconductor(Distribution::ggx, 1e-3f, 1e-3f, true, vec3(0.2f),
                                       vec3(3.9f), vec3(1.0f)),
                        n, flip, false));
        }
      }
    }
    add("normalmap", "normalmap(diffuse) n=0",
        normalmap(diffuse(vec3(1.0f)), vec3(0.0f), true, true));
  }
  if (bsdf_type_available(BSDF_BUMPMAP)) {
    // Scale 0 (no perturbation), moderate, huge (the normal within 1e-6 rad of the tangent
    // plane) and infinite-like (the cross product overflows), negative, with flipping on and off.
    for (float scale : {0.0f, 1.0f, -3.0f, 1e6f, -1e6f, 1e30f}) {
      for (vec2 slope : {vec2(1.0f, 0.0f), vec2(0.3f, -0.8f)}) {
        for (bool flip : {true, false}) {
          std::string p = " scale=" + fmt(scale) + " slope=(" + fmt(slope.x) + "," + fmt(slope.y) +
                          ")" + (flip ? " flip" : " noflip");
          add("bumpmap", "bumpmap(diffuse r=1)" + p,
              bumpmap(diffuse(vec3(1.0f)), slope, scale, flip, true));
          add("bumpmap", "bumpmap(dielectric)" + p,
              bumpmap(dielectric(1.5f, vec3(1.0f), vec3(1.0f)), slope, scale, flip, true));
          add("bumpmap", "bumpmap(roughconductor a=1e-3)" + p,
              bumpmap(roughconductor(Distribution::ggx, 1e-3f, 1e-3f, true, vec3(0.2f), vec3(3.9f),
                                     vec3(1.0f)),
                      slope, scale, flip, false));
        }
      }
    }
  }
  // principled: every weight at 0, 0.5 and 1 (one at a time from the all-0.5 setting), all at
  // 0 and all at 1, over the roughness and eta grids and black/white base colour.
  auto weights = [](PrincipledParameters& p, float w) {
    p.metallic = p.specular = p.spec_tint = p.anisotropic = p.sheen = p.sheen_tint = w;
    p.clearcoat = p.clearcoat_gloss = p.spec_trans = p.flatness = w;
  };
  float PrincipledParameters::*fields[] = {
      &PrincipledParameters::metallic,   &PrincipledParameters::specular,
      &PrincipledParameters::spec_tint,  &PrincipledParameters::anisotropic,
      &PrincipledParameters::sheen,      &PrincipledParameters::sheen_tint,
      &PrincipledParameters::clearcoat,  &PrincipledParameters::clearcoat_gloss,
      &PrincipledParameters::spec_trans, &PrincipledParameters::flatness};
  const char* field_names[] = {"metallic",   "specular",   "spec_tint", "anisotropic",
                               "sheen",      "sheen_tint", "clearcoat", "clearcoat_gloss",
                               "spec_trans", "flatness"};
  for (vec3 base : kReflectances) {
    for (float roughness : {0.0f, 0.01f, 0.5f, 1.0f}) {
      for (float eta : kEtas) {
        for (float all : {0.0f, 1.0f}) {
          PrincipledParameters p;
          weights(p, all);
          p.base_color = base;
          p.roughness = roughness;
          p.eta = eta;
          add("principled",
              "principled all=" + fmt(all) + " base=" + fmt(base.x) +
                  " roughness=" + fmt(roughness) + " eta=" + fmt(eta),
              principled(p));
        }
      }
      for (int f = 0; f < 10; ++f) {
        for (float w : {0.0f, 0.5f, 1.0f}) {
          PrincipledParameters p;
          weights(p, 0.5f);
          p.*fields[f] = w;
          p.base_color = base;
          p.roughness = roughness;
          add("principled",
              std::string("principled ") + field_names[f] + "=" + fmt(w) + " base=" + fmt(base.x) +
                  " roughness=" + fmt(roughness),
              principled(p));
        }
      }
    }
  }
  return cases;
}

std::vector<std::string> families_of(const std::vector<std::string>& all) {
  std::vector<std::string> unique;
  for (const std::string& f : all) {
    if (std::find(unique.begin(), unique.end(), f) == unique.end()) unique.push_back(f);
  }
  return unique;
}

}  // namespace

const std::vector<StatisticalCase>& statistical_cases() {
  static const std::vector<StatisticalCase> cases = [] {
    StatisticalList list;
    add_warps(list);
    add_microfacet_normals(list);
    add_bsdfs(list);
    return list.cases;
  }();
  return cases;
}

const std::vector<ExtremesCase>& extremes_cases() {
  static const std::vector<ExtremesCase> cases = build_extremes();
  return cases;
}

// Per BSDF and incident direction: chi-square, and albedo (on radiance or energy weights) where
// the model conserves energy.
std::size_t statistical_test_count(const StatisticalCase& c) {
  return c.material ? (c.energy_conserving ? 2 : 1) * c.incident.size() : 1;
}

std::size_t statistical_test_count() {
  std::size_t n = 0;
  for (const StatisticalCase& c : statistical_cases()) n += statistical_test_count(c);
  return n;
}

double alpha_per_test() { return tv::sidak_alpha(kSignificance, statistical_test_count()); }

std::vector<std::string> statistical_families() {
  std::vector<std::string> all;
  for (const StatisticalCase& c : statistical_cases()) all.push_back(c.family);
  return families_of(all);
}

std::vector<std::string> extremes_families() {
  std::vector<std::string> all;
  for (const ExtremesCase& c : extremes_cases()) all.push_back(c.family);
  return families_of(all);
}

tv::ValidationOptions validation_options(const SuiteSize& size, double alpha) {
  tv::ValidationOptions o;
  o.chi_square = size.chi_square;
  o.consistency = size.consistency;
  o.albedo_samples = size.albedo_samples;
  o.extreme_random_draws = size.extreme_random_draws;
  o.significance = kSignificance;
  o.alpha_per_test = alpha;
  return o;
}

tv::Report run_statistical_case(const StatisticalCase& c, std::size_t number, double alpha,
                                const SuiteSize& size, CoreCalls& calls) {
  tv::CheckRunner run = [&calls](const std::function<void()>& check) { calls.run_check(check); };
  tv::Report report;
  tv::ChiSquareOptions chi = size.chi_square;
  chi.seed = 0x7715ull * number;
  if (c.directions) {
    tv::DirectionSampler sampler = c.directions(calls);
    tv::ChiSquareResult r;
    run([&] { r = tv::chi_square_directions(sampler, chi); });
    report.checks.push_back(tv::report_line(sampler.name, glm::vec3(0.0f), r, alpha));
  }
  if (c.planar) {
    tv::PlanarSampler sampler = c.planar(calls);
    tv::ChiSquareResult r;
    run([&] { r = tv::chi_square_planar(sampler, chi); });
    report.checks.push_back(tv::report_line(sampler.name, glm::vec3(0.0f), r, alpha));
  }
  if (c.material) {
    Material m = c.material();
    tv::BsdfUnderTest bsdf = core_bsdf(c.bsdf_name, m, calls);
    bsdf.energy_conserving = c.energy_conserving && !c.transmissive;
    bsdf.reciprocal = c.reciprocal;
    tv::ValidationOptions o = validation_options(size, alpha);
    o.chi_square = chi;
    o.consistency.seed = chi.seed + 1;
    o.run_check = run;
    report.append(tv::validate_bsdf(bsdf, c.incident, o));
    if (c.transmissive && c.energy_conserving) {
      tv::BsdfUnderTest energy = energy_weights(c.bsdf_name + " [energy]", m, calls);
      std::uint64_t k = 0;
      for (const glm::vec3& wi : c.incident) {
        tv::AlbedoResult a;
        std::uint64_t seed = chi.seed + 31 * ++k;
        run([&] { a = tv::albedo_test(energy, wi, size.albedo_samples, seed); });
        report.checks.push_back(tv::report_line(energy.name, wi, a, alpha));
      }
    }
  }
  return report;
}

tv::Report run_extremes_case(const ExtremesCase& c, std::size_t number, const SuiteSize& size,
                             CoreCalls& calls) {
  tv::BsdfUnderTest bsdf = core_bsdf(c.name, c.material(), calls);
  tv::ExtremesResult r;
  calls.run_check([&] {
    r = tv::extremes_check(bsdf, tv::extreme_incident_directions(), size.extreme_random_draws,
                           number);
  });
  return tv::Report{{tv::report_line(c.name, r)}};
}

tv::Report run_statistical_family(const std::string& family) {
  tv::Report report;
  std::size_t number = 0;
  for (const StatisticalCase& c : statistical_cases()) {
    ++number;
    if (c.family != family) continue;
    report.append(
        run_statistical_case(c, number, alpha_per_test(), suite_size(), cpu_core_calls()));
  }
  return report;
}

tv::Report run_extremes_family(const std::string& family) {
  tv::Report report;
  std::size_t number = 0;
  for (const ExtremesCase& c : extremes_cases()) {
    ++number;
    if (c.family != family) continue;
    report.append(run_extremes_case(c, number, suite_size(), cpu_core_calls()));
  }
  return report;
}

}  // namespace tr::bsdf_suite
