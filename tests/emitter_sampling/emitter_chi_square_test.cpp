// Chi-square goodness of fit of the emitter samplers (issue 3): from a reference point,
// sample_emitter (core/emitter.h) draws directions; their histogram over (cos θ, φ) is compared
// with the density the integrator's MIS uses for the same directions: pdf_environment plus,
// for every surface point of an area emitter along the direction that faces the reference
// point, the selection pmf times pdf_area_emitter. Covers every area-emitter shape (mesh
// triangles, sphere from outside and inside, disk, cylinder), the constant and envmap
// emitters, a mixture chosen by sampling_weight, and the opt-in selections (power, light BVH;
// scenes/emitter_selection.h) over mixtures. Point and directional emitters are Dirac deltas
// with nothing to bin (they take their share of the choices all the same). Each case runs at the
// Šidák level of 1% over all cases and prints its p-value.
#include <gtest/gtest.h>

#include <cstring>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <string>
#include <vector>

#include "core/emitter.h"
#include "cpu_backend/bound_scene.h"
#include "scenes/load_scene.h"
#include "surface_hits.h"
#include "twinray_validation.h"

namespace tr {
namespace {

namespace tv = twinray::validation;

struct EmitterCase {
  std::string name;
  std::string body;  // the <scene> element's content
  glm::dvec3 ref_p;
  uint selection = EMITTER_SELECTION_UNIFORM;
};

const std::string kMuseum = std::string(TWINRAY_MITSUBA_TEXTURES) + "/museum.exr";

std::filesystem::path case_directory() {
  std::filesystem::path dir = std::filesystem::temp_directory_path() / "twinray_emitter_tests";
  std::filesystem::create_directories(dir);
  return dir;
}

// Writes an OBJ of the square [-1, 1]^2 in z = 0 cut into nx x ny cells of two triangles, each
// cell's vertices of its own (the quads of a grid facing +z); returns its path.
std::string grid_obj(int nx, int ny) {
  std::filesystem::path file =
      case_directory() / ("grid_" + std::to_string(nx) + "x" + std::to_string(ny) + ".obj");
  std::ofstream obj(file);
  for (int j = 0; j <= ny; ++j)
    for (int i = 0; i <= nx; ++i)
      obj << "v " << -1.0 + 2.0 * i / nx << ' ' << -1.0 + 2.0 * j / ny << " 0\n";
  for (int j = 0; j < ny; ++j)
    for (int i = 0; i < nx; ++i) {
      int v = j * (nx + 1) + i + 1;
      obj << "f " << v << ' ' << v + 1 << ' ' << v + nx + 2 << " " << v + nx + 1 << "\n";
    }
  return file.string();
}

// Emitters of every kind with a position and an environment, weighted by sampling_weight.
const std::string kMixture =
    R"(<shape type="sphere"><point name="center" x="0.5" y="0.3" z="0.4"/>
       <float name="radius" value="0.3"/><emitter type="area"><rgb name="radiance" value="3"/>
       <float name="sampling_weight" value="2"/></emitter></shape>
       <shape type="disk"><transform name="to_world"><scale value="0.4"/><rotate y="1" angle="-150"/>
       <translate x="0.5" z="0.8"/></transform><emitter type="area"/></shape>
       <shape type="rectangle"><transform name="to_world"><scale x="0.5" y="0.3"/>
       <translate z="-1"/></transform><emitter type="area"><rgb name="radiance" value="0.2"/>
       </emitter></shape>
       <emitter type="point"><point name="position" x="-1" y="0.5" z="0"/></emitter>
       <emitter type="spot"><transform name="to_world"><lookat origin="0, 2, 0" target="0, 0, 0"/>
       </transform></emitter>
       <emitter type="constant"><float name="sampling_weight" value="0.5"/></emitter>)";

const std::vector<EmitterCase>& cases() {
  static const std::vector<EmitterCase> list = {
      {"rectangle",
       R"(<shape type="rectangle"><transform name="to_world"><scale x="0.5" y="0.3"/>
          <rotate x="1" angle="30"/><translate z="-1"/></transform><emitter type="area"/></shape>)",
       {0.2, -0.1, 0.0}},
      {"cube",
       R"(<shape type="cube"><transform name="to_world"><scale x="0.4" y="0.2" z="0.3"/>
          <rotate x="1" y="1" angle="35"/><translate x="0.8" z="0.3"/></transform>
          <emitter type="area"/></shape>)",
       {0.0, 0.0, 0.0}},
      // More triangles than ALIAS_REUSE_MAX_COUNT (core/alias.h): the triangle and the point
      // take a 2D number each, where the rectangle and the cube reuse one.
      {"grid_of_288_triangles",
       R"(<shape type="obj"><string name="filename" value=")" + grid_obj(12, 12) +
           R"("/><transform name="to_world"><scale x="0.6" y="0.4"/><rotate x="1" angle="-20"/>
          <translate z="-0.9"/></transform><emitter type="area"/></shape>)",
       {0.1, 0.1, 0.0}},
      {"sphere_outside",
       R"(<shape type="sphere"><point name="center" x="0.5" y="0.3" z="0.4"/>
          <float name="radius" value="0.3"/><emitter type="area"/></shape>)",
       {0.0, 0.0, 0.0}},
      {"sphere_inside_flipped",
       R"(<shape type="sphere"><float name="radius" value="1.5"/>
          <boolean name="flip_normals" value="true"/><emitter type="area"/></shape>)",
       {0.3, 0.2, -0.4}},
      {"disk",
       R"(<shape type="disk"><transform name="to_world"><scale value="0.6"/>
          <rotate y="1" angle="-150"/><translate x="0.5" z="0.8"/></transform>
          <emitter type="area"/></shape>)",
       {0.0, 0.0, 0.0}},
      // Seen from inside (flipped normals face the axis): from outside, draws within float
      // rounding of the silhouette make rays that miss the double-precision quadric.
      {"cylinder_inside_flipped",
       R"(<shape type="cylinder"><point name="p0" x="0.1" y="-0.4" z="-0.2"/>
          <point name="p1" x="-0.1" y="0.5" z="0.6"/><float name="radius" value="0.4"/>
          <boolean name="flip_normals" value="true"/><emitter type="area"/></shape>)",
       {0.05, 0.0, 0.1}},
      {"constant", R"(<emitter type="constant"/>)", {0.0, 0.0, 0.0}},
      {"envmap",
       R"(<emitter type="envmap"><string name="filename" value=")" + kMuseum +
           R"("/><transform name="to_world"><rotate x="1" angle="90"/></transform></emitter>)",
       {0.0, 0.0, 0.0}},
      {"mixture_by_sampling_weight",
       R"(<shape type="sphere"><point name="center" x="0.5" y="0.3" z="0.4"/>
          <float name="radius" value="0.3"/>
          <emitter type="area"><float name="sampling_weight" value="2"/></emitter></shape>
          <shape type="rectangle"><transform name="to_world"><scale x="0.5" y="0.3"/>
          <translate z="-1"/></transform><emitter type="area"/></shape>
          <emitter type="envmap"><string name="filename" value=")" +
           kMuseum + R"("/><float name="sampling_weight" value="0.5"/></emitter>)",
       {0.0, 0.0, 0.0}},
      {"mixture_by_power", kMixture, {0.1, -0.2, 0.3}, EMITTER_SELECTION_POWER},
      {"mixture_by_light_bvh", kMixture, {0.1, -0.2, 0.3}, EMITTER_SELECTION_BVH},
  };
  return list;
}

