// glTF 2.0 import (scenes/gltf/): the node tree import_gltf builds (transforms, principled
// parameters, baked texture channels, camera, KHR_lights_punctual units), the warnings for
// fields that do not map, and the one-line errors for malformed files.
#include "scenes/gltf/gltf_import.h"

#include <OpenImageIO/imageio.h>
#include <gtest/gtest.h>

#include <cstring>
#include <fstream>
#include <glm/gtc/matrix_transform.hpp>
#include <glm/gtc/quaternion.hpp>
#include <nlohmann/json.hpp>

#include "gltf_test_support.h"
#include "scene_test_files.h"
#include "scenes/bitmap.h"
#include "scenes/load_scene.h"
#include "scenes/mesh.h"

namespace tr {
namespace {

using namespace testing_files;
using namespace gltf_test;
using json = nlohmann::json;

// One triangle (0,0,0) (1,0,0) (0,1,0) with uv (0,0) (1,0) (0,1), as a data: URI buffer.
json triangle_gltf() {
  std::string bytes;
  auto put = [&](float f) { bytes.append(reinterpret_cast<const char*>(&f), 4); };
  for (float f : {0.f, 0.f, 0.f, 1.f, 0.f, 0.f, 0.f, 1.f, 0.f}) put(f);
  for (float f : {0.f, 0.f, 1.f, 0.f, 0.f, 1.f}) put(f);
  json g = {{"asset", {{"version", "2.0"}}},
            {"scene", 0},
            {"scenes", {{{"nodes", {0, 2}}}}},
            {"nodes",
             {{{"translation", {1.0, 2.0, 3.0}}, {"children", {1}}},
              {{"mesh", 0},
               {"rotation", {0.0, 0.0, std::sqrt(0.5), std::sqrt(0.5)}},  // 90 degrees about z
               {"scale", {2.0, 2.0, 2.0}}},
              {{"camera", 0}, {"translation", {0.0, 0.0, 5.0}}}}},
            {"cameras",
             {{{"type", "perspective"},
               {"perspective", {{"yfov", 0.5}, {"aspectRatio", 2.0}, {"znear", 0.1}}}}}},
            {"meshes",
             {{{"primitives",
                {{{"attributes", {{"POSITION", 0}, {"TEXCOORD_0", 1}}}, {"material", 0}}}}}}},
            {"materials",
             {{{"pbrMetallicRoughness",
                {{"baseColorFactor", {0.5, 0.25, 0.125, 1.0}},
                 {"metallicFactor", 0.25},
                 {"roughnessFactor", 0.625}}},
               {"emissiveFactor", {1.0, 2.0, 4.0}},
               {"extensions",
                {{"KHR_materials_transmission", {{"transmissionFactor", 0.375}}},
                 {"KHR_materials_ior", {{"ior", 1.33}}},
                 {"KHR_materials_emissive_strength", {{"emissiveStrength", 3.0}}}}}}}},
            {"buffers",
             {{{"byteLength", bytes.size()},
               {"uri", "data:application/octet-stream;base64," + base64(bytes)}}}},
            {"bufferViews",
             {{{"buffer", 0}, {"byteOffset", 0}, {"byteLength", 36}},
              {{"buffer", 0}, {"byteOffset", 36}, {"byteLength", 24}}}},
            {"accessors",
             {{{"bufferView", 0},
               {"componentType", 5126},
               {"count", 3},
               {"type", "VEC3"},
               {"min", {0, 0, 0}},
               {"max", {1, 1, 0}}},
              {{"bufferView", 1}, {"componentType", 5126}, {"count", 3}, {"type", "VEC2"}}}}};
  return g;
}

// An 8-bit image of `width` x `height` x `channels` (OpenImageIO picks the format by the name).
void write_png(const std::filesystem::path& file, int width, int height, int channels,
               const unsigned char* pixels) {
  auto out = OIIO::ImageOutput::create(file.string());
  ASSERT_TRUE(out);
  ASSERT_TRUE(
      out->open(file.string(), OIIO::ImageSpec(width, height, channels, OIIO::TypeDesc::UINT8)));
  ASSERT_TRUE(out->write_image(OIIO::TypeDesc::UINT8, pixels));
  out->close();
}

TEST(GltfImport, TransformsMaterialCameraAndIntegrator) {
  Imported im = import(triangle_gltf());
  const Node& root = *im.scene.parsed.root;
  const Node& shape = one(root, "shape", "ply");
  // Spec "Transformations": world = parent T * (child T R S).
  glm::dmat4 expected = glm::translate(glm::dmat4(1.0), glm::dvec3(1, 2, 3)) *
                        glm::rotate(glm::dmat4(1.0), glm::radians(90.0), glm::dvec3(0, 0, 1)) *
                        glm::scale(glm::dmat4(1.0), glm::dvec3(2.0));
  const glm::dmat4& m = prop(shape, "to_world").matrix;
  for (int c = 0; c < 4; ++c)
    for (int r = 0; r < 4; ++r) EXPECT_NEAR(m[c][r], expected[c][r], 1e-12) << c << r;
  EXPECT_TRUE(prop(shape, "face_normals").boolean);  // no NORMAL: flat (spec "Meshes")

  // The PLY keeps glTF's uv (Assimp's flip of v undone): vertex 1 has uv (1, 0).
  std::ifstream ply(prop(shape, "filename").text, std::ios::binary);
  std::string data((std::istreambuf_iterator<char>(ply)), std::istreambuf_iterator<char>());
  size_t body = data.find("end_header\n") + 11;
  float v1[5];
  std::memcpy(v1, data.data() + body + 20, sizeof v1);
  EXPECT_EQ(v1[0], 1.0f);
  EXPECT_EQ(v1[3], 1.0f);
  EXPECT_EQ(v1[4], 0.0f);

  const Node& bsdf = one(root, "bsdf", "principled");
  expect_vec(prop(bsdf, "base_color").vec, {0.5, 0.25, 0.125});
  EXPECT_EQ(prop(bsdf, "metallic").number, 0.25);
  EXPECT_EQ(prop(bsdf, "roughness").number, 0.625);
  EXPECT_EQ(prop(bsdf, "spec_trans").number, 0.375);
  EXPECT_EQ(prop(bsdf, "eta").number, 1.33);
  const Node& area = one(root, "emitter", "area");
  expect_vec(prop(area, "radiance").vec, {3.0, 6.0, 12.0});  // emissiveFactor * strength

  const Node& sensor = one(root, "sensor", "perspective");
  EXPECT_NEAR(prop(sensor, "fov").number, glm::degrees(0.5), 1e-12);
  EXPECT_EQ(prop(sensor, "fov_axis").text, "y");
  EXPECT_EQ(prop(sensor, "near_clip").number, 0.1);
  const glm::dmat4& cam = prop(sensor, "to_world").matrix;
  expect_vec(glm::dvec3(cam[3]), {0, 0, 5});
  expect_vec(glm::dvec3(cam[2]), {0, 0, -1});  // looks along glTF's -z
  expect_vec(glm::dvec3(cam[0]), {-1, 0, 0});  // Mitsuba's +x is the image's left
  const Node& film = one(root, "film", "hdrfilm");
  EXPECT_EQ(prop(film, "height").integer, 576);
  EXPECT_EQ(prop(film, "width").integer, 1152);  // height * aspectRatio
  EXPECT_EQ(prop(one(root, "integrator", "path"), "max_depth").integer, -1);
  EXPECT_TRUE(im.scene.warnings.empty()) << im.scene.warnings.front();

  LoadOptions o;
  o.defines = {{"width", "64"}, {"max_depth", "5"}, {"spp", "3"}};
  Imported im2 = import(triangle_gltf(), o);
  const Node& root2 = *im2.scene.parsed.root;
  EXPECT_EQ(prop(one(root2, "film", "hdrfilm"), "width").integer, 64);
  EXPECT_EQ(prop(one(root2, "film", "hdrfilm"), "height").integer, 32);
  EXPECT_EQ(prop(one(root2, "integrator", "path"), "max_depth").integer, 5);
  EXPECT_EQ(prop(one(root2, "sampler", "independent"), "sample_count").integer, 3);
}

TEST(GltfImport, PunctualLightsKeepTheirUnitsAndDirections) {
  json g = triangle_gltf();
  g["extensionsUsed"] = {"KHR_lights_punctual"};
  g["extensions"]["KHR_lights_punctual"]["lights"] = {
      {{"type", "point"}, {"color", {1.0, 0.5, 0.25}}, {"intensity", 10.0}},
      {{"type", "spot"},
       {"intensity", 4.0},
       {"spot", {{"innerConeAngle", 0.25}, {"outerConeAngle", 0.5}}}},
      {{"type", "directional"}, {"intensity", 2.0}}};
  // A node rotated 90 degrees about x: its -z points along world +y.
  double h = std::sqrt(0.5);
  for (int i = 0; i < 3; ++i) {
    g["nodes"].push_back({{"translation", {0.0, 1.0, 0.0}},
                          {"rotation", {h, 0.0, 0.0, h}},
                          {"extensions", {{"KHR_lights_punctual", {{"light", i}}}}}});
    g["scenes"][0]["nodes"].push_back(3 + i);
  }
  Imported im = import(g);
  const Node& root = *im.scene.parsed.root;
  // Candela and lux read as W/sr and W/m^2 (factor 1), times the colour.
  const Node& point = one(root, "emitter", "point");
  expect_vec(prop(point, "intensity").vec, {10.0, 5.0, 2.5});
  expect_vec(prop(point, "position").vec, {0, 1, 0});
  const Node& spot = one(root, "emitter", "spot");
  expect_vec(prop(spot, "intensity").vec, {4.0, 4.0, 4.0});
  EXPECT_NEAR(prop(spot, "cutoff_angle").number, glm::degrees(0.5), 1e-12);
  EXPECT_NEAR(prop(spot, "beam_width").number, glm::degrees(0.25), 1e-12);
  expect_vec(glm::dvec3(prop(spot, "to_world").matrix[2]), {0, 1, 0}, 1e-12);
  const Node& sun = one(root, "emitter", "directional");
  expect_vec(prop(sun, "irradiance").vec, {2.0, 2.0, 2.0});
  expect_vec(prop(sun, "direction").vec, {0, 1, 0}, 1e-12);
  ASSERT_EQ(im.scene.warnings.size(), 1u);
  EXPECT_NE(im.scene.warnings[0].find("spot: approximate"), std::string::npos);
}

// Names carry no meaning (spec "Objects": they need not be unique): two lights and two nodes
// of one name load as two of each (Assimp's validation refused such files).
TEST(GltfImport, RepeatedNamesAreNoError) {
  json g = triangle_gltf();
  g["extensions"]["KHR_lights_punctual"]["lights"] = {{{"type", "point"}, {"name", "lamp"}},
                                                      {{"type", "point"}, {"name", "lamp"}}};
  for (int i = 0; i < 2; ++i) {
    g["nodes"].push_back({{"name", "twin"},
                          {"translation", {double(i), 0.0, 0.0}},
                          {"extensions", {{"KHR_lights_punctual", {{"light", i}}}}}});
    g["scenes"][0]["nodes"].push_back(3 + i);
  }
  g["nodes"][0]["name"] = "twin";
  Imported im = import(g);
  EXPECT_EQ(all(*im.scene.parsed.root, "emitter", "point").size(), 2u);
  EXPECT_TRUE(im.scene.warnings.empty()) << im.scene.warnings.front();
}

TEST(GltfImport, MetallicRoughnessChannelsAreSplitAndScaled) {
  std::filesystem::path dir = fresh_dir();
  // 2x2: B (metallic) and G (roughness) differ per pixel; R is the occlusion channel.
  const unsigned char pixels[] = {10, 51, 204, 20, 102, 153, 30, 153, 102, 40, 204, 51};
  write_png(dir / "mr.png", 2, 2, 3, pixels);
  json g = triangle_gltf();
  g["images"] = {{{"uri", "mr.png"}}};
  g["textures"] = {{{"source", 0}}};
  g["materials"][0]["pbrMetallicRoughness"]["metallicRoughnessTexture"] = {{"index", 0}};
  GltfScene s = import_in(dir, g).scene;
  const Node& bsdf = one(*s.parsed.root, "bsdf", "principled");
  Image metallic = load_image(prop(*prop(bsdf, "metallic").object, "filename").text, true);
  Image roughness = load_image(prop(*prop(bsdf, "roughness").object, "filename").text, true);
  ASSERT_EQ(metallic.width, 2);
  ASSERT_EQ(metallic.height, 2);
  for (int i = 0; i < 4; ++i) {
    EXPECT_NEAR(metallic.texels[i].x, 0.25 * pixels[3 * i + 2] / 255.0, 1e-6) << i;
    EXPECT_NEAR(roughness.texels[i].x, 0.625 * pixels[3 * i + 1] / 255.0, 1e-6) << i;
  }
}

// Spec "Alpha Coverage": MASK -> twinray's alphatest, opacity = baseColorFactor.a x the base
// colour texture's alpha, cutoff = alphaCutoff.
// KHR_texture_transform as the bitmap's to_uv (u' = cos u + sin v, v' = -sin u + cos v, then
// scale and offset: the direction the TextureTransformTest sample checks), the samplers' wrap and
// magnification filter as wrap_mode and filter_type, and a 4x1 texture written as 4x2.
TEST(GltfImport, TextureTransformsAndSamplersMapOntoTheBitmap) {
  std::filesystem::path dir = fresh_dir();
  const unsigned char pixels[] = {0, 64, 128, 255};
  write_png(dir / "row.png", 4, 1, 1, pixels);
  json g = triangle_gltf();
  g["images"] = {{{"uri", "row.png"}}};
  g["samplers"] = {{{"wrapS", 33071}, {"wrapT", 33071}, {"magFilter", 9728}},
                   {{"wrapS", 33648}, {"wrapT", 10497}}};
  g["textures"] = {{{"source", 0}, {"sampler", 0}}, {{"source", 0}, {"sampler", 1}}};
  g["materials"][0]["pbrMetallicRoughness"]["baseColorTexture"] = {
      {"index", 0},
      {"extensions",
       {{"KHR_texture_transform",
         {{"offset", {0.5, 0.25}}, {"rotation", M_PI / 2}, {"scale", {2.0, 3.0}}}}}}};
  g["materials"][0]["pbrMetallicRoughness"]["metallicRoughnessTexture"] = {{"index", 1}};
  GltfScene s = import_in(dir, g).scene;
  const Node& bsdf = one(*s.parsed.root, "bsdf", "principled");
  const Node& color = *prop(bsdf, "base_color").object;
  const glm::dmat4& m = prop(color, "to_uv").matrix;
  EXPECT_NEAR(m[0][0], 0.0, 1e-12);  // u' = 3 v + 0.5
  EXPECT_NEAR(m[1][0], 3.0, 1e-12);
  EXPECT_NEAR(m[3][0], 0.5, 1e-12);
  EXPECT_NEAR(m[0][1], -2.0, 1e-12);  // v' = -2 u + 0.25
  EXPECT_NEAR(m[1][1], 0.0, 1e-12);
  EXPECT_NEAR(m[3][1], 0.25, 1e-12);
  EXPECT_EQ(prop(color, "wrap_mode").text, "clamp");
  EXPECT_EQ(prop(color, "filter_type").text, "nearest");
  const Node& metallic = *prop(bsdf, "metallic").object;
  EXPECT_EQ(prop(metallic, "wrap_mode").text, "mirror");
  ASSERT_EQ(s.warnings.size(), 1u);
  EXPECT_NE(s.warnings[0].find("samplers[1].wrapT: approximate: twinray's bitmaps wrap u and v "
                               "alike; wrapS (mirror) used for both"),
            std::string::npos)
      << s.warnings[0];
  Image row = load_image(prop(color, "filename").text, true);
  ASSERT_EQ(row.width, 4);
  ASSERT_EQ(row.height, 2);
  for (int x = 0; x < 4; ++x) EXPECT_EQ(row.texels[x], row.texels[4 + x]) << x;
}

// emissiveTexture: the area emitter's radiance is a bitmap of emissiveFactor x strength x the
// sRGB-decoded texel (no emitter where the factor is 0, the spec's default).
TEST(GltfImport, EmissiveTexturesAreTheEmittersRadiance) {
  std::filesystem::path dir = fresh_dir();
  const unsigned char pixels[] = {255, 0, 0, 0, 128, 255};
  write_png(dir / "glow.png", 2, 1, 3, pixels);
  json g = triangle_gltf();
  g["images"] = {{{"uri", "glow.png"}}};
  g["textures"] = {{{"source", 0}}};
  g["materials"][0]["emissiveTexture"] = {{"index", 0}};
  GltfScene s = import_in(dir, g).scene;
  const Node& area = one(*s.parsed.root, "emitter", "area");
  const Property& radiance = prop(area, "radiance");
  ASSERT_EQ(radiance.kind, PropertyKind::Object);
  Image texels = load_image(prop(*radiance.object, "filename").text, true);
  ASSERT_EQ(texels.width, 2);
  auto srgb = [](double c) {
    return c <= 0.04045 ? c / 12.92 : std::pow((c + 0.055) / 1.055, 2.4);
  };
  const glm::dvec3 factor(3.0, 6.0, 12.0);  // emissiveFactor (1, 2, 4) x emissiveStrength 3
  for (int x = 0; x < 2; ++x)
    for (int k = 0; k < 3; ++k)
      EXPECT_NEAR(texels.texels[x][k], factor[k] * srgb(pixels[3 * x + k] / 255.0), 2e-3) << x << k;
  EXPECT_TRUE(s.warnings.empty()) << s.warnings.front();
}

TEST(GltfImport, AlphaMaskBecomesAlphaTest) {
  std::filesystem::path dir = fresh_dir();
  const unsigned char pixels[] = {255, 0, 0, 0, 0, 255, 0, 64, 0, 0, 255, 128, 9, 9, 9, 255};
  write_png(dir / "base.png", 2, 2, 4, pixels);
  json g = triangle_gltf();
  g["materials"][0].erase("emissiveFactor");
  g["images"] = {{{"uri", "base.png"}}};
  g["textures"] = {{{"source", 0}}};
  g["materials"][0]["pbrMetallicRoughness"]["baseColorFactor"] = {1.0, 1.0, 1.0, 0.5};
  g["materials"][0]["pbrMetallicRoughness"]["baseColorTexture"] = {{"index", 0}};
  g["materials"][0]["alphaMode"] = "MASK";
  g["materials"][0]["alphaCutoff"] = 0.3;
  GltfScene s = import_in(dir, g).scene;
  EXPECT_TRUE(s.warnings.empty()) << s.warnings[0];
  const Node& alpha = one(*s.parsed.root, "bsdf", "alphatest");
  EXPECT_DOUBLE_EQ(prop(alpha, "cutoff").number, 0.3);
  Image opacity = load_image(prop(*prop(alpha, "opacity").object, "filename").text, true);
  ASSERT_EQ(opacity.width, 2);
  for (int i = 0; i < 4; ++i)
    EXPECT_NEAR(opacity.texels[i].x, 0.5 * pixels[4 * i + 3] / 255.0, 1e-6) << i;
  Scene scene = load_scene((dir / "scene.gltf").string(), {});
  ASSERT_EQ(scene.buffers.materials.size(), 1u);
  EXPECT_NE(scene.buffers.materials[0].flags & MATERIAL_ALPHA_TESTED, 0u);
  EXPECT_FLOAT_EQ(scene.buffers.materials[0].alpha_cutoff, 0.3f);
}

// A normal-mapped primitive's PLY carries tangent frames (the file's TANGENT, else twinray's
// MikkTSpace tangents) and its shape reads them (`vertex_tangents`); the frames reach the scene
// through the node's transform. The triangle's dp/du is +x and its v runs along +y, so up the
// image (glTF's +y of a normal texture) is -y: bitangent -(n x t), n the face's +z (no NORMAL).
TEST(GltfImport, NormalMapsGetTangentFrames) {
  std::filesystem::path dir = fresh_dir();
  const unsigned char flat[] = {128, 128, 255};
  write_png(dir / "n.png", 1, 1, 3, flat);
  json g = triangle_gltf();
  g["materials"][0].erase("emissiveFactor");
  g["images"] = {{{"uri", "n.png"}}};
  g["textures"] = {{{"source", 0}}};
  g["materials"][0]["normalTexture"] = {{"index", 0}};
  GltfScene s = import_in(dir, g).scene;
  EXPECT_TRUE(s.warnings.empty()) << s.warnings[0];
  const Node& shape = one(*s.parsed.root, "shape", "ply");
  EXPECT_TRUE(prop(shape, "vertex_tangents").boolean);
  TriangleMesh mesh = load_ply_mesh(prop(shape, "filename").text, false);
  ASSERT_EQ(mesh.attributes.count("vertex_tangent"), 1u);
  ASSERT_EQ(mesh.attributes.count("vertex_bitangent"), 1u);
  for (size_t v = 0; v < mesh.positions.size(); ++v) {
    const std::vector<float>& t = mesh.attributes["vertex_tangent"].values;
    const std::vector<float>& b = mesh.attributes["vertex_bitangent"].values;
    expect_vec(glm::dvec3(t[3 * v], t[3 * v + 1], t[3 * v + 2]), glm::dvec3(1.0, 0.0, 0.0), 1e-6);
    expect_vec(glm::dvec3(b[3 * v], b[3 * v + 1], b[3 * v + 2]), glm::dvec3(0.0, -1.0, 0.0), 1e-6);
  }
  // In the scene: turned 90 degrees about z and scaled by 2 (triangle_gltf's nodes).
  Scene scene = load_scene((dir / "scene.gltf").string(), {});
  const Shape& r = scene.buffers.shapes[0];
  ASSERT_NE(r.flags & SHAPE_HAS_TANGENTS, 0u);
  auto word = [&](uint i) { return double(glm::uintBitsToFloat(scene.buffers.attributes[i])); };
  for (uint v = 0; v < r.vertex_count; ++v) {
    uint t = r.tangent_frames + 3 * v, b = t + 3 * r.vertex_count;
    expect_vec(glm::dvec3(word(t), word(t + 1), word(t + 2)), glm::dvec3(0.0, 2.0, 0.0), 1e-6);
    expect_vec(glm::dvec3(word(b), word(b + 1), word(b + 2)), glm::dvec3(2.0, 0.0, 0.0), 1e-6);
  }

  g["materials"][0].erase("normalTexture");
  GltfScene plain = import_in(fresh_dir(), g).scene;
  EXPECT_THROW(prop(one(*plain.parsed.root, "shape", "ply"), "vertex_tangents"),
               std::runtime_error);
}

// The same warning for fields of the same shape is printed once, with its count and the shape.
TEST(GltfImport, RepeatedWarningsAreCollapsed) {
  json g = triangle_gltf();
  g["materials"][0].erase("emissiveFactor");
  json prim = g["meshes"][0]["primitives"][0];
  prim["attributes"]["COLOR_0"] = 1;
  g["meshes"][0]["primitives"] = {prim, prim, prim};
  GltfScene s = import(g).scene;
  ASSERT_EQ(s.warnings.size(), 1u) << s.warnings[1];
  EXPECT_NE(s.warnings[0].find("meshes[0].primitives[0].attributes.COLOR_0: vertex colors are "
                               "not supported by twinray, ignored (x 3: "
                               "meshes[*].primitives[*].attributes.COLOR_0)"),
            std::string::npos)
      << s.warnings[0];
}

TEST(GltfImport, FieldsThatDoNotMapAreWarnedOneLineEach) {
  json g = triangle_gltf();
  g["skins"] = {{{"joints", {0}}}};
  g["extensionsUsed"] = {"KHR_materials_clearcoat"};
  g["materials"][0]["extensions"]["KHR_materials_clearcoat"] = {{"clearcoatFactor", 1.0}};
  g["meshes"][0]["primitives"][0]["attributes"]["TEXCOORD_1"] = 1;
  g["materials"][0]["alphaMode"] = "BLEND";
  g["materials"][0]["alphaCutoff"] = 0.25;
  g["materials"][0]["occlusionTexture"] = {{"index", 0}};
  g["images"] = {{{"uri", "none.png"}}};
  g["textures"] = {{{"source", 0}}};
  Imported im = import(g);
  std::vector<std::string> expected = {
      "skins: not supported by twinray, ignored",
      "extensionsUsed[0]: extension \"KHR_materials_clearcoat\" not supported by twinray",
      "materials[0].extensions.KHR_materials_clearcoat: extension not supported by twinray",
      "meshes[0].primitives[0].attributes.TEXCOORD_1: ignored: only TEXCOORD_0 is read",
      "materials[0].alphaCutoff: ignored: the material's alphaMode is not MASK",
      "materials[0].occlusionTexture: not used"};
  ASSERT_EQ(im.scene.warnings.size(), expected.size());
  for (size_t i = 0; i < expected.size(); ++i) {
    bool found = false;
    for (const std::string& w : im.scene.warnings) found = found || w.find(expected[i]) != w.npos;
    EXPECT_TRUE(found) << expected[i];
  }
}

// BLEND: Mitsuba's mask with alpha as its opacity (an opaque alpha of 1 needs none), warned as
// an approximation; --strict-gltf refuses it, as every field that does not map exactly, but not
// what has no effect on the rendered quantity (minFilter, occlusionTexture).
TEST(GltfImport, BlendIsAMaskAndStrictGltfRefusesApproximations) {
  json g = triangle_gltf();
  g["materials"][0]["alphaMode"] = "BLEND";
  g["materials"][0]["pbrMetallicRoughness"]["baseColorFactor"] = {0.5, 0.25, 0.125, 0.375};
  Imported im = import(g);
  const Node& mask = one(*im.scene.parsed.root, "bsdf", "mask");
  EXPECT_EQ(prop(mask, "opacity").number, 0.375);
  one(mask, "bsdf", "principled");
  ASSERT_EQ(im.scene.warnings.size(), 1u);
  EXPECT_NE(
      im.scene.warnings[0].find("materials[0].alphaMode: approximate: BLEND as Mitsuba's mask"),
      std::string::npos);

  LoadOptions strict;
  strict.strict_gltf = true;
  try {
    import(g, strict);
    ADD_FAILURE() << "BLEND accepted with --strict-gltf";
  } catch (const SceneError& e) {
    EXPECT_NE(std::string(e.what()).find("materials[0].alphaMode: approximate: BLEND"),
              std::string::npos);
    EXPECT_NE(std::string(e.what()).find("(refused: --strict-gltf)"), std::string::npos);
  }
  json exact = triangle_gltf();
  exact["samplers"] = {{{"minFilter", 9987}}};
  exact["materials"][0]["occlusionTexture"] = {{"index", 0}};
  exact["images"] = {{{"uri", "none.png"}}};
  exact["textures"] = {{{"source", 0}, {"sampler", 0}}};
  EXPECT_EQ(import(exact, strict).scene.warnings.size(), 2u);
}

// --camera auto (the default without a camera node): yfov 45 degrees down -z at the centre c of
// the world bounds, at d = r / sin(fov / 2) with fov the narrower field of view.
TEST(GltfImport, WithoutACameraTheBoundsAreFramed) {
  json g = triangle_gltf();
  g["nodes"][2].erase("camera");
  Imported im = import(g);
  const Node& sensor = one(*im.scene.parsed.root, "sensor", "perspective");
  EXPECT_EQ(prop(sensor, "fov").number, 45.0);
  // The triangle's world corners: (1,2,3) + R_z(90) * 2 (x, y, 0): x in [-1, 1], y in [2, 4].
  glm::dvec3 c(0.0, 3.0, 3.0);
  double r = std::sqrt(2.0), aspect = 768.0 / 576.0;
  double xfov = 2.0 * std::atan(std::tan(glm::radians(22.5)) * aspect);
  double d = r / std::sin(0.5 * std::min(glm::radians(45.0), xfov));
  const glm::dmat4& cam = prop(sensor, "to_world").matrix;
  expect_vec(glm::dvec3(cam[3]), c + glm::dvec3(0, 0, d), 1e-9);
  expect_vec(glm::dvec3(cam[2]), {0, 0, -1});
  ASSERT_EQ(im.scene.warnings.size(), 1u);
  EXPECT_NE(im.scene.warnings[0].find("no node of the scene has a camera: rendered through a "
                                      "camera framing the scene's bounds (--camera auto)"),
            std::string::npos)
      << im.scene.warnings[0];

  LoadOptions o;
  o.camera = "auto";  // asked for: the file's camera is not used, nothing is warned
  o.defines = {{"width", "100"}, {"height", "400"}};
  Imported tall = import(triangle_gltf(), o);
  const Node& s2 = one(*tall.scene.parsed.root, "sensor", "perspective");
  xfov = 2.0 * std::atan(std::tan(glm::radians(22.5)) * 0.25);
  expect_vec(glm::dvec3(prop(s2, "to_world").matrix[3]),
             c + glm::dvec3(0, 0, r / std::sin(0.5 * xfov)));
  EXPECT_TRUE(tall.scene.warnings.empty());
}

TEST(GltfImport, CameraNChoosesTheFilesNthCamera) {
  json g = triangle_gltf();
  g["cameras"].push_back(
      {{"type", "perspective"}, {"perspective", {{"yfov", 1.0}, {"znear", 0.5}}}});
  g["nodes"].push_back({{"camera", 1}, {"translation", {0.0, 7.0, 0.0}}});
  g["scenes"][0]["nodes"].push_back(3);
  Imported first = import(g);
  EXPECT_NEAR(prop(one(*first.scene.parsed.root, "sensor", "perspective"), "fov").number,
              glm::degrees(0.5), 1e-12);
  ASSERT_EQ(first.scene.warnings.size(), 1u);
  EXPECT_NE(first.scene.warnings[0].find("nodes[3].camera: not used: twinray renders through the "
                                         "first camera node, nodes[2] (--camera N chooses"),
            std::string::npos);
  LoadOptions o;
  o.camera = "1";
  Imported second = import(g, o);
  const Node& sensor = one(*second.scene.parsed.root, "sensor", "perspective");
  EXPECT_NEAR(prop(sensor, "fov").number, glm::degrees(1.0), 1e-12);
  expect_vec(glm::dvec3(prop(sensor, "to_world").matrix[3]), {0, 7, 0});
  EXPECT_TRUE(second.scene.warnings.empty());
  for (const char* bad : {"2", "1"}) {
    if (std::string(bad) == "1") g["scenes"][0]["nodes"].erase(2);  // cameras[1] on no node
    o.camera = bad;
    try {
      import(g, o);
      ADD_FAILURE() << "--camera " << bad << " accepted";
    } catch (const SceneError& e) {
      EXPECT_NE(std::string(e.what()).find(
                    std::string(bad) == "2" ? "--camera 2: the file has 2 cameras"
                                            : "--camera 1: no node of the scene uses cameras[1]"),
                std::string::npos)
          << e.what();
    }
  }
}

std::string load_error(const std::string& name, const std::string& text) {
  std::filesystem::path dir = fresh_dir();
  std::string path = write_file(dir, name, text);
  try {
    load_scene(path, {});
  } catch (const SceneError& e) {
    std::string message = e.what();
    EXPECT_EQ(message.find('\n'), std::string::npos) << message;
    EXPECT_EQ(message.rfind(path + ":", 0), 0u) << message;
    return message.substr(path.size());
  }
  ADD_FAILURE() << "no SceneError for " << name;
  return "";
}

TEST(GltfImport, MalformedFilesGiveOneLineErrors) {
  EXPECT_EQ(load_error("cut.gltf", "{\n \"asset\": {\"version\": \"2.0\"},\n \"nodes\": [\n")
                .rfind(":4: malformed JSON", 0),
            0u);
  json g = triangle_gltf();
  g["buffers"][0]["uri"] = "missing.bin";
  EXPECT_NE(
      load_error("nobuffer.gltf", g.dump(1)).find("buffers[0].uri: file \"missing.bin\" not found"),
      std::string::npos);
  json v = triangle_gltf();
  v["asset"]["version"] = "1.0";
  EXPECT_NE(load_error("old.gltf", v.dump(1)).find("asset.version: glTF 1.0 is not glTF 2.x"),
            std::string::npos);
  json c = triangle_gltf();
  c["nodes"][2].erase("camera");
  c["meshes"][0]["primitives"][0]["mode"] = 0;  // points: nothing to frame
  EXPECT_NE(
      load_error("nocamera.gltf", c.dump(1)).find("--camera auto: the scene has no finite extent"),
      std::string::npos);
  EXPECT_NE(load_error("bad.glb", "glTF\x02").find("truncated GLB header"), std::string::npos);
}

}  // namespace
}  // namespace tr
