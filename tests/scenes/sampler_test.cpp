// The sampler element of scenes/build_sensor.cpp: Mitsuba 3.8's stratified, ldsampler and
// multijitter with their parameters (`jitter` defaults to true; ldsampler has none), their
// sample_count rounding, and file:line errors.
#include <gtest/gtest.h>

#include <algorithm>

#include "scene_test_files.h"

namespace tr {
namespace {

using namespace testing_files;

std::string sensor_with(const std::string& sampler) {
  return "<scene version=\"3.0.0\">\n<sensor type=\"perspective\">\n" + sampler +
         "\n</sensor>\n</scene>\n";
}

Scene load_sampler(const std::string& sampler) {
  return load_scene(write_file(fresh_dir(), "scene.xml", sensor_with(sampler)), {});
}

TEST(SamplerElement, ParametersAndRounding) {
  Scene s = load_sampler(
      "<sampler type=\"stratified\"><integer name=\"sample_count\" value=\"10\"/>"
      "<integer name=\"seed\" value=\"3\"/></sampler>");
  EXPECT_EQ(s.buffers.globals.sampler_params.type, SAMPLER_STRATIFIED);
  EXPECT_EQ(s.buffers.globals.sampler_params.sample_count, 16u);
  EXPECT_EQ(s.buffers.globals.sampler_params.resolution, uvec2(4u));
  EXPECT_EQ(s.buffers.globals.sampler_params.jitter, 1u);
  EXPECT_EQ(s.spp, 16u);
  EXPECT_EQ(s.seed, 3u);
  EXPECT_EQ(s.sample_count_note, "stratified: sample_count 10 rounded up to 16, as Mitsuba");

  s = load_sampler(
      "<sampler type=\"multijitter\"><boolean name=\"jitter\" value=\"false\"/></sampler>");
  EXPECT_EQ(s.buffers.globals.sampler_params.type, SAMPLER_MULTIJITTER);
  EXPECT_EQ(s.spp, 4u);  // Mitsuba's default sample_count
  EXPECT_EQ(s.buffers.globals.sampler_params.jitter, 0u);
  EXPECT_EQ(s.sample_count_note, "");

  s = load_sampler(
      "<sampler type=\"ldsampler\"><integer name=\"sample_count\" value=\"20\"/></sampler>");
  EXPECT_EQ(s.buffers.globals.sampler_params.type, SAMPLER_LDSAMPLER);
  EXPECT_EQ(s.spp, 64u);
  EXPECT_EQ(s.sample_count_note, "ldsampler: sample_count 20 rounded up to 64, as Mitsuba");

  s = load_sampler(
      "<sampler type=\"independent\"><integer name=\"sample_count\" value=\"10\"/></sampler>");
  EXPECT_EQ(s.buffers.globals.sampler_params.type, SAMPLER_INDEPENDENT);
  EXPECT_EQ(s.spp, 10u);
}

void expect_sampler_error(const std::string& sampler, const std::string& words) {
  std::string xml = sensor_with(sampler);
  std::string path = write_file(fresh_dir(), "scene.xml", xml);
  try {
    load_scene(path, {});
    ADD_FAILURE() << "no SceneError for:\n" << xml;
  } catch (const SceneError& e) {
    std::string message = e.what();
    EXPECT_EQ(message.rfind(path + ":3: ", 0), 0u) << message;
    EXPECT_NE(message.find(words), std::string::npos) << message;
  }
}

TEST(SamplerElement, BadParametersNameTheirLine) {
  expect_sampler_error(
      "<sampler type=\"ldsampler\"><boolean name=\"jitter\" value=\"false\"/></sampler>",
      "unused parameter 'jitter'");
  expect_sampler_error(
      "<sampler type=\"independent\"><boolean name=\"jitter\" value=\"false\"/></sampler>",
      "unused parameter 'jitter'");
  expect_sampler_error(
      "<sampler type=\"stratified\"><integer name=\"jitter\" value=\"1\"/></sampler>", "jitter");
  expect_sampler_error(
      "<sampler type=\"stratified\"><integer name=\"sample_count\" value=\"20000000\"/></sampler>",
      "sample_count 20000000 exceeds 2^24");
  expect_sampler_error(
      "<sampler type=\"multijitter\"><integer name=\"sample_count\" value=\"0\"/></sampler>",
      "sample_count must be positive");
}

}  // namespace
}  // namespace tr
