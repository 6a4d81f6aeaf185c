// core/texture.h on the host, against hand-computed lookups, and the loader's image decoding.
#include "core/texture.h"

#include <Imath/half.h>
#include <OpenImageIO/imageio.h>
#include <gtest/gtest.h>

#include <algorithm>

#include "scene_test_files.h"
#include "scenes/bitmap.h"

namespace tr {

// The scene accessors core/texture.h reads, over one SceneBuffers (the test's own scene).
static const SceneBuffers* g_buffers = nullptr;
const Texture& scene_texture(uint i) { return g_buffers->textures[i]; }
vec4 scene_texel(uint i) { return g_buffers->texels[i]; }
const Shape& scene_shape(uint i) { return g_buffers->shapes[i]; }
uint scene_index(uint i) { return g_buffers->indices[i]; }
uint scene_attribute(uint i) { return g_buffers->attributes[i]; }

namespace {

using namespace testing_files;

// A 2x2 bitmap, texels a b (top row) / c d (bottom row).
SceneBuffers two_by_two(uint filter, uint wrap) {
  SceneBuffers b;
  b.texels = {vec4(1, 0, 0, 1), vec4(0, 1, 0, 1), vec4(0, 0, 1, 1), vec4(1, 1, 1, 1)};
  Texture t{};
  t.type = TEXTURE_BITMAP;
  t.filter_mode = filter;
  t.wrap_mode = wrap;
  t.width = t.height = 2;
  t.to_uv[0] = vec4(1, 0, 0, 0);
  t.to_uv[1] = vec4(0, 1, 0, 0);
  b.textures.push_back(t);
  return b;
}

void expect_vec(vec3 a, vec3 b) {
  EXPECT_NEAR(a.x, b.x, 1e-6);
  EXPECT_NEAR(a.y, b.y, 1e-6);
  EXPECT_NEAR(a.z, b.z, 1e-6);
}

TEST(Texture, BilinearLookup) {
  SceneBuffers b = two_by_two(FILTER_BILINEAR, WRAP_REPEAT);
  g_buffers = &b;
  expect_vec(eval_texture(0, vec2(0.25f, 0.25f)), vec3(1, 0, 0));  // texel centre, top left
  expect_vec(eval_texture(0, vec2(0.75f, 0.75f)), vec3(1, 1, 1));  // bottom right
  expect_vec(eval_texture(0, vec2(0.5f, 0.25f)), vec3(0.5f, 0.5f, 0));
  expect_vec(eval_texture(0, vec2(0.5f, 0.5f)), vec3(0.5f, 0.5f, 0.5f));
  // Repeat: at uv = 0 the four neighbours are the four (wrapped) corners.
  expect_vec(eval_texture(0, vec2(0.0f, 0.0f)), vec3(0.5f, 0.5f, 0.5f));
  expect_vec(eval_texture(0, vec2(1.25f, -0.75f)), vec3(1, 0, 0));
}

TEST(Texture, WrapModes) {
  SceneBuffers clamp = two_by_two(FILTER_BILINEAR, WRAP_CLAMP);
  g_buffers = &clamp;
  expect_vec(eval_texture(0, vec2(0.0f, 0.0f)), vec3(1, 0, 0));
  expect_vec(eval_texture(0, vec2(3.0f, 0.25f)), vec3(0, 1, 0));
  SceneBuffers mirror = two_by_two(FILTER_NEAREST, WRAP_MIRROR);
  g_buffers = &mirror;
  // Texel columns for x = -2..3 under mirroring: 1 0 | 0 1 | 1 0.
  expect_vec(eval_texture(0, vec2(-0.75f, 0.25f)), vec3(0, 1, 0));
  expect_vec(eval_texture(0, vec2(-0.25f, 0.25f)), vec3(1, 0, 0));
  expect_vec(eval_texture(0, vec2(1.25f, 0.25f)), vec3(0, 1, 0));
  expect_vec(eval_texture(0, vec2(1.75f, 0.25f)), vec3(1, 0, 0));
  SceneBuffers nearest = two_by_two(FILTER_NEAREST, WRAP_REPEAT);
  g_buffers = &nearest;
  expect_vec(eval_texture(0, vec2(0.49f, 0.51f)), vec3(0, 0, 1));
  expect_vec(eval_texture(0, vec2(-0.49f, 0.51f)), vec3(1, 1, 1));
}

// Mitsuba's eval_1_grad (bitmap.cpp): the uv derivative of the bilinear interpolation of the
// first channel, checked against central differences of eval_texture inside the four-texel
// cells (where the interpolant is smooth), through a diagonal to_uv, and zero when nearest.
TEST(Texture, BilinearGradient) {
  SceneBuffers b = two_by_two(FILTER_BILINEAR, WRAP_REPEAT);
  b.textures[0].to_uv[0] = vec4(3, 0, 0.1f, 0);
  b.textures[0].to_uv[1] = vec4(0, -2, 0.2f, 0);
  g_buffers = &b;
  const float h = 1e-3f;
  for (vec2 uv : {vec2(0.07f, 0.03f), vec2(0.3f, 0.41f), vec2(0.62f, 0.17f), vec2(0.9f, 0.8f)}) {
    vec2 g = eval_texture_1_grad(0, uv);
    float du = (eval_texture(0, uv + vec2(h, 0)).x - eval_texture(0, uv - vec2(h, 0)).x) / (2 * h);
    float dv = (eval_texture(0, uv + vec2(0, h)).x - eval_texture(0, uv - vec2(0, h)).x) / (2 * h);
    EXPECT_NEAR(g.x, du, 2e-2f) << uv.x << "," << uv.y;
    EXPECT_NEAR(g.y, dv, 2e-2f) << uv.x << "," << uv.y;
    EXPECT_GT(std::abs(g.x) + std::abs(g.y), 1.0f);
  }
  // Between the four texel centres (weights 1/2) with top row (1, 0.5), bottom row (0, 1):
  // dh/dx = ((0.5 - 1) + (1 - 0)) / 2 texels, times the resolution 2 and the to_uv scale 3;
  // dh/dy = ((0 - 1) + (1 - 0.5)) / 2 times the resolution 2.
  b.texels[1] = vec4(0.5f, 0, 0, 1);
  b.textures[0].to_uv[0] = vec4(3, 0, 0, 0);
  b.textures[0].to_uv[1] = vec4(0, 1, 0, 0);
  vec2 g = eval_texture_1_grad(0, vec2(0.5f / 3.0f, 0.5f));
  EXPECT_NEAR(g.x, 1.5f, 1e-5f);
  EXPECT_NEAR(g.y, -0.5f, 1e-5f);
  b.textures[0].filter_mode = FILTER_NEAREST;
  g = eval_texture_1_grad(0, vec2(0.3f, 0.41f));
  EXPECT_EQ(g, vec2(0.0f));
}

TEST(Texture, CheckerboardAndTexturedValues) {
  SceneBuffers b;
  Texture t{};
  t.type = TEXTURE_CHECKERBOARD;
  t.color0 = vec4(1, 0, 0, 1);
  t.color1 = vec4(0, 0, 1, 1);
  t.to_uv[0] = vec4(2, 0, 0, 0);
  t.to_uv[1] = vec4(0, 2, 0, 0);
  b.textures.push_back(t);
  g_buffers = &b;
  expect_vec(eval_texture(0, vec2(0.1f, 0.1f)), vec3(1, 0, 0));  // both fractions < 1/2
  expect_vec(eval_texture(0, vec2(0.3f, 0.1f)), vec3(0, 0, 1));
  expect_vec(eval_texture(0, vec2(0.3f, 0.3f)), vec3(1, 0, 0));
  expect_vec(eval_texture(0, vec2(0.6f, 0.1f)), vec3(1, 0, 0));
  TexturedValue constant{vec3(0.25f), NO_INDEX};
  expect_vec(eval_textured(constant, vec2(0.3f, 0.1f)), vec3(0.25f));
  TexturedValue textured{vec3(0.0f), 0u};
  expect_vec(eval_textured(textured, vec2(0.3f, 0.1f)), vec3(0, 0, 1));
}

// Mitsuba's mesh_attribute (Mesh::interpolate_attribute): vertex values interpolated with the
// barycentrics of the hit, face values constant over the triangle, both times `scale`.
TEST(Texture, MeshAttributesInterpolatedAndConstantPerFace) {
  SceneBuffers b;
  // Shape 1 is a quad (triangles 0 2 1 and 0 3 2 of its own vertices) after a triangle of
  // shape 0, so the lookups must go through first_index; its table starts at word 2.
  b.indices = {0, 1, 2, 0, 2, 1, 0, 3, 2};
  Shape quad{};
  quad.type = SHAPE_MESH;
  quad.first_index = 3;
  quad.attribute_table = 2;
  b.shapes = {Shape{}, quad};
  auto bits = [](float f) { return glm::floatBitsToUint(f); };
  // Slot 0: vertex_c, 3 channels; slot 1: face_w, 1 channel; slot 2 unused by this mesh.
  b.attributes = {7u, 7u, 8u, 3u, 20u, 1u, NO_INDEX, 0u};
  const float c[4][3] = {{1, 0, 0}, {0, 2, 0}, {0, 0, 4}, {0.5f, 0.5f, 0.5f}};
  for (const auto& v : c)
    for (float x : v) b.attributes.push_back(bits(x));
  b.attributes.push_back(bits(0.25f));
  b.attributes.push_back(bits(0.75f));
  Texture vertex{};
  vertex.type = TEXTURE_MESH_ATTRIBUTE;
  vertex.attribute_slot = 0u;
  vertex.color0 = vec4(2.0f, 0, 0, 0);  // scale
  Texture face = vertex;
  face.attribute_slot = 1u;
  face.attribute_per_face = 1u;
  face.color0.x = 3.0f;
  b.textures = {vertex, face};
  g_buffers = &b;
  const TexturedValue v{vec3(0.0f), 0u}, f{vec3(0.0f), 1u};
  // Triangle 0 of the quad: vertices 0, 2, 1 with weights b0 = 1 - b1 - b2, b1, b2.
  const vec2 bary(0.25f, 0.5f);
  expect_vec(eval_textured(v, tex_coord_mesh(vec2(0.9f), 1u, 0u, bary)),
             2.0f * (0.25f * vec3(1, 0, 0) + 0.25f * vec3(0, 0, 4) + 0.5f * vec3(0, 2, 0)));
  // Triangle 1: vertices 0, 3, 2.
  expect_vec(eval_textured(v, tex_coord_mesh(vec2(0.0f), 1u, 1u, vec2(0.5f, 0.5f))),
             2.0f * (0.5f * vec3(0.5f) + 0.5f * vec3(0, 0, 4)));
  // At a corner the vertex's value; the uv plays no part.
  expect_vec(eval_textured(v, tex_coord_mesh(vec2(0.3f), 1u, 1u, vec2(1.0f, 0.0f))), vec3(1.0f));
  // A face attribute is the same anywhere on its triangle, one channel broadcast.
  for (vec2 at : {vec2(0.0f), vec2(1.0f, 0.0f), vec2(0.2f, 0.7f)}) {
    expect_vec(eval_textured(f, tex_coord_mesh(vec2(0.5f), 1u, 0u, at)), vec3(0.75f));
    expect_vec(eval_textured(f, tex_coord_mesh(vec2(0.5f), 1u, 1u, at)), vec3(2.25f));
  }
}

// The same through the loader: a PLY's attributes, the shape's table and the texture records.
TEST(Texture, MeshAttributesOfALoadedPly) {
  std::filesystem::path dir = fresh_dir();
  write_file(dir, "tri.ply",
             "ply\nformat ascii 1.0\nelement vertex 3\nproperty float x\nproperty float y\n"
             "property float z\nproperty float w_x\nelement face 1\n"
             "property list uchar int vertex_indices\nproperty float r\nproperty float g\n"
             "property float b\nend_header\n0 0 0 1\n1 0 0 2\n0 1 0 4\n3 0 1 2 0.1 0.2 0.3\n");
  auto shape = [](const std::string& param, const std::string& name) {
    return "<shape type=\"ply\"><string name=\"filename\" value=\"tri.ply\"/><bsdf "
           "type=\"diffuse\"><texture type=\"mesh_attribute\" name=\"" +
           param + "\"><string name=\"name\" value=\"" + name +
           "\"/><float name=\"scale\" value=\"0.5\"/></texture></bsdf></shape>";
  };
  Scene s = load_scene(
      write_file(dir, "scene.xml",
                 scene_xml(shape("reflectance", "vertex_w") + shape("reflectance", "face_color"))),
      {});
  g_buffers = &s.buffers;
  const TexturedValue w = s.buffers.materials[s.buffers.shapes[0].material].param[0];
  const TexturedValue color = s.buffers.materials[s.buffers.shapes[1].material].param[0];
  expect_vec(eval_textured(w, tex_coord_mesh(vec2(0.0f), 0u, 0u, vec2(0.25f, 0.5f))),
             vec3(0.5f * (0.25f * 1 + 0.25f * 2 + 0.5f * 4)));
  expect_vec(eval_textured(color, tex_coord_mesh(vec2(0.0f), 1u, 0u, vec2(0.25f, 0.5f))),
             0.5f * vec3(0.1f, 0.2f, 0.3f));
}

TEST(Texture, ImagesLoadTopRowFirstAndSrgbDecoded) {
  std::filesystem::path dir = fresh_dir();
  std::string png = (dir / "image.png").string();
  // 2x2, top row red | green, bottom row 128-grey | white.
  const unsigned char pixels[] = {255, 0, 0, 0, 255, 0, 128, 128, 128, 255, 255, 255};
  auto out = OIIO::ImageOutput::create(png);
  ASSERT_TRUE(out);
  OIIO::ImageSpec spec(2, 2, 3, OIIO::TypeDesc::UINT8);
  ASSERT_TRUE(out->open(png, spec));
  ASSERT_TRUE(out->write_image(OIIO::TypeDesc::UINT8, pixels));
  out->close();

  float grey = srgb_to_linear(128.0f / 255.0f);
  EXPECT_NEAR(grey, 0.2158605, 1e-6);  // IEC 61966-2-1
  Image image = load_image(png, false);
  EXPECT_EQ(image.texels[0], glm::vec4(1, 0, 0, 1));
  EXPECT_NEAR(image.texels[2].x, grey, 1e-6);
  Image raw = load_image(png, true);
  EXPECT_NEAR(raw.texels[2].x, 128.0f / 255.0f, 1e-6);

  std::string xml = write_file(
      dir, "scene.xml",
      scene_xml("<shape type=\"sphere\"><bsdf type=\"diffuse\"><texture name=\"reflectance\" "
                "type=\"bitmap\"><string name=\"filename\" value=\"image.png\"/>"
                "<string name=\"filter_type\" value=\"nearest\"/></texture></bsdf></shape>"));
  Scene s = load_scene(xml, {});
  g_buffers = &s.buffers;
  uint tex = s.buffers.materials[0].param[0].texture;
  ASSERT_NE(tex, NO_INDEX);
  // v = 0.25 is the top row (Mitsuba: v -> rows, row 0 = top of the image). An 8-bit image is
  // stored in half precision (Mitsuba's default bitmap format "auto").
  expect_vec(eval_texture(tex, vec2(0.25f, 0.25f)), vec3(1, 0, 0));
  expect_vec(eval_texture(tex, vec2(0.75f, 0.25f)), vec3(0, 1, 0));
  expect_vec(eval_texture(tex, vec2(0.25f, 0.75f)), vec3(float(Imath::half(grey))));
}

// Every band of rows reaches its place, from a tiled file and from one whose data window does
// not start at the origin; 64 x 40 with more rows than a band of a 32768-texel-wide image.
TEST(Texture, TiledAndOffsetImagesLoadWhole) {
  std::filesystem::path dir = fresh_dir();
  const int w = 64, h = 40;
  std::vector<float> pixels(size_t(w) * h * 3);
  for (size_t i = 0; i < pixels.size(); ++i) pixels[i] = float(i % 977) / 977.0f;
  for (bool tiled : {false, true}) {
    std::string exr = (dir / (tiled ? "tiled.exr" : "offset.exr")).string();
    OIIO::ImageSpec spec(w, h, 3, OIIO::TypeDesc::FLOAT);
    if (tiled) {
      spec.tile_width = spec.tile_height = 16;
    } else {
      spec.x = 5;
      spec.y = -7;
    }
    auto out = OIIO::ImageOutput::create(exr);
    ASSERT_TRUE(out);
    ASSERT_TRUE(out->open(exr, spec));
    ASSERT_TRUE(out->write_image(OIIO::TypeDesc::FLOAT, pixels.data()));
    out->close();
    Image image = load_image(exr, false);
    ASSERT_EQ(image.texels.size(), size_t(w) * h);
    for (size_t i = 0; i < image.texels.size(); ++i)
      ASSERT_EQ(image.texels[i], glm::vec4(pixels[3 * i], pixels[3 * i + 1], pixels[3 * i + 2], 1))
          << exr << " texel " << i;
  }
}

// PNG alpha stays unassociated, as Mitsuba 3.8's Bitmap::read_png leaves it
// (m_premultiplied_alpha = false): a grey texel under alpha 0 keeps its grey.
TEST(Texture, PngAlphaIsNotPremultiplied) {
  std::filesystem::path dir = fresh_dir();
  std::string png = (dir / "grey_alpha.png").string();
  const unsigned char pixels[] = {128, 0, 128, 255, 255, 64, 0, 255};
  auto out = OIIO::ImageOutput::create(png);
  ASSERT_TRUE(out);
  ASSERT_TRUE(out->open(png, OIIO::ImageSpec(2, 2, 2, OIIO::TypeDesc::UINT8)));
  ASSERT_TRUE(out->write_image(OIIO::TypeDesc::UINT8, pixels));
  out->close();
  Image raw = load_image(png, true);
  ASSERT_EQ(raw.channels, 2);
  EXPECT_EQ(raw.texels[0], glm::vec4(glm::vec3(128.0f / 255.0f), 0.0f));
  EXPECT_EQ(raw.texels[2], glm::vec4(glm::vec3(1.0f), 64.0f / 255.0f));
  EXPECT_EQ(load_image(png, false).texels[0],
            glm::vec4(glm::vec3(srgb_to_linear(128.0f / 255.0f)), 0.0f));
}

// PFM (bottom row first, byte order by the scale's sign) and 16-bit PPM (most significant byte
// first, Netpbm) load to the values the files hold.
TEST(Texture, PfmAndSixteenBitPpmLoadExactly) {
  std::filesystem::path dir = fresh_dir();
  auto big_endian = [](const void* p, size_t size) {
    std::string bytes(static_cast<const char*>(p), size);
    std::reverse(bytes.begin(), bytes.end());
    return bytes;
  };
  // 1 x 2 grey, rows bottom first: 2.5 (bottom), -0.75 (top).
  const float bottom = 2.5f, top = -0.75f;
  std::string little("Pf\n1 2\n-1.0\n");
  little.append(reinterpret_cast<const char*>(&bottom), 4);
  little.append(reinterpret_cast<const char*>(&top), 4);
  std::string big = "Pf\n1 2\n1.0\n" + big_endian(&bottom, 4) + big_endian(&top, 4);
  for (const std::string& file : {little, big}) {
    Image image = load_image(write_file(dir, "grey.pfm", file), false);
    ASSERT_EQ(image.texels.size(), 2u);
    EXPECT_EQ(image.texels[0], glm::vec4(-0.75f, -0.75f, -0.75f, 1.0f));
    EXPECT_EQ(image.texels[1], glm::vec4(2.5f, 2.5f, 2.5f, 1.0f));
    EXPECT_EQ(image.bytes_per_channel, 4);
  }
  const std::string ppm =
      std::string("P6\n1 1\n65535\n") + std::string("\x03\xe8\x75\x30\xff\xff", 6);
  Image image = load_image(write_file(dir, "rgb16.ppm", ppm), true);
  EXPECT_EQ(image.bytes_per_channel, 2);
  EXPECT_EQ(image.texels[0],
            glm::vec4(1000.0f * (1.0f / 65535.0f), 30000.0f * (1.0f / 65535.0f), 1.0f, 1.0f));
}

// A 70-byte BMP whose header claims 2 x 100663298 texels (found by scripts/fuzz) is refused
// before the 2.4 GB it would take are allocated.
TEST(Texture, HeadersClaimingHugeImagesAreRefused) {
  std::filesystem::path dir = fresh_dir();
  const unsigned char bmp[] = {
      0x42, 0x4d, 0x46, 0x00, 0x00, 0x00, 0x00, 0x00, 0x00, 0x00, 0x36, 0x00, 0x00, 0x00,
      0x28, 0x00, 0x00, 0x00, 0x02, 0x00, 0x00, 0x00, 0x02, 0x00, 0x00, 0x06, 0x01, 0x00,
      0x18, 0x00, 0x00, 0x00, 0x00, 0x00, 0x04, 0x00, 0x00, 0x09, 0x00, 0x00, 0x00, 0x00,
      0x00, 0x00, 0x00, 0x00, 0x00, 0x00, 0x00, 0x00, 0x00, 0x00, 0x00, 0x00, 0xff, 0xff,
      0xff, 0x00, 0x00, 0x00, 0x00, 0x00, 0x00, 0x00, 0x00, 0xff, 0xff, 0xff, 0x00, 0x00};
  std::string path = write_file(dir, "huge.bmp", std::string(bmp, bmp + sizeof(bmp)));
  try {
    load_image(path, false);
    FAIL() << "the image was accepted";
  } catch (const std::runtime_error& e) {
    EXPECT_STREQ(e.what(), "image of 2 x 100663298 texels: twinray reads at most 65536 per side");
  }
}

// A BMP, a TGA and an RGBE file that end inside their texels are refused; stb_image alone would
// read the missing bytes as zeros. Whole, they load to their texels.
TEST(Texture, TruncatedStbImagesAreRefused) {
  std::filesystem::path dir = fresh_dir();
  auto le32 = [](uint32_t v) {
    return std::string{char(v), char(v >> 8), char(v >> 16), char(v >> 24)};
  };
  // 2 x 2, 24 bits, rows bottom first and padded to 4 bytes: bottom row blue | green, top row
  // red | white (BGR order).
  std::string bmp = "BM" + le32(70) + le32(0) + le32(54) + le32(40) + le32(2) + le32(2) +
                    std::string("\x01\x00\x18\x00", 4) + le32(0) + le32(16) + le32(2835) +
                    le32(2835) + le32(0) + le32(0);
  bmp += std::string("\xff\x00\x00\x00\xff\x00\x00\x00", 8);
  bmp += std::string("\x00\x00\xff\xff\xff\xff\x00\x00", 8);
  // 2 x 2 uncompressed true-colour TGA, rows top first (descriptor bit 5), BGR.
  std::string tga("\x00\x00\x02\x00\x00\x00\x00\x00\x00\x00\x00\x00\x02\x00\x02\x00\x18\x20", 18);
  tga += std::string("\x00\x00\xff\xff\xff\xff\xff\x00\x00\x00\xff\x00", 12);
  // 2 x 2 RGBE, flat scanlines: red, white / blue, green at exponent 129 (values 1 or 0).
  std::string hdr = "#?RADIANCE\nFORMAT=32-bit_rle_rgbe\n\n-Y 2 +X 2\n";
  hdr += std::string("\x80\x00\x00\x81\x80\x80\x80\x81\x00\x00\x80\x81\x00\x80\x00\x81", 16);
  const std::pair<std::string, std::string> files[] = {
      {"image.bmp", bmp}, {"image.tga", tga}, {"image.hdr", hdr}};
  for (const auto& [name, file] : files) {
    Image image = load_image(write_file(dir, name, file), true);
    ASSERT_EQ(image.texels.size(), 4u) << name;
    EXPECT_EQ(image.texels[0], glm::vec4(1, 0, 0, 1)) << name;
    EXPECT_EQ(image.texels[1], glm::vec4(1, 1, 1, 1)) << name;
    EXPECT_EQ(image.texels[2], glm::vec4(0, 0, 1, 1)) << name;
    EXPECT_EQ(image.texels[3], glm::vec4(0, 1, 0, 1)) << name;
    const std::string cut = write_file(dir, "cut_" + name, file.substr(0, file.size() - 5));
    try {
      load_image(cut, true);
      ADD_FAILURE() << name << ": the truncated file was accepted";
    } catch (const std::runtime_error& e) {
      EXPECT_STREQ(e.what(), "cannot open image: the file ends inside its texels") << name;
    }
  }
}

// Found by scripts/fuzz: libpng allocated the 2 GB a tEXt chunk's length claimed in a 370-byte
// file before finding the file too short.
TEST(Texture, PngChunksLongerThanTheFileAreRefused) {
  const std::string path =
      std::string(TWINRAY_SOURCE_DIR) + "/tests/fuzz/corpus/regression_png_chunk_length.png";
  try {
    load_image(path, false);
    FAIL() << "the image was accepted";
  } catch (const std::runtime_error& e) {
    EXPECT_STREQ(e.what(),
                 "cannot open image: a PNG chunk claims 2097191424 bytes, the file has "
                 "179 left");
  }
}

// Found by scripts/fuzz: OpenEXR allocated an attribute's claimed 1.7 GB before failing.
TEST(Texture, ExrAttributesLargerThanTheFileAreRefused) {
  std::filesystem::path dir = fresh_dir();
  std::string exr("\x76\x2f\x31\x01\x02\x00\x00\x00", 8);
  exr += std::string("comments\0string\0", 16) + std::string("\x5d\x6e\x20\x66", 4) + "short";
  std::string path = write_file(dir, "attribute.exr", exr);
  try {
    load_image(path, false);
    FAIL() << "the image was accepted";
  } catch (const std::runtime_error& e) {
    EXPECT_STREQ(e.what(),
                 "cannot open image: EXR attribute 'comments' claims 1713401437 bytes, the file "
                 "has 5 left");
  }
}

}  // namespace
}  // namespace tr
