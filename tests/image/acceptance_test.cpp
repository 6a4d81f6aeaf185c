// The harness catches what it must (issue 5): with the Mitsuba reference of
// bsdf_spheres/test_arealight and its per-sample variance, synthetic renders at the README's
// sample count spp = floor(2e6 / (48 * 48)) = 868 are
//  - unbiased noise          → pass every variance test (seeds 1-5);
//  - a 2% uniform scale      → fail the gain test (the README's two tests alone let it
//                              through on this scene, see variance_tests.h);
//  - one 4x4 block 10% off   → fail the block test, and lockstep against the unbiased render
//                              it was made from. The block is the one whose mean the
//                              reference determines best (smallest relative standard error):
//                              a change of a noisy block, or of a black one, is invisible to
//                              any test, while lockstep sees it anywhere it is non-zero.
// Expected false-failure rate of the unbiased case, per seed: at most 1% for each of the block
// and gain tests (their Šidák family level), conservative here because the README's XYZ
// transform of the variance (M var rather than M² var) overstates the XYZ variance of the
// synthetic noise; the pixel test far below that (about 0.03 failing values expected where 18
// are needed to fail). The seeds are fixed, so the outcome is deterministic.
#include <gtest/gtest.h>

#include "synthetic.h"
#include "validation/image/compare.h"

namespace tr {
namespace {

constexpr double kSpp = 868.0;  // floor(2e6 / (48 * 48))
constexpr double kReferenceSpp = 32000.0;

class Acceptance : public ::testing::Test {
 protected:
  static void SetUpTestSuite() {
    reference_ = new RgbImage(read_rgb(testing::arealight_refs() + ".exr"));
    variance_ = new RgbImage(read_rgb(testing::arealight_refs() + "_var.exr"));
  }
  static void TearDownTestSuite() {
    delete reference_;
    delete variance_;
  }
  static const RgbImage& ref() { return *reference_; }
  static const RgbImage& var() { return *variance_; }

  // Pixel-space origin of the 4x4 block whose mean luminance the reference determines best:
  // the smallest ratio of standard error (per-sample variance / 868 / 16) to mean.
  static void best_determined_block(int* bx, int* by) {
    double best = INFINITY;
    for (int y = 0; y + 4 <= ref().height; y += 4)
      for (int x = 0; x + 4 <= ref().width; x += 4) {
        double mean = 0.0, variance = 0.0;
        for (int j = 0; j < 4; ++j)
          for (int i = 0; i < 4; ++i) {
            mean += ref().at(x + i, y + j, 1) / 16.0;
            variance += var().at(x + i, y + j, 1) / 16.0;
          }
        double relative_error = std::sqrt(variance / (kSpp * 16.0)) / mean;
        if (mean > 0.0 && relative_error < best) {
          best = relative_error;
          *bx = x;
          *by = y;
        }
      }
  }

  static RgbImage scaled_patch(RgbImage img, int x0, int y0, double factor) {
    for (int y = y0; y < y0 + 4; ++y)
      for (int x = x0; x < x0 + 4; ++x)
        for (int c = 0; c < 3; ++c) img.at(x, y, c) *= factor;
    return img;
  }

  static CompareReport against_reference(const RgbImage& render) {
    CompareInputs in;
    in.test = render;
    in.reference = ref();
    in.reference_variance = var();
    in.test_spp = kSpp;
    in.reference_spp = kReferenceSpp;
    return compare_images(in);
  }

