// twinray::validation — statistical and numerical checks of BSDF sampling routines, usable on
// any BSDF: pass callables for sample(), pdf() and (optionally) eval() and get a report.
//
// Conventions (those of twinray and Mitsuba 3):
//  * Directions live in the local shading frame, normal along +z, unit length.
//  * wi points from the surface towards the previous path vertex, wo away from the surface
//    towards the next one; both may lie in either hemisphere.
//  * sample() draws wo from the BSDF's sampling density given wi and three uniform numbers in
//    [0, 1): u1 (typically the lobe choice) and u2.
//  * A failed draw (e.g. a microfacet reflection below the horizon) returns pdf = 0 and weight 0.
//  * A draw from a Dirac-delta lobe sets delta = true and reports in pdf the discrete
//    probability with which that lobe was chosen (e.g. the Fresnel reflectance of a smooth
//    dielectric); pdf() ignores delta lobes and returns the solid-angle density of the
//    continuous lobes only.
//
// Every statistical check states its significance level; validate_bsdf() applies a Šidák
// correction so that a correct BSDF fails the whole report with probability `significance`.
#ifndef TWINRAY_VALIDATION_H
#define TWINRAY_VALIDATION_H

#include <cstddef>
#include <cstdint>
#include <functional>
#include <glm/vec2.hpp>
#include <glm/vec3.hpp>
#include <ostream>
#include <string>
#include <vector>

