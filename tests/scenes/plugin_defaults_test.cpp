// Every default of the BSDF, texture and emitter plugins twinray supports, against Mitsuba 3.8
// (src/bsdfs, src/textures, src/emitters, src/render/endpoint.cpp at v3.8.0): a scene that
// leaves a parameter out must build the same records, byte for byte, as one that sets it to
// Mitsuba's default, and a different value must build different records (so each comparison
// can fail). Also the Mitsuba 3.8 refusals and aliases the builders reproduce.
#include <Imath/half.h>
#include <OpenImageIO/imageio.h>
#include <gtest/gtest.h>

#include <cstring>
#include <sstream>

#include "core/material_slots.h"
#include "scene_test_files.h"

namespace tr {
namespace {

using namespace testing_files;

// A 2x2 8-bit sRGB PNG and a 4x3 float EXR written beside each scene.
void write_images(const std::filesystem::path& dir) {
  const unsigned char png[] = {255, 0, 0, 0, 255, 0, 0, 0, 255, 200, 100, 50};
  auto out = OIIO::ImageOutput::create((dir / "image.png").string());
  ASSERT_TRUE(out);
  ASSERT_TRUE(
      out->open((dir / "image.png").string(), OIIO::ImageSpec(2, 2, 3, OIIO::TypeDesc::UINT8)));
  ASSERT_TRUE(out->write_image(OIIO::TypeDesc::UINT8, png));
  out->close();
  std::vector<float> exr;
  for (int k = 0; k < 4 * 3 * 3; ++k) exr.push_back(0.1f + 0.0731f * float(k));
  out = OIIO::ImageOutput::create((dir / "image.exr").string());
  ASSERT_TRUE(out);
  ASSERT_TRUE(
      out->open((dir / "image.exr").string(), OIIO::ImageSpec(4, 3, 3, OIIO::TypeDesc::FLOAT)));
  ASSERT_TRUE(out->write_image(OIIO::TypeDesc::FLOAT, exr.data()));
  out->close();
}

// Loads scene_xml(body) from a fresh folder that also holds the test images; `tag` keeps the
// folders of one test apart.
Scene load_body(const std::string& body, const std::string& tag) {
  std::filesystem::path dir = fresh_dir() / tag;
  std::filesystem::create_directories(dir);
  if (body.find("image.") != std::string::npos) write_images(dir);
  return load_scene(write_file(dir, "scene.xml", scene_xml(body)), {});
}

std::string error_of(const std::string& body) {
  try {
    load_body(body, "error");
  } catch (const SceneError& e) {
    return e.what();
  }
  ADD_FAILURE() << "no SceneError for:\n" << body;
  return "";
}

void expect_error(const std::string& body, const std::string& words) {
  std::string e = error_of(body);
  EXPECT_NE(e.find(words), std::string::npos) << "expected \"" << words << "\" in: " << e;
}

template <typename T>
bool same_bytes(const std::vector<T>& a, const std::vector<T>& b) {
  return a.size() == b.size() &&
         (a.empty() || std::memcmp(a.data(), b.data(), a.size() * sizeof(T)) == 0);
}

// The records the BSDF, texture and emitter builders write.
bool same_records(const Scene& a, const Scene& b) {
  const SceneBuffers &x = a.buffers, &y = b.buffers;
  return same_bytes(x.materials, y.materials) && same_bytes(x.textures, y.textures) &&
         same_bytes(x.texels, y.texels) && same_bytes(x.emitters, y.emitters) &&
         same_bytes(x.alias, y.alias);
}

std::string replace(std::string text, const std::string& slot, const std::string& with) {
  size_t at = text.find(slot);
  EXPECT_NE(at, std::string::npos) << text;
  return at == std::string::npos ? text : text.replace(at, slot.size(), with);
}

// One default: `plugin` holds %P% where the parameter goes; `defaults` are spellings of
// Mitsuba's default (each must build what the absent parameter builds); `other` is a different
// value (it must not).
struct DefaultCase {
  std::string name;
  std::string plugin;
  std::vector<std::string> defaults;
  std::string other;
};

void check(const DefaultCase& c) {
  SCOPED_TRACE(c.name);
  Scene absent = load_body(replace(c.plugin, "%P%", ""), "absent");
  for (size_t i = 0; i < c.defaults.size(); ++i) {
    Scene given = load_body(replace(c.plugin, "%P%", c.defaults[i]), "default" + std::to_string(i));
    EXPECT_TRUE(same_records(absent, given)) << c.defaults[i];
  }
  Scene other = load_body(replace(c.plugin, "%P%", c.other), "other");
  EXPECT_FALSE(same_records(absent, other)) << c.other;
}

std::string flt(const std::string& name, const std::string& value) {
  return "<float name=\"" + name + "\" value=\"" + value + "\"/>";
}
std::string rgb(const std::string& name, const std::string& value) {
  return "<rgb name=\"" + name + "\" value=\"" + value + "\"/>";
}
std::string str(const std::string& name, const std::string& value) {
  return "<string name=\"" + name + "\" value=\"" + value + "\"/>";
}
std::string boolean(const std::string& name, bool value) {
  return "<boolean name=\"" + name + "\" value=\"" + (value ? "true" : "false") + "\"/>";
}
std::string bsdf(const std::string& type) { return "<bsdf type=\"" + type + "\">%P%</bsdf>"; }

// Cases shared by the three microfacet BSDFs.
void check_microfacet(const std::string& type) {
  check({type + " distribution",
         bsdf(type),
         {str("distribution", "beckmann"), str("distribution", "Beckmann")},
         str("distribution", "ggx")});
  check({type + " sample_visible",
         bsdf(type),
         {boolean("sample_visible", true)},
         boolean("sample_visible", false)});
  check({type + " alpha", bsdf(type), {flt("alpha", "0.1")}, flt("alpha", "0.2")});
}

TEST(PluginDefaults, Diffuse) {
  check({"reflectance",
         bsdf("diffuse"),
         {rgb("reflectance", "0.5"), flt("reflectance", "0.5"),
          "<spectrum name=\"reflectance\" value=\"0.5\"/>"},
         rgb("reflectance", "0.3")});
}

// Mitsuba 3.8 shape.cpp: a shape without a BSDF is diffuse of reflectance 0.5, a luminaire
// without one diffuse of reflectance 0.
TEST(PluginDefaults, ShapeWithoutBsdf) {
  const std::string grey = "<bsdf type=\"diffuse\"/>";
  const std::string black = "<bsdf type=\"diffuse\">" + rgb("reflectance", "0") + "</bsdf>";
  check({"shape", "<shape type=\"sphere\">%P%</shape>", {grey}, black});
  check({"luminaire", "<shape type=\"sphere\"><emitter type=\"area\"/>%P%</shape>", {black}, grey});
}

TEST(PluginDefaults, Conductors) {
  for (std::string type : {"conductor", "roughconductor"}) {
    check({type + " material", bsdf(type), {str("material", "none")}, str("material", "Au")});
    check({type + " eta", bsdf(type), {flt("eta", "0"), rgb("eta", "0")}, flt("eta", "0.5")});
    check({type + " k", bsdf(type), {flt("k", "1"), rgb("k", "1")}, flt("k", "2")});
    check({type + " specular_reflectance",
           bsdf(type),
           {flt("specular_reflectance", "1"), rgb("specular_reflectance", "1")},
           flt("specular_reflectance", "0.5")});
  }
  check_microfacet("roughconductor");
  // Mitsuba conductor.cpp: a named material excludes eta and k.
  expect_error("<bsdf type=\"conductor\">" + str("material", "Au") + flt("k", "2") + "</bsdf>",
               "give either a named 'material' or 'eta'/'k', not both");
  expect_error(
      "<bsdf type=\"roughconductor\">" + str("material", "Au") + flt("eta", "2") + "</bsdf>",
      "give either a named 'material' or 'eta'/'k', not both");
}

TEST(PluginDefaults, Dielectrics) {
  for (std::string type : {"dielectric", "roughdielectric", "thindielectric"}) {
    check({type + " int_ior",
           bsdf(type),
           {str("int_ior", "bk7"), str("int_ior", "BK7"), flt("int_ior", "1.5046")},
           str("int_ior", "water")});
    check({type + " ext_ior",
           bsdf(type),
           {str("ext_ior", "air"), flt("ext_ior", "1.000277")},
           flt("ext_ior", "1")});
    check({type + " specular_reflectance",
           bsdf(type),
           {flt("specular_reflectance", "1")},
           flt("specular_reflectance", "0.5")});
    check({type + " specular_transmittance",
           bsdf(type),
           {flt("specular_transmittance", "1")},
           flt("specular_transmittance", "0.5")});
  }
  check_microfacet("roughdielectric");
  expect_error("<bsdf type=\"dielectric\"><integer name=\"int_ior\" value=\"2\"/></bsdf>",
               "int_ior must be a <float> or an IOR name (Mitsuba refuses an <integer> here)");
}

TEST(PluginDefaults, Plastics) {
  for (std::string type : {"plastic", "roughplastic"}) {
    check({type + " int_ior",
           bsdf(type),
           {str("int_ior", "polypropylene"), flt("int_ior", "1.49")},
           str("int_ior", "bk7")});
    check({type + " ext_ior",
           bsdf(type),
           {str("ext_ior", "air"), flt("ext_ior", "1.000277")},
           str("ext_ior", "vacuum")});
    check({type + " diffuse_reflectance",
           bsdf(type),
           {rgb("diffuse_reflectance", "0.5")},
           rgb("diffuse_reflectance", "0.4")});
    check({type + " specular_reflectance",
           bsdf(type),
           {flt("specular_reflectance", "1")},
           flt("specular_reflectance", "0.8")});
    check({type + " nonlinear",
           bsdf(type),
           {boolean("nonlinear", false)},
           boolean("nonlinear", true)});
  }
  check_microfacet("roughplastic");
  // Mitsuba's MicrofacetDistribution(props) takes equal alpha_u and alpha_v as isotropic.
  check({"roughplastic alpha_u = alpha_v",
         bsdf("roughplastic"),
         {flt("alpha_u", "0.1") + flt("alpha_v", "0.1")},
         flt("alpha_u", "0.3") + flt("alpha_v", "0.3")});
  expect_error(
      "<bsdf type=\"roughplastic\">" + flt("alpha_u", "0.1") + flt("alpha_v", "0.2") + "</bsdf>",
      "anisotropic roughness (alpha_u != alpha_v) is not supported by roughplastic");
  expect_error("<bsdf type=\"roughplastic\">" + flt("alpha_u", "0.1") + "</bsdf>",
               "alpha_u and alpha_v must be given together");
  // Mitsuba roughplastic.cpp: the two indices must differ (plastic.cpp allows equal ones).
  expect_error(
      "<bsdf type=\"roughplastic\">" + flt("int_ior", "1.3") + flt("ext_ior", "1.3") + "</bsdf>",
      "int_ior and ext_ior must differ");
  load_body("<bsdf type=\"plastic\">" + flt("int_ior", "1.3") + flt("ext_ior", "1.3") + "</bsdf>",
            "equal");
}

// Mitsuba 3.8 pplastic.cpp: eta = int_ior / ext_ior unless `eta` is given, never both.
TEST(PluginDefaults, PolarizedPlastic) {
  const std::string p = bsdf("pplastic");
  check({"pplastic int_ior",
         p,
         {str("int_ior", "polypropylene"), flt("int_ior", "1.49")},
         str("int_ior", "bk7")});
  check({"pplastic ext_ior",
         p,
         {str("ext_ior", "air"), flt("ext_ior", "1.000277")},
         flt("ext_ior", "1.2")});
  check({"pplastic eta", p, {}, flt("eta", "1.7")});
  check({"pplastic diffuse_reflectance",
         p,
         {rgb("diffuse_reflectance", "0.5")},
         rgb("diffuse_reflectance", "0.4")});
  check({"pplastic specular_reflectance",
         p,
         {flt("specular_reflectance", "1")},
         flt("specular_reflectance", "0.8")});
  check_microfacet("pplastic");
  check({"pplastic alpha_u and alpha_v",
         p,
         {flt("alpha_u", "0.1") + flt("alpha_v", "0.1")},
         flt("alpha_u", "0.1") + flt("alpha_v", "0.3")});
  expect_error("<bsdf type=\"pplastic\">" + flt("eta", "1.5") + flt("int_ior", "1.5") + "</bsdf>",
               "give either eta or int_ior/ext_ior, not both");
  expect_error("<bsdf type=\"pplastic\">" + flt("eta", "1.5") + flt("ext_ior", "1.1") + "</bsdf>",
               "give either eta or int_ior/ext_ior, not both");
  expect_error(
      "<bsdf type=\"pplastic\">" + flt("int_ior", "1.3") + flt("ext_ior", "1.3") + "</bsdf>",
      "int_ior and ext_ior must differ");
  expect_error("<bsdf type=\"pplastic\">" + flt("alpha_v", "0.1") + "</bsdf>",
               "alpha_u and alpha_v must be given together");
}

TEST(PluginDefaults, Principled) {
  const std::string p = bsdf("principled");
  check({"base_color",
         p,
         {rgb("base_color", "0.5"), flt("base_color", "0.5")},
         rgb("base_color", "0.2")});
  check({"roughness", p, {flt("roughness", "0.5")}, flt("roughness", "0.2")});
  for (std::string name : {"metallic", "spec_tint", "anisotropic", "sheen", "sheen_tint",
                           "clearcoat", "clearcoat_gloss", "spec_trans", "flatness"})
    check({name, p, {flt(name, "0")}, flt(name, "0.3")});
  // eta = 2 / (1 - sqrt(0.08 specular)) - 1: specular 0.5 is eta 1.5.
  check({"specular", p, {flt("specular", "0.5"), flt("eta", "1.5")}, flt("specular", "0.3")});
  for (std::string name : {"diffuse_reflectance_sampling_rate", "main_specular_sampling_rate",
                           "clearcoat_sampling_rate"})
    check({name, p, {flt(name, "1")}, flt(name, "0.5")});
  // get_flag: a <float> spec_trans of 0 leaves the transmission lobe off, so eta = 1 stays 1;
  // an <integer> 0 turns it on, and eta = 1 becomes 1.001.
  Scene off = load_body(
      "<bsdf type=\"principled\">" + flt("spec_trans", "0") + flt("eta", "1") + "</bsdf>", "off");
  Scene on = load_body("<bsdf type=\"principled\"><integer name=\"spec_trans\" value=\"0\"/>" +
                           flt("eta", "1") + "</bsdf>",
                       "on");
  EXPECT_EQ(off.buffers.materials[0].eta, 1.0f);
  EXPECT_EQ(on.buffers.materials[0].eta, 1.001f);
}

TEST(PluginDefaults, TwosidedAndMask) {
  check({"mask opacity",
         "<bsdf type=\"mask\">%P%<bsdf type=\"diffuse\"/></bsdf>",
         {flt("opacity", "0.5"), rgb("opacity", "0.5")},
         flt("opacity", "0.7")});
  Scene absent = load_body("<bsdf type=\"twosided\"><bsdf type=\"diffuse\"/></bsdf>", "absent");
  Scene given = load_body("<bsdf type=\"twosided\">" + boolean("allow_transmission", false) +
                              "<bsdf type=\"diffuse\"/></bsdf>",
                          "given");
  EXPECT_TRUE(same_records(absent, given));
  // Mitsuba 3.8 twosided.cpp: allow_transmission is false by default, and a nested BSDF with
  // transmission or null lobes needs it.
  for (std::string inner : std::vector<std::string>{
           "<bsdf type=\"dielectric\"/>", "<bsdf type=\"roughdielectric\"/>",
           "<bsdf type=\"thindielectric\"/>", "<bsdf type=\"mask\"><bsdf type=\"diffuse\"/></bsdf>",
           "<bsdf type=\"principled\">" + flt("spec_trans", "0.5") + "</bsdf>"}) {
    expect_error("<bsdf type=\"twosided\">" + inner + "</bsdf>",
                 "transmits light; Mitsuba accepts it only with allow_transmission = true");
    load_body("<bsdf type=\"twosided\">" + boolean("allow_transmission", true) + inner + "</bsdf>",
              "allowed");
  }
  load_body("<bsdf type=\"twosided\"><bsdf type=\"principled\">" + flt("spec_trans", "0") +
                "</bsdf></bsdf>",
            "no_transmission");
  // twosided(twosided(x)) behaves as twosided(x) (the inner one sees wi on the front side).
  Scene once = load_body("<bsdf type=\"twosided\"><bsdf type=\"diffuse\"/></bsdf>", "once");
  Scene twice = load_body(
      "<bsdf type=\"twosided\"><bsdf type=\"twosided\"><bsdf type=\"diffuse\"/></bsdf></bsdf>",
      "twice");
  EXPECT_TRUE(same_records(once, twice));
}

std::string bitmap(const std::string& file) {
  return "<bsdf type=\"diffuse\"><texture type=\"bitmap\" name=\"reflectance\">" +
         str("filename", file) + "%P%</texture></bsdf>";
}

TEST(PluginDefaults, Bitmap) {
  for (std::string file : {"image.png", "image.exr"}) {
    check({file + " filter_type",
           bitmap(file),
           {str("filter_type", "bilinear")},
           str("filter_type", "nearest")});
    check({file + " wrap_mode",
           bitmap(file),
           {str("wrap_mode", "repeat")},
           str("wrap_mode", "clamp")});
    // accel (a CUDA texture-unit hint) changes nothing; the other value shows the comparison
    // can fail.
    check({file + " accel",
           bitmap(file),
           {boolean("accel", true), boolean("accel", false)},
           str("wrap_mode", "mirror")});
    check({file + " to_uv",
           bitmap(file),
           {"<transform name=\"to_uv\"><scale value=\"1\"/></transform>"},
           "<transform name=\"to_uv\"><scale value=\"2\"/></transform>"});
  }
  check({"raw", bitmap("image.png"), {boolean("raw", false)}, boolean("raw", true)});
  // format "auto": half precision for sources of at most 16 bits per channel, else float.
  check({"png format",
         bitmap("image.png"),
         {str("format", "auto"), str("format", "fp16")},
         str("format", "variant")});
  check({"exr format",
         bitmap("image.exr"),
         {str("format", "auto"), str("format", "variant")},
         str("format", "fp16")});
  Scene png = load_body(replace(bitmap("image.png"), "%P%", ""), "png");
  for (const vec4& t : png.buffers.texels)
    for (int c = 0; c < 3; ++c) EXPECT_EQ(t[c], float(Imath::half(t[c])));
  expect_error(replace(bitmap("image.png"), "%P%", str("format", "fp32")),
               "format \"fp32\" must be auto, variant or fp16");
}

TEST(PluginDefaults, BitmapSizes) {
  std::filesystem::path dir = fresh_dir();
  for (auto [w, h] : {std::pair{1, 1}, std::pair{1, 2}, std::pair{3, 1}}) {
    std::string name = std::to_string(w) + "x" + std::to_string(h) + ".exr";
    std::vector<float> px(size_t(w) * h * 3, 0.25f);
    auto out = OIIO::ImageOutput::create((dir / name).string());
    ASSERT_TRUE(out->open((dir / name).string(), OIIO::ImageSpec(w, h, 3, OIIO::TypeDesc::FLOAT)));
    ASSERT_TRUE(out->write_image(OIIO::TypeDesc::FLOAT, px.data()));
    out->close();
    std::string xml = write_file(dir, name + ".xml", scene_xml(replace(bitmap(name), "%P%", "")));
    if (w == 1 && h == 1) {
      EXPECT_NO_THROW(load_scene(xml, {}));
      continue;
    }
    try {
      load_scene(xml, {});
      ADD_FAILURE() << name << " loaded";
    } catch (const SceneError& e) {
      EXPECT_NE(std::string(e.what()).find("Mitsuba resamples bitmaps smaller than 2x2"),
                std::string::npos)
          << e.what();
    }
  }
}

// Mitsuba's plastic specular sampling weight s_mean / (d_mean + s_mean) uses the bitmap's
// mean luminance (BitmapTextureImpl::rebuild_internals), not its mean channel value.
TEST(PluginDefaults, PlasticWeightUsesMeanLuminance) {
  Scene s =
      load_body("<bsdf type=\"plastic\"><texture type=\"bitmap\" name=\"diffuse_reflectance\">" +
                    str("filename", "image.png") + "</texture></bsdf>",
                "plastic");
  const SceneBuffers& b = s.buffers;
  const Texture& t = b.textures[b.materials[0].param[PLASTIC_DIFFUSE_REFLECTANCE].texture];
  double lum = 0.0;
  for (uint i = 0; i < t.width * t.height; ++i) {
    vec4 c = b.texels[t.texel_offset + i];
    lum += (0.212671 * c.x + 0.715160 * c.y + 0.072169 * c.z) / (t.width * t.height);
  }
  EXPECT_NEAR(b.materials[0].extra, 1.0 / (lum + 1.0), 1e-6);
}

TEST(PluginDefaults, Checkerboard) {
  const std::string c =
      "<bsdf type=\"diffuse\"><texture type=\"checkerboard\" name=\"reflectance\">"
      "%P%</texture></bsdf>";
  check({"color0", c, {rgb("color0", "0.4"), flt("color0", "0.4")}, rgb("color0", "0.2")});
  check({"color1", c, {rgb("color1", "0.2"), flt("color1", "0.2")}, rgb("color1", "0.4")});
  check({"to_uv",
         c,
         {"<transform name=\"to_uv\"><translate x=\"0\"/></transform>"},
         "<transform name=\"to_uv\"><translate x=\"0.5\"/></transform>"});
  expect_error(replace(c, "%P%", "<texture type=\"checkerboard\" name=\"color0\"/>"),
               "a nested texture as 'color0' is not supported by twinray");
}

TEST(PluginDefaults, Emitters) {
  check({"constant radiance",
         "<emitter type=\"constant\">%P%</emitter>",
         {rgb("radiance", "1"), flt("radiance", "1"), "<integer name=\"radiance\" value=\"1\"/>"},
         "<spectrum name=\"radiance\" value=\"1\"/>"});
  check({"constant to_world",
         "<emitter type=\"constant\">%P%</emitter>",
         {"<transform name=\"to_world\"><rotate y=\"1\" angle=\"30\"/></transform>"},
         rgb("radiance", "2")});
  check({"point intensity",
         "<emitter type=\"point\">%P%</emitter>",
         {rgb("intensity", "1"), flt("intensity", "1")},
         flt("intensity", "2")});
  check({"point position",
         "<emitter type=\"point\">%P%</emitter>",
         {"<point name=\"position\" value=\"0, 0, 0\"/>",
          "<vector name=\"position\" value=\"0, 0, 0\"/>",
          "<transform name=\"to_world\"><rotate y=\"1\" angle=\"30\"/></transform>"},
         "<vector name=\"position\" value=\"0, 1, 0\"/>"});
  check({"directional irradiance",
         "<emitter type=\"directional\">%P%</emitter>",
         {rgb("irradiance", "1"), flt("irradiance", "1")},
         flt("irradiance", "3")});
  check({"directional direction",
         "<emitter type=\"directional\">%P%</emitter>",
         {"<vector name=\"direction\" value=\"0, 0, 1\"/>",
          "<point name=\"direction\" value=\"0, 0, 2\"/>"},
         "<vector name=\"direction\" value=\"0, 1, 0\"/>"});
  const std::string env =
      "<emitter type=\"envmap\">" + str("filename", "image.exr") + "%P%</emitter>";
  check({"envmap scale", env, {flt("scale", "1")}, flt("scale", "2")});
  check({"envmap mis_compensation", env, {boolean("mis_compensation", false)}, flt("scale", "3")});
  check({"envmap to_world",
         env,
         {"<transform name=\"to_world\"><scale value=\"1\"/></transform>"},
         "<transform name=\"to_world\"><rotate y=\"1\" angle=\"30\"/></transform>"});
  for (std::string type : {"constant", "point", "directional"})
    check({type + " sampling_weight",
           "<emitter type=\"" + type + "\">%P%</emitter><emitter type=\"point\"/>",
           {flt("sampling_weight", "1")},
           flt("sampling_weight", "2")});
  check({"area radiance",
         "<shape type=\"sphere\"><emitter type=\"area\">%P%</emitter></shape>",
         {rgb("radiance", "1"), flt("radiance", "1")},
         flt("radiance", "4")});
  check({"area sampling_weight",
         "<shape type=\"sphere\"><emitter type=\"area\">%P%</emitter></shape>"
         "<emitter type=\"point\"/>",
         {flt("sampling_weight", "1")},
         flt("sampling_weight", "2")});
  expect_error("<emitter type=\"envmap\">" + str("filename", "image.png") + "</emitter>",
               "is 2x2 pixels; an environment map must be at least 2x3");
}

// Mitsuba 3.8 Properties::get_texture_impl: an absent emissive spectrum is the uniform value 1,
// i.e. RGB (1, 1, 1) in scalar_rgb; a <spectrum> of value 1 is the colour of an equal-energy
// spectrum instead.
TEST(PluginDefaults, ConstantRadianceIsOne) {
  Scene s = load_body("<emitter type=\"constant\"/>", "constant");
  ASSERT_EQ(s.buffers.emitters.size(), 1u);
  EXPECT_EQ(s.buffers.emitters[0].radiance, vec3(1.0f));
  for (std::string type : {"point", "directional"}) {
    s = load_body("<emitter type=\"" + type + "\"/>", type);
    EXPECT_EQ(s.buffers.emitters[0].radiance, vec3(1.0f)) << type;
  }
  s = load_body("<shape type=\"sphere\"><emitter type=\"area\"/></shape>", "area");
  EXPECT_EQ(s.buffers.emitters[0].radiance, vec3(1.0f));
}

// Shape parameters Mitsuba's Shape and Mesh bases read for every shape (shape.cpp, mesh.cpp),
// and the unbounded microfacet alphas (roughconductor.cpp get_unbounded_texture).
namespace shapes {

Scene load_shape(const std::string& shape) {
  return load_scene(write_file(fresh_dir(), "scene.xml", scene_xml(shape)), {});
}

TEST(PluginDefaults, ShapeBaseParameters) {
  Scene a = load_shape("<shape type=\"sphere\"><point name=\"center\" value=\"1 2 3\"/></shape>");
  Scene b = load_shape("<shape type=\"sphere\"><vector name=\"center\" value=\"1 2 3\"/></shape>");
  EXPECT_TRUE(same_bytes(a.buffers.shapes, b.buffers.shapes));
  Scene c = load_shape(
      "<shape type=\"sphere\"><float name=\"silhouette_sampling_weight\" value=\"3\"/></shape>");
  Scene d = load_shape("<shape type=\"sphere\"/>");
  EXPECT_TRUE(same_bytes(c.buffers.shapes, d.buffers.shapes));
  // A rectangle with face normals is shaded flat: no vertex normals.
  Scene flat = load_shape(
      "<shape type=\"rectangle\"><boolean name=\"face_normals\" value=\"true\"/></shape>");
  Scene smooth = load_shape("<shape type=\"rectangle\"/>");
  EXPECT_EQ(flat.buffers.shapes[0].flags & SHAPE_HAS_NORMALS, 0u);
  EXPECT_NE(smooth.buffers.shapes[0].flags & SHAPE_HAS_NORMALS, 0u);
  expect_error(
      "<shape type=\"sphere\"><emitter type=\"area\"><transform name=\"to_world\"><translate "
      "x=\"1\"/></transform></emitter></shape>",
      "an area emitter takes its shape's transform");
}

TEST(PluginDefaults, MicrofacetAlphaIsUnbounded) {
  Scene s = load_shape(
      "<shape type=\"sphere\"><bsdf type=\"roughconductor\"><rgb name=\"alpha\" value=\"1.5\"/>"
      "</bsdf></shape>");
  EXPECT_EQ(s.buffers.materials.size(), 1u);
  expect_error(
      "<shape type=\"sphere\"><bsdf type=\"diffuse\"><rgb name=\"reflectance\" value=\"1.5\"/>"
      "</bsdf></shape>",
      "must lie in [0, 1]");
}

// Mitsuba's Integrator/SamplingIntegrator bases (integrator.cpp): timeout -1, block_size 0,
// samples_per_pass unset; tiling and passes do not change twinray's estimate.
TEST(PluginDefaults, IntegratorBaseParameters) {
  const std::string plain = "<integrator type=\"path\"/>";
  Scene a = load_shape(plain);
  for (const std::string& p :
       {flt("timeout", "-1"), std::string("<integer name=\"block_size\" value=\"32\"/>"),
        std::string("<integer name=\"samples_per_pass\" value=\"4\"/>")}) {
    Scene b = load_shape("<integrator type=\"path\">" + p + "</integrator>");
    EXPECT_EQ(std::memcmp(&a.buffers.globals.integrator, &b.buffers.globals.integrator,
                          sizeof(Integrator)),
              0)
        << p;
  }
  Scene m = load_shape(
      "<integrator type=\"moment\"><integer name=\"block_size\" value=\"16\"/>"
      "<integrator type=\"path\"/></integrator>");
  EXPECT_EQ(m.integrator_name, "moment(path)");
  expect_error("<integrator type=\"path\">" + flt("timeout", "10") + "</integrator>",
               "a timeout would stop the render early");
  expect_error(
      "<integrator type=\"moment\"><integrator type=\"path\"/><integrator "
      "type=\"direct\"/></integrator>",
      "must wrap exactly one integrator");
}

// The twinray extension min_depth of path: 1 (every path length counts, as Mitsuba); with
// max_depth 0 (nothing rendered) the default is still accepted.
TEST(PluginDefaults, PathMinDepth) {
  EXPECT_EQ(load_shape("<integrator type=\"path\"/>").buffers.globals.integrator.min_depth, 1);
  EXPECT_EQ(load_shape("<integrator type=\"path\"><integer name=\"max_depth\" value=\"0\"/>"
                       "</integrator>")
                .buffers.globals.integrator.min_depth,
            1);
  EXPECT_EQ(load_shape("<integrator type=\"path\"><integer name=\"min_depth\" value=\"3\"/>"
                       "</integrator>")
                .buffers.globals.integrator.min_depth,
            3);
}

// pbrt-v4's ambientocclusion (AOIntegrator::Create): cossample true, maxdistance Infinity.
TEST(PluginDefaults, AmbientOcclusion) {
  Scene a = load_shape("<integrator type=\"ambientocclusion\"/>");
  const Integrator& it = a.buffers.globals.integrator;
  EXPECT_EQ(it.type, INTEGRATOR_AMBIENT_OCCLUSION);
  EXPECT_EQ(it.cos_sample, 1u);
  EXPECT_EQ(it.max_distance, FLOAT_MAX);
  EXPECT_EQ(a.integrator_name, "ambientocclusion");
  Scene b = load_shape(
      "<integrator type=\"ambientocclusion\"><boolean name=\"cossample\" value=\"false\"/>" +
      flt("maxdistance", "2.5") + "</integrator>");
  EXPECT_EQ(b.buffers.globals.integrator.cos_sample, 0u);
  EXPECT_EQ(b.buffers.globals.integrator.max_distance, 2.5f);
  Scene m = load_shape(
      "<integrator type=\"moment\"><integrator type=\"ambientocclusion\"/></integrator>");
  EXPECT_EQ(m.integrator_name, "moment(ambientocclusion)");
}

}  // namespace shapes

}  // namespace
}  // namespace tr
