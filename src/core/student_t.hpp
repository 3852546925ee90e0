#pragma once
// Student's t distribution: the width of a confidence interval for a mean estimated, with its
// standard error, from few independent samples (the reference's passes: docs/methods.md,
// "Ground truth", "Its own error").
namespace glintlab {

/// P(T <= t) for Student's t with `dof` degrees of freedom (dof >= 1).
double student_t_cdf(double t, int dof);

/// The t with P(T <= t) = p (0 < p < 1) for `dof` degrees of freedom: t_{0.975, 3} = 3.182.
double student_t_quantile(double p, int dof);

}  // namespace glintlab
