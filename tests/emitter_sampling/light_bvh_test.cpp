// The light BVH's emitter choice (core/light_bvh.h, scenes/light_bvh_build.cpp) on a scene of
// 120 emitters of every kind with a position plus an environment:
// - the probabilities emitter_pmf gives every emitter sum to at most one, select_emitter reports
// the
//   same probability for what it draws, and draws each emitter that often (chi-square over the
//   emitters, Šidák level of 1% over the points);
// - an emitter that can light a point is never pruned from it (its probability is positive),
//   the bound the tree must keep to stay unbiased; a tree whose emission cones are narrowed by
//   hand is caught by the same check.
#include <gtest/gtest.h>

#include <cmath>
#include <random>
#include <string>
#include <vector>

#include "core/emitter.h"
#include "cpu_backend/bound_scene.h"
#include "delta_emitters.h"
#include "scenes/emitter_selection.h"
#include "twinray_validation.h"

namespace tr {
namespace {

namespace tv = twinray::validation;

struct Placed {
  glm::dvec3 centre, normal;  // rectangles: their emitting side; spots: their axis
  double cos_cutoff = -1.0;   // spots
};

// Random rectangles (one-sided, facing every way), spheres, points and spots, and a constant
// environment; `placed` receives each emitter's geometry in the scene's emitter order (area
// emitters first, then the others in document order; core/scene_types.h).
std::string scene_body(std::vector<Placed>& placed) {
  std::mt19937 rng(7);
  std::uniform_real_distribution<double> u(0.0, 1.0);
  auto point = [&] { return glm::dvec3(u(rng), u(rng), u(rng)) * 8.0 - 4.0; };
  auto str = [](const glm::dvec3& v) {
    return std::to_string(v.x) + ", " + std::to_string(v.y) + ", " + std::to_string(v.z);
  };
  std::string areas, others;
  std::vector<Placed> area_list, other_list;
  for (int i = 0; i < 120; ++i) {
    const glm::dvec3 c = point();
    const double power = std::pow(10.0, 3.0 * u(rng));
    const int kind = i % 4;
    if (kind == 0 || kind == 1) {
      // The rectangle's normal is its to_world's +z: a lookat towards `target`.
      const glm::dvec3 n = glm::normalize(point() - c);
      areas += R"(<shape type="rectangle"><transform name="to_world"><scale value="0.2"/>)"
               R"(<lookat origin=")" +
               str(c) + R"(" target=")" + str(c + n) + R"(" up=")" +
               str(std::abs(n.y) < 0.9 ? glm::dvec3(0, 1, 0) : glm::dvec3(1, 0, 0)) +
               R"("/></transform><emitter type="area"><rgb name="radiance" value=")" +
               std::to_string(power) + R"("/></emitter></shape>)";
      area_list.push_back({c, n});
    } else if (kind == 2) {
      others += R"(<emitter type="point"><point name="position" x=")" + std::to_string(c.x) +
                R"(" y=")" + std::to_string(c.y) + R"(" z=")" + std::to_string(c.z) +
                R"("/><rgb name="intensity" value=")" + std::to_string(power) + R"("/></emitter>)";
      other_list.push_back({c, glm::dvec3(0.0)});
    } else {
      const glm::dvec3 axis = glm::normalize(point() - c);
      const double cutoff = 10.0 + 50.0 * u(rng);
      others += R"(<emitter type="spot"><float name="cutoff_angle" value=")" +
                std::to_string(cutoff) + R"("/><float name="beam_width" value=")" +
                std::to_string(0.5 * cutoff) + R"("/><transform name="to_world"><lookat origin=")" +
                str(c) + R"(" target=")" + str(c + axis) + R"(" up=")" +
                str(std::abs(axis.y) < 0.9 ? glm::dvec3(0, 1, 0) : glm::dvec3(1, 0, 0)) +
                R"("/></transform><rgb name="intensity" value=")" + std::to_string(power) +
                R"("/></emitter>)";
      other_list.push_back({c, axis, std::cos(cutoff * M_PI / 180.0)});
    }
  }
  placed = area_list;
  placed.insert(placed.end(), other_list.begin(), other_list.end());
  placed.push_back({});  // the environment
  return areas + others +
         R"(<emitter type="constant"><rgb name="radiance" value="0.1"/></emitter>)";
}

struct BvhScene {
  Scene scene;
  std::vector<Placed> placed;
};

BvhScene load_bvh_scene() {
  BvhScene s;
  std::string body = scene_body(s.placed);
  s.scene = load_emitter_scene("light_bvh", body);
  use_emitter_selection(s.scene.buffers, EMITTER_SELECTION_BVH);
  return s;
}

