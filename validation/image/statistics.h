// Distribution functions for the hypothesis tests.
#pragma once

namespace tr {

// P(|Z| >= |z|) for a standard normal Z: erfc(|z| / sqrt(2)).
double normal_two_sided_p(double z);

// P(|T| >= |t|) for Student's t with `dof` degrees of freedom (dof > 0, may be infinite):
// I_{dof / (dof + t^2)}(dof / 2, 1 / 2) (Abramowitz & Stegun 26.7.1 with 26.5.27).
double student_two_sided_p(double t, double dof);

// The z >= 0 with normal_two_sided_p(z) = p, by bisection on [0, 40] (40 for p that small).
double normal_two_sided_quantile(double p);

// The regularized incomplete beta function I_x(a, b), a, b > 0, x in [0, 1], by its continued
// fraction (DLMF 8.17.22) evaluated with the modified Lentz method (Press et al., Numerical
// Recipes 3rd ed. §5.2, §6.4). Throws std::runtime_error if it does not converge.
double regularized_incomplete_beta(double x, double a, double b);

// Per-test significance level that keeps the family-wise error rate at family_alpha over
// `tests` independent tests (Šidák 1967): 1 - (1 - family_alpha)^(1 / tests).
double sidak_alpha(double family_alpha, double tests);

}  // namespace tr
