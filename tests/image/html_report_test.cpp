// The HTML report: base64 embedding, and a headless Chromium run proving the page renders,
// decodes every embedded image and shows each scene's verdict.
#include "validation/image/html_report.h"

#include <gtest/gtest.h>
#include <unistd.h>

#include <array>
#include <cstdio>
#include <filesystem>
#include <memory>

#include "io/heatmap.h"
#include "io/image.h"
#include "synthetic.h"

namespace tr {
namespace {

namespace fs = std::filesystem;

TEST(HtmlReport, Base64MatchesRfc4648TestVectors) {
  // RFC 4648 §10.
  EXPECT_EQ(base64_encode(""), "");
  EXPECT_EQ(base64_encode("f"), "Zg==");
  EXPECT_EQ(base64_encode("fo"), "Zm8=");
  EXPECT_EQ(base64_encode("foo"), "Zm9v");
  EXPECT_EQ(base64_encode("foob"), "Zm9vYg==");
  EXPECT_EQ(base64_encode("fooba"), "Zm9vYmE=");
  EXPECT_EQ(base64_encode("foobar"), "Zm9vYmFy");
  EXPECT_EQ(base64_encode(std::string("\xff\x00\x80", 3)), "/wCA");
}

void write_preview(const std::string& path, const RgbImage& rgb) {
  Image img;
  img.width = rgb.width;
  img.height = rgb.height;
  img.channels = 3;
  img.pixels.assign(rgb.rgb.begin(), rgb.rgb.end());
  write_png_srgb(path, img);
}

std::string run_command(const std::string& command) {
  std::unique_ptr<FILE, int (*)(FILE*)> pipe(popen(command.c_str(), "r"), pclose);
  if (!pipe) return "";
  std::string out;
  std::array<char, 4096> buf;
  while (size_t n = fread(buf.data(), 1, buf.size(), pipe.get())) out.append(buf.data(), n);
  return out;
}

TEST(HtmlReport, RendersInHeadlessChromiumWithEveryVerdict) {
  fs::path dir = fs::temp_directory_path() / ("twinray_report_" + std::to_string(getpid()));
  fs::create_directories(dir);
  RgbImage ref = read_rgb(testing::arealight_refs() + ".exr");
  RgbImage var = read_rgb(testing::arealight_refs() + "_var.exr");

  std::vector<ReportScene> scenes;
  for (double scale : {1.0, 1.02}) {
    CompareInputs in;
    in.test = testing::noisy_render(ref, var, 868.0, 1);
    for (double& v : in.test.rgb) v *= scale;
    in.reference = ref;
    in.reference_variance = var;
    in.test_spp = 868.0;
    in.reference_spp = 32000.0;
    ReportScene s;
    s.name = scale == 1.0 ? "unbiased <render>" : "scaled by 1.02";
    std::string tag = scale == 1.0 ? "unbiased" : "scaled";
    ReportComparison c;
    c.title = "render vs Mitsuba reference";
    c.report = compare_images(in);
    s.passed = c.report.passed;
    std::string render_png = (dir / (tag + ".png")).string(), ref_png = (dir / "ref.png").string();
    std::string heat_png = (dir / (tag + "_flip.png")).string();
    write_preview(render_png, in.test);
    write_preview(ref_png, ref);
    write_heatmap_png(heat_png, ref.width, ref.height, c.report.flip.map, 0.0f, 1.0f);
    s.images = {{"render", render_png}, {"reference", ref_png}};
    c.heatmaps = {{"LDR-FLIP", heat_png}};
    s.facts = {{"spp", "868"}};
    s.comparisons.push_back(c);
    scenes.push_back(s);
  }
  ASSERT_TRUE(scenes[0].passed);
  ASSERT_FALSE(scenes[1].passed);
  std::string html_path = (dir / "report.html").string();
  write_text_file(html_path, html_report("twinray validation", scenes));

#ifndef TWINRAY_CHROMIUM
  FAIL() << "chromium was not found when the build was configured";
#else
  std::string dom = run_command(std::string(TWINRAY_CHROMIUM) +
                                " --headless --no-sandbox --disable-gpu --dump-dom file://" +
                                html_path + " 2>/dev/null");
  EXPECT_NE(dom.find("data-images-decoded=\"6/6\""), std::string::npos) << dom.substr(0, 400);
  EXPECT_NE(dom.find("1 of 2 scenes pass."), std::string::npos);
  EXPECT_NE(dom.find("id=\"scene-0\" data-verdict=\"pass\""), std::string::npos);
  EXPECT_NE(dom.find("id=\"scene-1\" data-verdict=\"fail\""), std::string::npos);
  EXPECT_NE(dom.find("unbiased &lt;render&gt;"), std::string::npos);  // names are escaped
#endif
  fs::remove_all(dir);
}

}  // namespace
}  // namespace tr