Scene load_case(const EmitterCase& c) {
  std::filesystem::path file = case_directory() / (c.name + ".xml");
  std::ofstream(file) << "<scene version=\"3.0.0\"><sensor type=\"perspective\"/>" << c.body
                      << "</scene>\n";
  LoadOptions options;
  options.emitter_selection = c.selection;
  return load_scene(file.string(), options);
}

uint bits_of(float x) {
  uint b;
  std::memcpy(&b, &x, sizeof b);
  return b;
}

// Density of sample_emitter at direction w from ref_p, summed over everything along w.
// `drop_cosine` replaces the area emitters' density by a deliberately wrong one (without the
// 1 / |cos theta_l| of the area-to-solid-angle Jacobian), which the test must reject.
double direction_pdf(const SceneBuffers& b, const glm::dvec3& ref_p, const glm::dvec3& w,
                     bool drop_cosine = false) {
  double pdf = pdf_environment(vec3(w));
  for (uint i = 0; i < b.emitters.size(); ++i) {
    const Emitter& e = b.emitters[i];
    if (e.type != EMITTER_AREA) continue;
    double pmf = emitter_pmf(b.globals, vec3(ref_p), i);
    for (const SurfaceHit& h : surface_hits(b, b.shapes[e.shape], ref_p, w))
      if (glm::dot(h.n, w) < 0.0) {
        double dist2 = glm::dot(h.p - ref_p, h.p - ref_p);
        pdf += pmf * (drop_cosine ? dist2 / b.shapes[e.shape].area
                                  : pdf_area_emitter(e, vec3(ref_p), vec3(h.p), vec3(h.n)));
      }
  }
  return pdf;
}