std::vector<glm::dvec3> reference_points() {
  std::mt19937 rng(11);
  std::uniform_real_distribution<double> u(-4.5, 4.5);
  std::vector<glm::dvec3> points;
  for (int i = 0; i < 12; ++i) points.push_back({u(rng), u(rng), u(rng)});
  return points;
}

// Whether emitter `i` can send light to p: a one-sided rectangle only to its front, a spot
// only within its cutoff cone; points, spheres and the environment anywhere.
bool can_light(const Placed& e, const glm::dvec3& p, uint type) {
  if (type == EMITTER_AREA) return glm::dot(e.normal, p - e.centre) > 1e-3;
  if (type == EMITTER_SPOT) return glm::dot(e.normal, glm::normalize(p - e.centre)) > e.cos_cutoff;
  return true;
}

TEST(LightBvh, ProbabilitiesMatchTheDraws) {
  BvhScene s = load_bvh_scene();
  ScopedSceneBinding bound(s.scene.buffers);
  const SceneGlobals g = s.scene.buffers.globals;
  ASSERT_NE(g.light_root, NO_INDEX);
  const std::vector<glm::dvec3> points = reference_points();
  const double alpha = tv::sidak_alpha(0.01, points.size());
  std::mt19937 rng(12345);
  std::uniform_real_distribution<float> u(0.0f, 1.0f);
  for (const glm::dvec3& p : points) {
    std::vector<double> pmf(g.emitter_count);
    double sum = 0.0;
    for (uint i = 0; i < g.emitter_count; ++i) sum += pmf[i] = emitter_pmf(g, vec3(p), i);
    // A draw fails where both children of a node it reaches turn out unable to light p (a
    // node's bounds are looser than its children's): the probabilities sum to one less that,
    // drawn as one more cell.
    EXPECT_LE(sum, 1.0 + 1e-5) << "at " << p.x << " " << p.y << " " << p.z;
    const int draws = 400000;
    std::vector<double> count(g.emitter_count + 1, 0.0);  // the last: failed draws
    pmf.push_back(std::max(0.0, 1.0 - sum));
    for (int k = 0; k < draws; ++k) {
      float chosen_pmf;
      uint i = select_emitter(g, vec3(p), vec2(u(rng), u(rng)), chosen_pmf);
      if (i == NO_INDEX) {
        count.back() += 1.0;
        continue;
      }
      // The same factors, multiplied root to leaf here and leaf to root by emitter_pmf.
      ASSERT_NEAR(chosen_pmf, pmf[i], 1e-6 * pmf[i]) << "emitter " << i;
      count[i] += 1.0;
    }
    // Emitters expected fewer than 5 times are pooled into one cell.
    double statistic = 0.0, pooled_observed = 0.0, pooled_expected = 0.0;
    int cells = 0;
    for (size_t i = 0; i < pmf.size(); ++i) {
      const double expected = pmf[i] * draws;
      if (expected < 5.0) {
        pooled_observed += count[i];
        pooled_expected += expected;
        continue;
      }
      statistic += (count[i] - expected) * (count[i] - expected) / expected;
      ++cells;
    }
    if (pooled_expected > 0.0) {
      statistic += (pooled_observed - pooled_expected) * (pooled_observed - pooled_expected) /
                   std::max(pooled_expected, 1e-12);
      ++cells;
    }
    const double p_value = tv::chi_square_p_value(statistic, cells - 1);
    EXPECT_GT(p_value, alpha) << "chi-square " << statistic << " over " << cells << " cells";
  }
}

// The points of reference_points() from which some emitter that can light them has probability
// zero.
int points_missing_an_emitter(const BvhScene& s) {
  ScopedSceneBinding bound(s.scene.buffers);
  const SceneGlobals g = s.scene.buffers.globals;
  int missing = 0;
  for (const glm::dvec3& p : reference_points()) {
    for (uint i = 0; i < g.emitter_count; ++i) {
      if (!can_light(s.placed[i], p, s.scene.buffers.emitters[i].type)) continue;
      if (!(emitter_pmf(g, vec3(p), i) > 0.0f)) {
        ++missing;
        break;
      }
    }
  }
  return missing;
}

TEST(LightBvh, NeverPrunesAnEmitterThatCanLightThePoint) {
  BvhScene s = load_bvh_scene();
  EXPECT_EQ(points_missing_an_emitter(s), 0);
}

TEST(LightBvhCatches, EmissionConesNarrowedByHand) {
  BvhScene s = load_bvh_scene();
  for (LightNode& n : s.scene.buffers.light_nodes) n.cos_theta_e = 0.9f;  // 26 degrees
  EXPECT_GT(points_missing_an_emitter(s), 0);
}

}  // namespace
}  // namespace tr
