// The validate and converge verbs end to end through twinray_harness_cli: exit status, the
// JSON summary, the HTML report (rendered in headless Chromium when it is installed), the
// convergence CSV/SVG and time-to-error table; and the suite-file parser.
#include <gtest/gtest.h>
#include <unistd.h>

#include <array>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <memory>
#include <sstream>

#include "validation/harness/suite.h"

namespace tr {
namespace {

namespace fs = std::filesystem;

fs::path scratch(const std::string& name) {
  fs::path dir = fs::temp_directory_path() / ("twinray_harness_" + std::to_string(getpid())) / name;
  fs::remove_all(dir);
  fs::create_directories(dir);
  return dir;
}

std::string slurp(const fs::path& p) {
  std::ifstream in(p);
  std::stringstream s;
  s << in.rdbuf();
  return s.str();
}

// Runs a command; returns its exit status and appends its standard output to *out.
int run(const std::string& command, std::string* out) {
  std::unique_ptr<FILE, int (*)(FILE*)> pipe(popen(command.c_str(), "r"), pclose);
  if (!pipe) return -1;
  std::array<char, 4096> buf;
  while (size_t n = fread(buf.data(), 1, buf.size(), pipe.get())) out->append(buf.data(), n);
  int status = pclose(pipe.release());
  return WIFEXITED(status) ? WEXITSTATUS(status) : -1;
}

std::string cli() { return TWINRAY_HARNESS_CLI; }

size_t count(const std::string& s, const std::string& what) {
  size_t n = 0;
  for (size_t at = s.find(what); at != std::string::npos; at = s.find(what, at + 1)) ++n;
  return n;
}

TEST(Suite, ParsesFieldsDefaultsAndRelativePaths) {
  fs::path dir = scratch("suite");
  std::ofstream(dir / "a.suite")
      << "# comment\n\n"
         "name=one scene=s/one.xml reference=r/one.exr reference_spp=32000 seed=7 "
         "define=spp=4\n"
         "  name=two scene=/abs/two.xml reference=two.exr variance=v.exr reference_spp=100 "
         "spp=12\n";
  std::vector<SuiteEntry> s = read_suite((dir / "a.suite").string());
  ASSERT_EQ(s.size(), 2u);
  EXPECT_EQ(s[0].scene, (dir / "s/one.xml").string());
  EXPECT_EQ(s[0].variance, (dir / "r/one_var.exr").string());
  EXPECT_EQ(s[0].spp, 0u);
  EXPECT_EQ(s[0].seed, std::optional<std::uint32_t>(7u));
  EXPECT_EQ(s[0].defines.at("spp"), "4");
  EXPECT_EQ(s[1].scene, "/abs/two.xml");
  EXPECT_EQ(s[1].variance, (dir / "v.exr").string());
  EXPECT_EQ(s[1].spp, 12u);
  EXPECT_EQ(s[1].reference_spp, 100.0);
  EXPECT_EQ(acceptance_spp(48, 48), 868u);
}

TEST(Suite, RejectsMalformedLinesWithTheirLineNumber) {
  fs::path dir = scratch("bad_suite");
  const char* bad[] = {"name=a scene=s reference=r",                              // no spp
                       "name=a scene=s reference=r reference_spp=10 colour=red",  // unknown key
                       "name=a scene=s reference=r reference_spp=10 seed=-1",
                       "name=a b scene=s reference=r reference_spp=10",
                       "name=a scene=s reference=r reference_spp=10\nname=a scene=t "
                       "reference=r reference_spp=10"};
  for (const char* text : bad) {
    std::ofstream(dir / "bad.suite") << "# header\n" << text << "\n";
    try {
      read_suite((dir / "bad.suite").string());
      ADD_FAILURE() << "accepted: " << text;
    } catch (const SuiteError& e) {
      EXPECT_NE(std::string(e.what()).find("bad.suite:"), std::string::npos) << e.what();
    }
  }
}

TEST(ValidateCommand, QuickSuiteOnTheCpuWritesAReportThatRendersWithEveryVerdict) {
  fs::path dir = scratch("validate");
  std::string out;
  int status = run(cli() + " validate " + TWINRAY_QUICK_SUITE + " --out " + dir.string(), &out);
  std::printf("%s", out.c_str());
  EXPECT_EQ(status, 0);
  std::string json = slurp(dir / "summary.json");
  EXPECT_NE(json.find("\"passed\": true"), std::string::npos) << json.substr(0, 300);
  EXPECT_NE(json.find("\"name\": \"directional\""), std::string::npos);
  EXPECT_NE(json.find("\"name\": \"textured_diffuse\""), std::string::npos);
  // Per scene: CPU render and reference, and the comparison's two heatmaps.
  ASSERT_TRUE(fs::exists(dir / "report.html"));
#ifndef TWINRAY_CHROMIUM
  FAIL() << "chromium was not found when the build was configured";
#else
  std::string dom;
  run(std::string(TWINRAY_CHROMIUM) + " --headless --no-sandbox --disable-gpu --dump-dom file://" +
          (dir / "report.html").string() + " 2>/dev/null",
      &dom);
  EXPECT_NE(dom.find("data-images-decoded=\"8/8\""), std::string::npos) << dom.substr(0, 400);
  EXPECT_NE(dom.find("2 of 2 scenes pass."), std::string::npos);
  EXPECT_NE(dom.find("id=\"scene-0\" data-verdict=\"pass\""), std::string::npos);
  EXPECT_NE(dom.find("id=\"scene-1\" data-verdict=\"pass\""), std::string::npos);
#endif
}

TEST(ValidateCommand, FailsWithExitOneWhenASceneFailsAndStillWritesTheReport) {
  // A suite whose reference is a different scene's: the render must fail against it, its
  // confirmation render too.
  fs::path dir = scratch("validate_fail");
  fs::path scenes = fs::path(TWINRAY_QUICK_SUITE).parent_path() / "../mitsuba/tests/scenes";
  std::ofstream(dir / "wrong.suite")
      << "name=wrong scene=" << (scenes / "floating_sphere/test_directional_direct.xml").string()
      << " reference=" << (scenes / "bsdf_spheres/refs/test_pointlight_ref_rgb.exr").string()
      << " reference_spp=32000 spp=16\n"
      << "name=missing scene=" << (dir / "missing.xml").string()
      << " reference=" << (scenes / "bsdf_spheres/refs/test_pointlight_ref_rgb.exr").string()
      << " reference_spp=32000 spp=16\n";
  std::string out;
  int status = run(cli() + " validate " + (dir / "wrong.suite").string() + " --out " +
                       (dir / "out").string() + " 2>&1",
                   &out);
  std::printf("%s", out.c_str());
  EXPECT_EQ(status, 1);
  EXPECT_NE(out.find("wrong: FAIL"), std::string::npos);
  // Its failure was judged again by a confirmation render (4 x 16 spp), which failed too.
  EXPECT_NE(out.find("CPU vs Mitsuba reference: confirmation, seed"), std::string::npos);
  EXPECT_NE(out.find("64 spp: FAIL"), std::string::npos);
  EXPECT_NE(out.find("missing: FAIL"), std::string::npos);
  std::string json = slurp(dir / "out/summary.json");
  size_t top_verdict = json.find("\"passed\": false");
  EXPECT_LT(top_verdict, json.find("\"scenes\"")) << json.substr(0, 300);
  EXPECT_NE(json.find("scene file not found"), std::string::npos);
  EXPECT_TRUE(fs::exists(dir / "out/report.html"));
  EXPECT_EQ(run(cli() + " validate " + (dir / "nonexistent.suite").string() + " 2>&1", &out), 2);
}

TEST(ConvergeCommand, TinyBudgetWritesCsvPlotAndTimeToError) {
  fs::path dir = scratch("converge");
  fs::path scenes = fs::path(TWINRAY_QUICK_SUITE).parent_path() / "../mitsuba/tests/scenes";
  std::string out;
  int status =
      run(cli() + " converge " + (scenes / "floating_sphere/test_directional_direct.xml").string() +
              " --reference " +
              (scenes / "floating_sphere/refs/test_directional_ref_rgb.exr").string() +
              " --budget 2 --max-spp 64 --variant label=direct" +
              " --variant integrator=path,max_depth=1,label=path-depth-1" +
              " --variant sampler=stratified,label=stratified" + " --targets 0.05,1e-9 --out " +
              dir.string(),
          &out);
  std::printf("%s", out.c_str());
  ASSERT_EQ(status, 0);
  std::string csv = slurp(dir / "convergence.csv");
  EXPECT_EQ(
      csv.rfind(
          "series,seconds,spp,rmse,relmse,relmse_stderr,renders,estimated_relmse,seed_relmse\n", 0),
      0u)
      << csv;
  EXPECT_GE(count(csv, "\ndirect (cpu),"), 2u) << csv;
  EXPECT_GE(count(csv, "\npath-depth-1 (cpu),"), 2u) << csv;
  // Each rung's sample_count is its spp, rounded as the sampler rounds it: squares.
  std::istringstream lines(csv);
  int stratified_rungs = 0;
  for (std::string line; std::getline(lines, line);) {
    if (line.rfind("stratified (cpu),", 0) != 0) continue;
    ++stratified_rungs;
    std::istringstream fields(line.substr(line.find(',') + 1));
    double seconds = 0.0, spp = 0.0;
    char comma = 0;
    fields >> seconds >> comma >> spp;
    const double root = std::round(std::sqrt(spp));
    EXPECT_EQ(root * root, spp) << line;
  }
  EXPECT_GE(stratified_rungs, 2) << csv;
  EXPECT_NE(slurp(dir / "convergence.svg").find("<svg"), std::string::npos);
  std::string tte = slurp(dir / "time_to_error.csv");
  EXPECT_EQ(tte.rfind("series,metric,target,seconds\n", 0), 0u);
  // max_depth 1 sees emitters only: this scene's image is black, its relMSE stays near 0.088.
  EXPECT_NE(tte.find("direct (cpu),relmse,0.05,0."), std::string::npos) << tte;
  EXPECT_NE(tte.find("path-depth-1 (cpu),relmse,0.05,\n"), std::string::npos) << tte;
  EXPECT_NE(tte.find("direct (cpu),relmse,1e-09,\n"), std::string::npos) << tte;
  EXPECT_NE(out.find("relMSE 1e-09 not reached"), std::string::npos);
  // Usage errors.
  EXPECT_EQ(run(cli() + " converge x.xml --budget 1 2>&1", &out), 2);  // no --reference
  EXPECT_EQ(
      run(cli() + " converge x.xml --reference y.exr --budget 1 --variant depth=3 2>&1", &out), 2);
  EXPECT_EQ(
      run(cli() + " converge x.xml --reference y.exr --budget 1 --variant sampler=xy 2>&1", &out),
      2);
  EXPECT_NE(out.find("unknown sampler 'xy'"), std::string::npos) << out;
}

// --repeats: each rung is the mean of that many renders (distinct seeds) and carries the
// standard error of its relMSE.
TEST(ConvergeCommand, RepeatsGiveErrorBars) {
  fs::path dir = scratch("converge_repeats");
  fs::path scenes = fs::path(TWINRAY_QUICK_SUITE).parent_path() / "../mitsuba/tests/scenes";
  std::string out;
  ASSERT_EQ(
      run(cli() + " converge " + (scenes / "floating_sphere/test_directional_direct.xml").string() +
              " --reference " +
              (scenes / "floating_sphere/refs/test_directional_ref_rgb.exr").string() +
              " --budget 5 --max-spp 4 --repeats 3 --variant sampler=zsobol,label=z --out " +
              dir.string(),
          &out),
      0)
      << out;
  std::istringstream lines(slurp(dir / "convergence.csv"));
  std::string line;
  std::getline(lines, line);
  int rungs = 0;
  for (; std::getline(lines, line); ++rungs) {
    ASSERT_EQ(line.rfind("z (cpu),", 0), 0u) << line;
    std::istringstream fields(line.substr(line.find(',') + 1));
    std::vector<double> v;
    for (std::string f; std::getline(fields, f, ',');) v.push_back(std::stod(f));
    // seconds, spp, rmse, relmse, relmse_stderr, renders, estimated_relmse, seed_relmse
    ASSERT_EQ(v.size(), 8u) << line;
    EXPECT_EQ(v[1], double(1 << rungs)) << line;
    EXPECT_GT(v[4], 0.0) << "three renders of distinct seeds differ: " << line;
    EXPECT_LT(v[4], v[3]) << line;
    EXPECT_EQ(v[5], 3.0) << line;
    if (v[1] >= 2.0) {
      EXPECT_GT(v[6], 0.0) << "the renders' own estimate: " << line;
    }
    EXPECT_GT(v[7], 0.0) << "the spread among them: " << line;
  }
  EXPECT_EQ(rungs, 3);  // 1, 2 and 4 spp
}

}  // namespace
}  // namespace tr