tv::ChiSquareOptions options() {
  tv::ChiSquareOptions o;
#ifdef TWINRAY_FULL_TESTS
  o.sample_count = 10000000;
#else
  o.sample_count = 1000000;
#endif
  o.cos_theta_bins = 10;
  o.phi_bins = 20;
  return o;
}

double alpha_per_case() { return tv::sidak_alpha(0.01, cases().size()); }

void PrintTo(const EmitterCase& c, std::ostream* out) { *out << c.name; }

class EmitterSampler : public testing::TestWithParam<EmitterCase> {};

tv::ChiSquareResult chi_square(const EmitterCase& c, bool drop_cosine) {
  Scene scene = load_case(c);
  ScopedSceneBinding bound(scene.buffers);
  const glm::dvec3 ref_p = c.ref_p;
  tv::DirectionSampler sampler;
  sampler.name = "emitter " + c.name;
  // The chi-square test needs independent draws: u's bits seed the sampler's own stream.
  sampler.sample = [&](const glm::vec2& u) {
    Rng rng = rng_init(bits_of(u.x), bits_of(u.y), 0x9e3779b9u);
    EmitterSample s = sample_emitter(vec3(ref_p), rng);
    tv::DirectionSample d;
    if (s.pdf > 0.0f && s.delta == 0u) {
      d.w = s.d;
      d.pdf = s.pdf;
    }
    return d;
  };
  sampler.pdf = [&](const glm::vec3& w) {
    return float(direction_pdf(scene.buffers, ref_p, glm::normalize(glm::dvec3(w)), drop_cosine));
  };
  return tv::chi_square_directions(sampler, options());
}

TEST_P(EmitterSampler, ChiSquareAgainstTheMisDensity) {
  const EmitterCase& c = GetParam();
  tv::ChiSquareResult r = chi_square(c, false);
  tv::Report report;
  report.checks.push_back(
      tv::report_line("emitter " + c.name, glm::vec3(0.0f), r, alpha_per_case()));
  std::cout << cases().size() << " emitter cases at overall significance 0.01, Sidak level "
            << alpha_per_case() << " each\n";
  report.print(std::cout);
  EXPECT_TRUE(report.passed()) << r.failure;
}

// The suite can fail: the rectangle's density without its cosine factor is rejected.
TEST(EmitterSamplerCatches, DensityWithoutTheCosineFails) {
  tv::ChiSquareResult r = chi_square(cases()[0], true);
  tv::Report report;
  report.checks.push_back(
      tv::report_line("emitter rectangle, pdf without cos", glm::vec3(0.0f), r, alpha_per_case()));
  report.print(std::cout);
  EXPECT_FALSE(report.passed());
}

INSTANTIATE_TEST_SUITE_P(Chi2, EmitterSampler, testing::ValuesIn(cases()),
                         [](const testing::TestParamInfo<EmitterCase>& i) { return i.param.name; });

}  // namespace
}  // namespace tr