  static RgbImage* reference_;
  static RgbImage* variance_;
};

RgbImage* Acceptance::reference_ = nullptr;
RgbImage* Acceptance::variance_ = nullptr;

const std::uint64_t kSeeds[] = {1, 2, 3, 4, 5};

TEST_F(Acceptance, UnbiasedNoisyRenderPasses) {
  for (std::uint64_t seed : kSeeds) {
    CompareReport r = against_reference(testing::noisy_render(ref(), var(), kSpp, seed));
    ASSERT_TRUE(r.pixel_z && r.block_z && r.gain_z);
    EXPECT_TRUE(r.pixel_z->passed) << "seed " << seed << ": " << r.pixel_z->failing_values;
    EXPECT_TRUE(r.block_z->passed) << "seed " << seed << ": min p " << r.block_z->min_p;
    EXPECT_TRUE(r.gain_z->passed) << "seed " << seed << ": min p " << r.gain_z->min_p;
    EXPECT_TRUE(r.passed) << "seed " << seed;
    EXPECT_EQ(r.criteria, (std::vector<std::string>{"pixel_z", "block_z", "gain_z"}));
  }
}

TEST_F(Acceptance, TwoPercentScaleFails) {
  for (std::uint64_t seed : kSeeds) {
    RgbImage render = testing::noisy_render(ref(), var(), kSpp, seed);
    for (double& v : render.rgb) v *= 1.02;
    CompareReport r = against_reference(render);
    EXPECT_FALSE(r.gain_z->passed) << "seed " << seed;
    EXPECT_LT(r.gain_z->min_p, 1e-6) << "seed " << seed;
    EXPECT_FALSE(r.passed) << "seed " << seed;
  }
}

// The gain test's margin: on test_textured_diffuse (low noise) a noise-free 0.3% gain is
// resolved (it fails with no margin) but counts as no bias under the default 0.5% margin,
// while 1% fails either way.
TEST(GainMargin, SmallGainsPassOnlyWithinTheMargin) {
  const std::string base =
      testing::shared_dir() +
      "/mitsuba-tests/tests/scenes/bsdf_spheres/refs/test_textured_diffuse_ref_rgb";
  RgbImage ref = read_rgb(base + ".exr"), var = read_rgb(base + "_var.exr");
  auto scaled = [&](double k) {
    RgbImage img = ref;
    for (double& v : img.rgb) v *= k;
    return img;
  };
  VarianceTestOptions exact;
  exact.gain_margin = 0.0;
  EXPECT_TRUE(gain_z_test(scaled(1.003), kSpp, ref, var, kReferenceSpp).passed);
  EXPECT_FALSE(gain_z_test(scaled(1.003), kSpp, ref, var, kReferenceSpp, exact).passed);
  HypothesisTestResult one_percent = gain_z_test(scaled(1.01), kSpp, ref, var, kReferenceSpp);
  EXPECT_FALSE(one_percent.passed);
  EXPECT_NEAR(one_percent.gain[1], 1.01, 1e-4);
}

// Channels that are not a colour (AOVs) are tested as they are: an offset in the third channel
// alone is found in that channel, where the XYZ conversion would spread it over X, Y and Z.
TEST(NonColourChannels, AreTestedWithoutTheXyzConversion) {
  RgbImage ref;
  ref.width = ref.height = 8;
  ref.rgb.assign(3 * ref.pixel_count(), 1.0);
  RgbImage var = ref, img = ref;
  for (double& v : var.rgb) v = 1.0;
  img.at(3, 5, 2) += 1.0;  // z = 1 * sqrt(1e4 / 1) = 100 in that one value
  VarianceTestOptions raw;
  raw.colour = false;
  HypothesisTestResult as_is = pixel_z_test(img, 1e4, ref, var, raw);
  EXPECT_EQ(as_is.failing_values, 1u);
  EXPECT_EQ(as_is.min_p_channel, 2);
  EXPECT_NEAR(as_is.max_statistic, 100.0, 1e-9);
  HypothesisTestResult as_colour = pixel_z_test(img, 1e4, ref, var);
  EXPECT_EQ(as_colour.failing_values, 3u);  // blue reaches X, Y and Z
}

TEST_F(Acceptance, OneBlockTenPercentOffFailsBlockTestAndLockstep) {
  int bx = 0, by = 0;
  best_determined_block(&bx, &by);
  for (std::uint64_t seed : kSeeds) {
    RgbImage render = testing::noisy_render(ref(), var(), kSpp, seed);
    RgbImage patched = scaled_patch(render, bx, by, 1.1);
    CompareReport r = against_reference(patched);
    EXPECT_FALSE(r.block_z->passed) << "seed " << seed;
    EXPECT_EQ(r.block_z->min_p_x, bx / 4);
    EXPECT_EQ(r.block_z->min_p_y, by / 4);

    // Lockstep: the patched render against the render it came from (same samples).
    CompareInputs pair;
    pair.test = patched;
    pair.reference = render;
    CompareOptions lockstep;
    lockstep.lockstep = true;
    CompareReport l = compare_images(pair, lockstep);
    EXPECT_FALSE(l.passed);
    EXPECT_EQ(l.lockstep.pixels_outside, 16u);
    EXPECT_GE(l.lockstep.clustered_windows, 1u);
    EXPECT_EQ(l.lockstep.most_outside, 16);
    ASSERT_FALSE(l.lockstep.worst.empty());
    EXPECT_GE(l.lockstep.worst[0].x, bx);
    EXPECT_LT(l.lockstep.worst[0].x, bx + 4);
  }
}

TEST_F(Acceptance, MisalignedPatchFailsLockstep) {
  int bx = 0, by = 0;
  best_determined_block(&bx, &by);
  RgbImage render = testing::noisy_render(ref(), var(), kSpp, 1);
  LockstepResult l = lockstep_compare(scaled_patch(render, bx + 2, by + 2, 1.1), render);
  EXPECT_FALSE(l.passed);
  EXPECT_LE(l.pixels_outside, 23u);    // within the 1% of 2304 pixels that may be outside
  EXPECT_GE(l.clustered_windows, 1u);  // the windows over the patch
}

// A 4x4 patch of pixels 1e-3 off in alternating directions (no systematic shift) is a cluster;
// a rounding control that moves the same pixels by 5e-4 marks them rounding-sensitive and
// takes them out of the cluster check, a control equal to the reference does not.
TEST_F(Acceptance, RoundingControlExcusesOnlyTheSensitivePixels) {
  int bx = 0, by = 0;
  best_determined_block(&bx, &by);
  RgbImage render = testing::noisy_render(ref(), var(), kSpp, 1);
  RgbImage patched = render, control = render;
  testing::scale_block(patched, bx, by, 0.999, 1.001);
  testing::scale_block(control, bx, by, 1.0005, 1.0005);
  LockstepResult plain = lockstep_compare(patched, render);
  EXPECT_EQ(plain.systematic_cells, 0u);
  EXPECT_GE(plain.clustered_windows, 1u);
  EXPECT_FALSE(plain.passed);

  LockstepResult excused = lockstep_compare(patched, render, {}, &control);
  EXPECT_GE(plain.pixels_outside, 8u);
  EXPECT_GE(excused.rounding_sensitive, plain.pixels_outside);
  EXPECT_LE(excused.rounding_sensitive, 16u);
  EXPECT_EQ(excused.clustered_windows, 0u);
  EXPECT_TRUE(excused.passed);

  LockstepResult insensitive = lockstep_compare(patched, render, {}, &render);
  EXPECT_EQ(insensitive.rounding_sensitive, 0u);
  EXPECT_FALSE(insensitive.passed);
}

// fraction_over_well_conditioned: 2% of the pixels, scattered, 1e-2 off (the 99% rule fails);
// a control that moves exactly those pixels excuses them from the fraction, a control that
// moves none does not, and a control that marks more than 5% of the image fails the cap.
TEST_F(Acceptance, WellConditionedFractionExcusesOnlySensitivePixels) {
  RgbImage render = testing::noisy_render(ref(), var(), kSpp, 1);
  RgbImage off = render, control = render, broad = render;
  const size_t pixels = render.pixel_count();
  size_t moved = 0;
  for (size_t i = 0; i < pixels; i += 50, ++moved)
    for (int c = 0; c < 3; ++c) {
      off.rgb[3 * i + c] += 1e-2;
      control.rgb[3 * i + c] += 5e-3;
    }
  for (size_t i = 0; i < pixels; i += 10)
    for (int c = 0; c < 3; ++c) broad.rgb[3 * i + c] += 5e-3;
  ASSERT_GT(moved, pixels / 100);
  LockstepOptions o;
  o.fraction_over_well_conditioned = true;
  EXPECT_FALSE(lockstep_compare(off, render, {}, &control).passed);
  LockstepResult excused = lockstep_compare(off, render, o, &control);
  EXPECT_EQ(excused.rounding_sensitive, moved);
  EXPECT_DOUBLE_EQ(excused.fraction_within, 1.0);
  EXPECT_TRUE(excused.passed);
  EXPECT_FALSE(lockstep_compare(off, render, o, &render).passed);
  EXPECT_FALSE(lockstep_compare(off, render, o, &broad).passed);
  EXPECT_FALSE(lockstep_compare(off, render, o).passed);
}

TEST_F(Acceptance, LockstepToleratesRoundingButNotSmallBias) {
  RgbImage render = testing::noisy_render(ref(), var(), kSpp, 1);
  testing::Gaussian normal(99);
  RgbImage rounded = render, biased = render;
  for (size_t i = 0; i < render.rgb.size(); ++i) {
    rounded.rgb[i] *= 1.0 + 1e-6 * normal();  // float-rounding-sized, unbiased
    biased.rgb[i] *= 1.0 + 5e-5;              // below the 1e-4 per-pixel tolerance
  }
  LockstepResult ok = lockstep_compare(rounded, render);
  EXPECT_TRUE(ok.passed);
  EXPECT_EQ(ok.pixels_outside, 0u);
  EXPECT_EQ(ok.systematic_cells, 0u);

  LockstepResult bias = lockstep_compare(biased, render);
  EXPECT_EQ(bias.pixels_outside, 0u);
  EXPECT_GT(bias.systematic_cells, 0u);
  EXPECT_FALSE(bias.passed);
}

// Two renders, each with its own variance (as CPU against GPU): Welch's tests pass unbiased
// pairs and catch the 10% block. (A 2% scale between two 868-spp renders of this scene is
// beyond what per-block tests resolve, and the gain test needs a converged reference.)
TEST_F(Acceptance, WelchPassesTwoUnbiasedRendersAndCatchesABlockBias) {
  int bx = 0, by = 0;
  best_determined_block(&bx, &by);
  for (std::uint64_t seed : kSeeds) {
    CompareInputs in;
    in.test = testing::noisy_render(ref(), var(), kSpp, seed);
    in.reference = testing::noisy_render(ref(), var(), kSpp, seed + 1000);
    in.test_variance = var();
    in.reference_variance = var();
    in.test_spp = in.reference_spp = kSpp;
    CompareReport r = compare_images(in);
    ASSERT_TRUE(r.pixel_welch && r.block_welch);
    EXPECT_TRUE(r.pixel_welch->passed) << "seed " << seed;
    EXPECT_TRUE(r.block_welch->passed) << "seed " << seed << ": min p " << r.block_welch->min_p;
    EXPECT_EQ(r.criteria, (std::vector<std::string>{"pixel_welch", "block_welch"}));

    in.test = scaled_patch(in.test, bx, by, 1.1);
    CompareReport patched = compare_images(in);
    EXPECT_FALSE(patched.block_welch->passed) << "seed " << seed;
    EXPECT_EQ(patched.block_welch->min_p_x, bx / 4);
    EXPECT_EQ(patched.block_welch->min_p_y, by / 4);
    EXPECT_FALSE(patched.passed) << "seed " << seed;
  }
}

}  // namespace
}  // namespace tr
