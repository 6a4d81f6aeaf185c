// Distribution functions against closed forms and tabulated values.
#include "validation/image/statistics.h"

#include <gtest/gtest.h>

#include <cmath>

namespace tr {
namespace {

TEST(Statistics, NormalTwoSided) {
  EXPECT_NEAR(normal_two_sided_p(1.959963984540054), 0.05, 1e-12);
  EXPECT_NEAR(normal_two_sided_p(-1.959963984540054), 0.05, 1e-12);
  EXPECT_DOUBLE_EQ(normal_two_sided_p(0.0), 1.0);
  EXPECT_NEAR(normal_two_sided_p(5.0), 5.733031437583878e-07, 1e-18);
}

TEST(Statistics, IncompleteBetaClosedForms) {
  // I_x(a, b) for integer a, b is a binomial tail: I_0.5(2, 3) = (6 + 4 + 1) / 16.
  EXPECT_NEAR(regularized_incomplete_beta(0.5, 2.0, 3.0), 0.6875, 1e-13);
  // I_x(1, b) = 1 - (1 - x)^b; I_x(a, 1) = x^a.
  EXPECT_NEAR(regularized_incomplete_beta(0.3, 1.0, 4.5), 1.0 - std::pow(0.7, 4.5), 1e-13);
  EXPECT_NEAR(regularized_incomplete_beta(0.9, 7.0, 1.0), std::pow(0.9, 7.0), 1e-13);
  // Symmetry I_x(a, b) = 1 - I_{1-x}(b, a) on both branches of the continued fraction.
  EXPECT_NEAR(regularized_incomplete_beta(0.8, 2.5, 3.5),
              1.0 - regularized_incomplete_beta(0.2, 3.5, 2.5), 1e-13);
}

TEST(Statistics, StudentTwoSided) {
  EXPECT_NEAR(student_two_sided_p(1.0, 1.0), 0.5, 1e-12);  // Cauchy: 1 - 2 atan(1) / π
  EXPECT_NEAR(student_two_sided_p(2.0, 10.0), 0.07338803477074431, 1e-10);
  EXPECT_NEAR(student_two_sided_p(2.131449545559323, 15.0), 0.05, 1e-10);  // t_{0.975, 15}
  // Large dof: the first-order expansion F_t(t) = Φ(t) - φ(t) (t³ + t) / (4 ν) + O(ν⁻²)
  // (Abramowitz & Stegun 26.7.5); infinite dof is the normal.
  const double t = 3.0, nu = 1e6, phi = std::exp(-0.5 * t * t) / std::sqrt(2.0 * M_PI);
  EXPECT_NEAR(student_two_sided_p(t, nu),
              normal_two_sided_p(t) + 2.0 * phi * (t * t * t + t) / (4.0 * nu), 1e-11);
  EXPECT_DOUBLE_EQ(student_two_sided_p(3.0, INFINITY), normal_two_sided_p(3.0));
}

TEST(Statistics, Sidak) {
  EXPECT_NEAR(sidak_alpha(0.01, 2304.0), 1.0 - std::pow(0.99, 1.0 / 2304.0), 1e-15);
  EXPECT_NEAR(sidak_alpha(0.05, 1.0), 0.05, 1e-15);
}

}  // namespace
}  // namespace tr
