// An area emitter of textured radiance (core/emitters/area.h): its light samples carry the
// radiance that a ray along them finds. For every shape, each of 4000 light samples from a
// reference point is traced (Embree); where the ray meets the emitter at the sampled distance,
// the sample's weight times its density must equal eval_emitter_surface at that hit to 1e-4
// relative (+1e-6), the agreement that MIS between light and BSDF samples rests on. The texture
// is bilinear, hence continuous: the two points, equal up to float rounding, read radiances
// equal to about 1e-6. The direction density is the untextured one, which the chi-square suite
// checks (emitter_chi_square_test.cpp). The test can fail: the same comparison with the texture
// read at (1 - u, v) instead is rejected.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <string>

#include "core/interaction.h"
#include "cpu_backend/bound_scene.h"
#include "cpu_backend/embree_scene.h"
#include "delta_emitters.h"
#include "io/image.h"

namespace tr {
namespace {

std::filesystem::path test_dir() {
  std::filesystem::path dir = std::filesystem::temp_directory_path() / "twinray_textured_area";
  std::filesystem::create_directories(dir);
  return dir;
}

// A 5 x 3 float EXR of distinct, varied texels.
std::string write_radiance_texture() {
  Image image;
  image.width = 5;
  image.height = 3;
  image.channels = 3;
  for (int j = 0; j < 3; ++j)
    for (int i = 0; i < 5; ++i)
      image.pixels.insert(image.pixels.end(),
                          {0.5f + float(i), 1.0f + float((i * 3 + j * 2) % 5), 0.25f + float(j)});
  std::string path = (test_dir() / "radiance.exr").string();
  write_exr(path, image);
  return path;
}

// One triangle with uvs: the emitter record carries it (Emitter.to_world), not the buffers.
std::string write_triangle_obj() {
  std::string path = (test_dir() / "triangle.obj").string();
  std::ofstream(path) << "v -0.5 -0.4 0\nv 0.6 -0.3 0\nv 0.1 0.7 0\n"
                         "vt 0.1 0.2\nvt 0.9 0.3\nvt 0.4 0.95\nf 1/1 2/2 3/3\n";
  return path;
}

struct TexturedCase {
  std::string name;
  std::string shape;  // a <shape> element with one `%EMITTER%` in it
  glm::dvec3 ref_p;
};

struct Agreement {
  int compared = 0;
  int agreeing = 0;
  int misses = 0;  // sampled directions whose ray missed the emitter or met it elsewhere
};

// Light samples from c.ref_p against the emission a ray along them finds; `mirrored`: read the
// texture at (1 - u, v) on the ray's side instead.
Agreement compare_samples(const TexturedCase& c, bool mirrored) {
  const std::string emitter =
      "<emitter type=\"area\"><texture type=\"bitmap\" name=\"radiance\"><string "
      "name=\"filename\" value=\"" +
      write_radiance_texture() + "\"/></texture></emitter>";
  std::string body = c.shape;
  body.replace(body.find("%EMITTER%"), 9, emitter);
  Scene scene = load_emitter_scene("textured_" + c.name, body);
  ScopedSceneBinding bound(scene.buffers);
  EmbreeScene accel(scene.buffers, false);
  Agreement a;
  for (uint k = 0; k < 4000; ++k) {
    Rng rng = rng_init(k, 17u, 5u);
    const vec3 ref_p = vec3(c.ref_p);
    EmitterSample s = sample_emitter(ref_p, rng);
    if (!(s.pdf > 0.0f)) continue;
    Ray ray = make_ray(ref_p, s.d, FLOAT_MAX);
    Hit hit = accel.intersect(ray);
    if (hit.shape == NO_INDEX || std::abs(hit.t - s.dist) > 1e-4f * s.dist) {
      ++a.misses;
      continue;
    }
    SurfaceInteraction si = surface_interaction(ray, hit);
    if (mirrored) si.uv.x = 1.0f - si.uv.x;
    const glm::dvec3 found(eval_emitter_surface(si));
    const glm::dvec3 carried = glm::dvec3(s.weight) * double(s.pdf);
    ++a.compared;
    bool agree = true;
    for (int ch = 0; ch < 3; ++ch)
      agree = agree && std::abs(carried[ch] - found[ch]) <= 1e-4 * std::abs(found[ch]) + 1e-6;
    a.agreeing += agree;
  }
  return a;
}

const std::vector<TexturedCase>& cases() {
  static const std::vector<TexturedCase> list = {
      {"rectangle",
       R"(<shape type="rectangle"><transform name="to_world"><scale x="0.5" y="0.3"/>
          <rotate x="1" angle="30"/><translate z="-1"/></transform>%EMITTER%</shape>)",
       {0.2, -0.1, 0.0}},
      {"one_triangle",
       "<shape type=\"obj\"><string name=\"filename\" value=\"" + write_triangle_obj() +
           "\"/><transform name=\"to_world\"><rotate x=\"1\" angle=\"180\"/><translate "
           "z=\"1\"/></transform>%EMITTER%</shape>",
       {0.1, 0.0, 0.0}},
      {"sphere_outside",
       R"(<shape type="sphere"><point name="center" x="0.5" y="0.3" z="0.4"/>
          <float name="radius" value="0.3"/>%EMITTER%</shape>)",
       {0.0, 0.0, 0.0}},
      {"sphere_inside_flipped",
       R"(<shape type="sphere"><float name="radius" value="1.5"/>
          <boolean name="flip_normals" value="true"/>%EMITTER%</shape>)",
       {0.3, 0.2, -0.4}},
      {"disk",
       R"(<shape type="disk"><transform name="to_world"><scale value="0.6"/>
          <rotate y="1" angle="-150"/><translate x="0.5" z="0.8"/></transform>%EMITTER%</shape>)",
       {0.0, 0.0, 0.0}},
      {"cylinder_inside_flipped",
       R"(<shape type="cylinder"><point name="p0" x="0.1" y="-0.4" z="-0.2"/>
          <point name="p1" x="-0.1" y="0.5" z="0.6"/><float name="radius" value="0.4"/>
          <boolean name="flip_normals" value="true"/>%EMITTER%</shape>)",
       {0.05, 0.0, 0.1}},
  };
  return list;
}

void PrintTo(const TexturedCase& c, std::ostream* out) { *out << c.name; }

class TexturedAreaEmitter : public testing::TestWithParam<TexturedCase> {};

TEST_P(TexturedAreaEmitter, SamplesCarryTheRadianceTheirRayFinds) {
  Agreement a = compare_samples(GetParam(), false);
  EXPECT_GT(a.compared, 3000) << a.misses << " rays missed";
  EXPECT_LE(a.misses, a.compared / 100);
  EXPECT_EQ(a.agreeing, a.compared);
}

INSTANTIATE_TEST_SUITE_P(Shapes, TexturedAreaEmitter, testing::ValuesIn(cases()),
                         [](const testing::TestParamInfo<TexturedCase>& i) {
                           return i.param.name;
                         });

TEST(TexturedAreaEmitterCatches, TextureMirroredOnTheRaysSideFails) {
  Agreement a = compare_samples(cases()[0], true);
  EXPECT_LT(a.agreeing, a.compared / 2);
}

}  // namespace
}  // namespace tr