namespace twinray::validation {

// ---- What the user supplies ---------------------------------------------------------------

/// One draw of a BSDF sampling routine.
struct BsdfSample {
  glm::vec3 wo{0.0f};      ///< Sampled outgoing direction (unit length).
  float pdf = 0.0f;        ///< Solid-angle density of wo, or the discrete lobe probability
                           ///< when `delta` is set; 0 marks a failed draw.
  glm::vec3 weight{0.0f};  ///< Monte Carlo weight f(wi, wo) |cos θo| / pdf.
  bool delta = false;      ///< wo was drawn from a Dirac-delta lobe.
  /// Label of the delta lobe (any value, distinct per lobe): two delta lobes that can yield the
  /// same direction (a mask's pass-through and a refraction at normal incidence) are then
  /// tested against their own probabilities. Ignored for continuous lobes.
  unsigned lobe = 0;
};

/// sample(wi, u1, u2): draw wo given wi and uniform numbers u1 ∈ [0,1), u2 ∈ [0,1)².
using SampleFunction =
    std::function<BsdfSample(const glm::vec3& wi, float u1, const glm::vec2& u2)>;
/// pdf(wi, wo): solid-angle density with which sample() draws wo from the continuous lobes.
using PdfFunction = std::function<float(const glm::vec3& wi, const glm::vec3& wo)>;
/// eval(wi, wo): the BSDF value, with or without the |cos θo| factor (see BsdfUnderTest).
using EvalFunction = std::function<glm::vec3(const glm::vec3& wi, const glm::vec3& wo)>;

/// A BSDF under test: its sampling routine, its density and optionally its value.
struct BsdfUnderTest {
  std::string name;       ///< Label used in reports.
  SampleFunction sample;  ///< Required.
  PdfFunction pdf;        ///< Required.
  EvalFunction eval;      ///< Optional: enables the weight, support, reciprocity and energy
                          ///< checks. Empty: those checks are skipped (and reported so).
  /// true when eval() returns f(wi, wo) |cos θo| (twinray's bsdf_eval, Mitsuba's eval);
  /// false when it returns f(wi, wo) alone.
  bool eval_includes_cosine = true;
  /// Check Helmholtz reciprocity f(wi, wo) = f(wo, wi) for pairs on the same side.
  bool reciprocal = true;
  /// Check that the directional albedo ∫ f |cos θo| dωo is at most 1.
  bool energy_conserving = true;
};

/// A sampler of directions on the sphere without an incident direction: warps, emitter
/// direction samplers (the hook for light-sampling routines), phase functions at fixed wi.
struct DirectionSample {
  glm::vec3 w{0.0f};  ///< Sampled direction (unit length).
  float pdf = 0.0f;   ///< Its solid-angle density as reported by the sampler; 0 = failed draw.
};
struct DirectionSampler {
  std::string name;
  std::function<DirectionSample(const glm::vec2& u)> sample;  ///< u uniform on [0,1)².
  std::function<float(const glm::vec3& w)> pdf;               ///< Solid-angle density.
};

/// A sampler of points in a rectangle of the plane (disk and triangle warps, image samplers).
struct PlanarSampler {
  std::string name;
  std::function<glm::vec2(const glm::vec2& u)> sample;  ///< u uniform on [0,1)².
  std::function<float(const glm::vec2& p)> pdf;         ///< Area density.
  glm::vec2 lower{0.0f};  ///< The rectangle [lower, upper] must contain the support.
  glm::vec2 upper{1.0f};
};

// ---- Chi-square goodness of fit ------------------------------------------------------------

/// Options of the chi-square test. The design is that of Wenzel Jakob's chi-square test in
/// Mitsuba and of pbrt-v3's src/tests/bsdfs.cpp: bin the samples, integrate the density over
/// each bin for the expected counts, pool sparse bins, compare with Pearson's statistic.
struct ChiSquareOptions {
  std::size_t sample_count = 1000000;
  int cos_theta_bins = 10;  ///< Bins over cos θ ∈ [-1, 1] (even, so the horizon is a bin edge);
                            ///< planar tests use it for x.
  int phi_bins = 20;        ///< Bins over φ ∈ [0, 2π); planar tests use it for y.
  double min_expected = 5.0;  ///< Bins expecting fewer samples are pooled together.
  /// Absolute tolerance of the adaptive Gauss-Kronrod integral of the density over one bin,
  /// as a probability (one draw in `sample_count` ≙ 1/sample_count).
  double integration_tolerance = 1e-8;
  int integration_max_panels = 32;  ///< Panel budget per one-dimensional adaptive integral.
  std::uint64_t seed = 1;
};

/// Outcome of one chi-square test.
struct ChiSquareResult {
  double statistic = 0.0;  ///< Pearson's X² over the pooled cells.
  int dof = 0;             ///< Degrees of freedom: pooled cells - 1.
  double p_value = 0.0;    ///< P(X² ≥ statistic) under the null hypothesis; 0 on a hard failure.
  double pdf_integral = 0.0;        ///< ∫ pdf over the domain + probabilities of sampled deltas.
  double integration_error = 0.0;   ///< Estimated quadrature error of pdf_integral (sum of
                                    ///< the per-bin QUADPACK Gauss-Kronrod error estimates).
  std::size_t samples = 0;          ///< Draws made.
  std::size_t failed_samples = 0;   ///< Draws with pdf 0.
  std::size_t delta_samples = 0;    ///< Draws from delta lobes (tested as discrete atoms).
  std::size_t delta_atoms = 0;      ///< Distinct delta directions seen.
  std::size_t outside_support = 0;  ///< Draws in bins whose integrated density is exactly 0.
  std::string failure;              ///< Non-empty on a hard failure (p_value is then 0).
};

/// Hard failures (p_value = 0, `failure` set): draws where pdf() is 0 or in bins whose integrated
/// density is 0 (samples outside the support), and ∫ pdf > 1 + integration_error + 1e-5 (the
/// last term for float rounding of the density values).
///
/// Chi-square test of a BSDF sampling routine at one incident direction, over (cos θ, φ) on the
/// whole sphere (so transmission is covered). Delta-lobe draws are grouped by (direction, lobe)
/// into discrete atoms whose expected counts come from their reported probabilities; the continuous
/// part is compared with pdf() integrated over each bin.
ChiSquareResult chi_square_bsdf(const BsdfUnderTest& bsdf, const glm::vec3& wi,
                                const ChiSquareOptions& options);

/// Chi-square test of a direction sampler over (cos θ, φ); use it for warps and for emitter
/// (light) direction samplers.
ChiSquareResult chi_square_directions(const DirectionSampler& sampler,
                                      const ChiSquareOptions& options);

/// Chi-square test of a planar sampler over its rectangle.
ChiSquareResult chi_square_planar(const PlanarSampler& sampler, const ChiSquareOptions& options);

// ---- Consistency ---------------------------------------------------------------------------

/// Options of the deterministic consistency checks.
struct ConsistencyOptions {
  std::size_t sample_count = 100000;  ///< Draws checked per incident direction.
  std::size_t random_pairs = 100000;  ///< Uniform (wo) directions checked for eval/pdf support.
  /// Two floats a, b agree when |a - b| ≤ relative_tolerance · max(|a|, |b|) + absolute_tolerance.
  float relative_tolerance = 1e-3f;
  float absolute_tolerance = 1e-6f;
  std::uint64_t seed = 2;
};

/// Outcome of the consistency checks at one incident direction. Each counter is the number of
/// violations; `first_failure` describes the first one.
struct ConsistencyResult {
  std::size_t checked_samples = 0;
  std::size_t weight_mismatch = 0;     ///< weight ≠ eval·(|cos θo|)/pdf.
  std::size_t pdf_mismatch = 0;        ///< pdf(wi, sampled wo) ≠ sampled pdf.
  std::size_t failed_with_weight = 0;  ///< pdf = 0 but weight ≠ 0.
  std::size_t not_unit = 0;            ///< | |wo| - 1 | > 1e-3 for a successful draw.
  std::size_t eval_without_pdf = 0;    ///< eval > 0 where pdf = 0 (a lobe never sampled).
  std::size_t not_reciprocal = 0;      ///< f(wi, wo) ≠ f(wo, wi) on the same side.
  std::size_t delta_mismatch = 0;      ///< A delta atom reports differing probabilities.
  std::string first_failure;
  bool passed() const;
};

/// Checks, at one incident direction: weight == eval·|cos θo|/pdf, pdf(sampled) == sampled pdf,
/// eval > 0 ⇒ pdf > 0 (on sampled and on uniformly distributed directions), reciprocity of
/// eval for reflection pairs, unit-length samples and zero weights on failed draws.
ConsistencyResult consistency_check(const BsdfUnderTest& bsdf, const glm::vec3& wi,
                                    const ConsistencyOptions& options);

// ---- Energy --------------------------------------------------------------------------------

/// Outcome of the Monte Carlo albedo test.
struct AlbedoResult {
  glm::dvec3 albedo{0.0};          ///< Mean sample weight per channel.
  glm::dvec3 standard_error{0.0};  ///< Its standard error per channel.
  double p_value = 1.0;            ///< One-sided test of H0: albedo ≤ 1 + 1e-5 in every channel.
};

/// Estimates the directional albedo ∫ f |cos θo| dωo = E[weight] at one incident direction and
/// tests H0: albedo_c ≤ 1 + 1e-5 (the slack covers float rounding of unit weights). Per
/// channel z = (mean - 1 - 1e-5) / standard error and p_c = 1 - Φ(z) by the central limit
/// theorem; p = min(1, 3 · min_c p_c) (Bonferroni over the three channels).
AlbedoResult albedo_test(const BsdfUnderTest& bsdf, const glm::vec3& wi, std::size_t samples,
                         std::uint64_t seed);

// ---- Extremes ------------------------------------------------------------------------------

/// Outcome of the extreme-argument check.
struct ExtremesResult {
  std::size_t evaluations = 0;  ///< Values inspected.
  std::size_t failures = 0;     ///< NaN, Inf or negative values.
  std::string first_failure;
};

/// Incident directions for extremes_check: cos θ ∈ {1, 0.5, 1e-2, 1e-4, 1e-6, 0, -1e-6, -0.5,
/// -1}, at two azimuths.
std::vector<glm::vec3> extreme_incident_directions();

/// Calls sample (with u at 0, 1-2⁻²⁴, ½ and random), pdf and eval for every incident direction
/// against a set of outgoing directions (normal, grazing, below the horizon, mirror, straight
/// through, sampled, random) and fails on any NaN, Inf or negative pdf/weight/eval component,
/// or a non-finite sampled direction.
ExtremesResult extremes_check(const BsdfUnderTest& bsdf, const std::vector<glm::vec3>& incident,
                              std::size_t random_draws, std::uint64_t seed);

// ---- Statistics helpers -------------------------------------------------------------------

/// Regularized upper incomplete gamma function Q(a, x) = Γ(a, x) / Γ(a).
double regularized_gamma_q(double a, double x);
/// P(X² ≥ statistic) for a chi-square variable with `dof` degrees of freedom.
double chi_square_p_value(double statistic, int dof);
/// Šidák-corrected per-test level: 1 - (1 - overall)^(1/tests).
double sidak_alpha(double overall, std::size_t tests);

// ---- Whole-BSDF validation and reports -----------------------------------------------------

/// One line of a report.
struct CheckResult {
  std::string bsdf;          ///< BsdfUnderTest::name (or sampler name).
  std::string check;         ///< "chi2", "albedo", "consistency", "extremes".
  glm::vec3 wi{0.0f};        ///< Incident direction (zero where not applicable).
  bool statistical = false;  ///< Has a p-value compared against `alpha`.
  double p_value = 1.0;
  double alpha = 0.0;  ///< Level the p-value was tested at.
  bool passed = false;
  std::string detail;  ///< Numbers behind the verdict.
};

/// A list of results with a verdict and a printer.
struct Report {
  std::vector<CheckResult> checks;
  bool passed() const;  ///< All checks passed.
  /// Prints one row per check: verdict, check, BSDF, incident angle, p-value, α, details.
  void print(std::ostream& out) const;
  void append(const Report& other);
};

/// Runs one check of validate_bsdf: it must call `check` at least once and may call it again;
/// the results of the last call are kept. A memoizing batch evaluator uses it to evaluate the
/// callables somewhere else (e.g. on a GPU, tests/bsdf_gpu): each call records the arguments it
/// has no value for yet, the runner evaluates them in one batch and repeats the check until a
/// call finds every value in its cache. Empty: each check is called once.
using CheckRunner = std::function<void(const std::function<void()>& check)>;

/// Options of validate_bsdf.
struct ValidationOptions {
  ChiSquareOptions chi_square;
  ConsistencyOptions consistency;
  std::size_t albedo_samples = 100000;
  std::size_t extreme_random_draws = 64;
  /// Overall significance: a correct BSDF fails the report with this probability.
  double significance = 0.01;
  /// Per-test level; 0 = Šidák over this call's statistical tests (2 per incident direction,
  /// or 1 without eval). Set it when the call is one part of a larger suite.
  double alpha_per_test = 0.0;
  /// Wraps every chi-square, consistency, albedo and extremes check (see CheckRunner).
  CheckRunner run_check;
};

/// Number of statistical tests validate_bsdf runs (used to apply Šidák across several calls).
std::size_t statistical_test_count(const BsdfUnderTest& bsdf, std::size_t incident_directions);

/// Runs chi-square, consistency and (with eval) albedo checks at every incident direction,
/// plus the extremes check over extreme_incident_directions() and `incident`.
Report validate_bsdf(const BsdfUnderTest& bsdf, const std::vector<glm::vec3>& incident,
                     const ValidationOptions& options);

/// A chi-square result as a report line: passed when there is no hard failure and
/// p_value ≥ alpha. `wi` is zero for samplers without an incident direction.
CheckResult report_line(const std::string& name, const glm::vec3& wi, const ChiSquareResult& result,
                        double alpha);
/// An albedo result as a report line: passed when p_value ≥ alpha.
CheckResult report_line(const std::string& name, const glm::vec3& wi, const AlbedoResult& result,
                        double alpha);
/// A consistency result as a report line (deterministic).
CheckResult report_line(const std::string& name, const glm::vec3& wi,
                        const ConsistencyResult& result);
/// An extremes result as a report line (deterministic, over many incident directions).
CheckResult report_line(const std::string& name, const ExtremesResult& result);

/// Incident direction at polar angle theta (degrees) and azimuth phi (degrees).
glm::vec3 direction_from_angles(double theta_degrees, double phi_degrees);

}  // namespace twinray::validation

#endif
