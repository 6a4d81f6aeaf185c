// Loading of Mitsuba 3.8's BSDF adapters (src/bsdfs/blendbsdf.cpp): the records they build and
// the scenes Mitsuba refuses.
#include <gtest/gtest.h>

#include "core/material_slots.h"
#include "scene_test_files.h"

namespace tr {
namespace {

using namespace testing_files;

Scene load_bsdf(const std::string& bsdf) {
  std::filesystem::path dir = fresh_dir();
  return load_scene(
      write_file(dir, "scene.xml", scene_xml("<shape type=\"sphere\">" + bsdf + "</shape>")), {});
}

std::string error_of(const std::string& bsdf) {
  try {
    load_bsdf(bsdf);
  } catch (const SceneError& e) {
    return e.what();
  }
  ADD_FAILURE() << "no SceneError for:\n" << bsdf;
  return "";
}

const Material& shape_material(const Scene& s) {
  return s.buffers.materials[s.buffers.shapes[0].material];
}

const Material& child(const Scene& s, const Material& blend, uint slot) {
  return s.buffers.materials[uint(blend.param[slot].value.x)];
}

const std::string kDiffuse = "<bsdf type=\"diffuse\"/>";
const std::string kConductor = "<bsdf type=\"conductor\"/>";

TEST(BlendBsdf, ChildrenInOrderAndScalarWeight) {
  Scene s = load_bsdf("<bsdf type=\"blendbsdf\"><rgb name=\"weight\" value=\"0.1, 0.2, 0.6\"/>" +
                      kDiffuse + kConductor + "</bsdf>");
  const Material& m = shape_material(s);
  ASSERT_EQ(m.type, BSDF_BLEND);
  EXPECT_EQ(child(s, m, BLEND_BSDF_0).type, BSDF_DIFFUSE);
  EXPECT_EQ(child(s, m, BLEND_BSDF_1).type, BSDF_CONDUCTOR);
  // eval_1 of a constant color is its channel mean.
  EXPECT_FLOAT_EQ(m.param[BLEND_WEIGHT].value.x, 0.3f);
  EXPECT_EQ(m.param[BLEND_WEIGHT].texture, NO_INDEX);
}

TEST(BlendBsdf, TexturedWeightAndNesting) {
  Scene s = load_bsdf(
      "<bsdf type=\"twosided\"><bsdf type=\"blendbsdf\"><texture name=\"weight\" "
      "type=\"checkerboard\"/><bsdf type=\"blendbsdf\"><float name=\"weight\" value=\"0.25\"/>" +
      kDiffuse + kConductor + "</bsdf>" + kDiffuse + "</bsdf></bsdf>");
  const Material& m = shape_material(s);
  ASSERT_EQ(m.type, BSDF_BLEND);
  EXPECT_NE(m.flags & MATERIAL_TWOSIDED, 0u);
  EXPECT_NE(m.param[BLEND_WEIGHT].texture, NO_INDEX);
  const Material& inner = child(s, m, BLEND_BSDF_0);
  ASSERT_EQ(inner.type, BSDF_BLEND);
  EXPECT_FLOAT_EQ(inner.param[BLEND_WEIGHT].value.x, 0.25f);
  EXPECT_EQ(child(s, inner, BLEND_BSDF_1).type, BSDF_CONDUCTOR);
}

TEST(BlendBsdf, MitsubaRefusals) {
  EXPECT_NE(error_of("<bsdf type=\"blendbsdf\"><float name=\"weight\" value=\"0.5\"/>" + kDiffuse +
                     "</bsdf>")
                .find("takes exactly two nested BSDFs (it has 1)"),
            std::string::npos);
  EXPECT_NE(error_of("<bsdf type=\"blendbsdf\"><float name=\"weight\" value=\"0.5\"/>" + kDiffuse +
                     kDiffuse + kConductor + "</bsdf>")
                .find("takes exactly two nested BSDFs (it has 3)"),
            std::string::npos);
  EXPECT_NE(error_of("<bsdf type=\"blendbsdf\">" + kDiffuse + kConductor + "</bsdf>")
                .find("needs a 'weight'"),
            std::string::npos);
  EXPECT_NE(error_of("<bsdf type=\"blendbsdf\"><float name=\"weight\" value=\"0.5\"/>"
                     "<float name=\"wieght\" value=\"0.5\"/>" +
                     kDiffuse + kConductor + "</bsdf>")
                .find("wieght"),
            std::string::npos);
  // twosided refuses a transmitting child anywhere below it (Mitsuba: the blend's flags).
  EXPECT_NE(error_of("<bsdf type=\"twosided\"><bsdf type=\"blendbsdf\"><float name=\"weight\" "
                     "value=\"0.5\"/><bsdf type=\"dielectric\"/>" +
                     kDiffuse + "</bsdf></bsdf>")
                .find("allow_transmission"),
            std::string::npos);
}

TEST(BlendBsdf, LimitsOfTheRepresentation) {
  EXPECT_NE(error_of("<bsdf type=\"mask\"><bsdf type=\"blendbsdf\"><float name=\"weight\" "
                     "value=\"0.5\"/>" +
                     kDiffuse + kConductor + "</bsdf></bsdf>")
                .find("around a blendbsdf is not supported"),
            std::string::npos);
  auto nested = [](uint levels) {
    std::string xml = kDiffuse;
    for (uint i = 0; i < levels; ++i)
      xml = "<bsdf type=\"blendbsdf\"><float name=\"weight\" value=\"0.5\"/>" + xml + kDiffuse +
            "</bsdf>";
    return xml;
  };
  EXPECT_EQ(load_bsdf(nested(BLEND_MAX_DEPTH)).buffers.materials.size(), 2u * BLEND_MAX_DEPTH + 1u);
  EXPECT_NE(error_of(nested(BLEND_MAX_DEPTH + 1u)).find("nested more than 7 deep"),
            std::string::npos);
}

}  // namespace
}  // namespace tr
