// Copyright (c) 2026 The Part_decomposition authors.
// All rights reserved.
//
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Author(s)     : The Part_decomposition authors

#ifndef CGAL_PART_DECOMPOSITION_INTERNAL_BOUNDED_LEAST_SQUARES_H
#define CGAL_PART_DECOMPOSITION_INTERNAL_BOUNDED_LEAST_SQUARES_H

#include <Eigen/Core>
#include <Eigen/Cholesky>

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <limits>

namespace CGAL {
namespace Part_decomposition {
namespace internal {

// Projected Levenberg-Marquardt with active-set freezing for
//   min 1/2 |f(x)|^2  subject to  lb <= x <= ub,   x in R^N, f in R^m.
//
// Each iteration solves (A_FF + mu D_FF) d_F = -g_F on the free set F (a bound variable is frozen
// while the gradient pushes it outward), with A = J^T J, g = J^T f and the Marquardt scaling
// D = diag(A) / scale^2: a variable of scale s moves s times as far as one of scale 1 for the same
// damping, which is how the caller shrinks the trust region along chosen directions (scipy's
// x_scale). The step is projected on the box and judged by the gain ratio of the projected step;
// the damping follows Nielsen's rule. A trial after an accepted step also evaluates the Jacobian
// (one pass per accepted step); a trial after a rejection evaluates residuals only.
//
// Problem interface (the problem forms the normal equations itself, so that it can sum them over
// fixed blocks of residuals in parallel without the solver storing the m x N Jacobian):
//   double cost(const Vector& x);                                  // 1/2 |f(x)|^2
//   double cost_and_normal_equations(const Vector& x, Matrix& A, Vector& g);
//                                  // also A = J^T J (both triangles) and g = J^T f at x
//   void accept(Vector& x);  // after an accepted step; may re-parametrize x at the same point
template <int N>
class Bounded_least_squares
{
public:
  typedef Eigen::Matrix<double, N, 1> Vector;
  typedef Eigen::Matrix<double, N, N> Matrix;

  struct Options
  {
    int maximum_evaluations = 50;  // residual evaluations, with or without Jacobian
    double ftol = 1e-8;            // stop when the accepted decrease is below ftol * cost
    double xtol = 1e-8;            // stop when |step| < xtol (xtol + |x|)
    double gtol = 1e-10;           // stop when the projected gradient is below gtol
    double initial_damping = 1e-3; // mu0, relative to diag(A)
    Vector scale = Vector::Ones(); // x_scale
  };

  struct Report
  {
    int evaluations = 0;
    int jacobian_evaluations = 0;
    int accepted_steps = 0;
    double initial_cost = 0.;
    double final_cost = 0.;
    bool finite = true; // false if the cost at x0 is not finite (x left at x0)
  };

  template <typename Problem>
  Report solve(Problem& problem, Vector& x, const Vector& lb, const Vector& ub, const Options& options)
  {
    Report report;
    clamp_to_box(x, lb, ub);

    Matrix A, A_trial;
    Vector g, g_trial;
    double F = evaluate(problem, x, true, A, g, report);
    report.initial_cost = report.final_cost = F;
    if(!std::isfinite(F))
    {
      report.finite = false;
      return report;
    }

    double mu = options.initial_damping, nu = 2.;
    bool last_accepted = true;
    while(report.evaluations < options.maximum_evaluations)
    {
      bool frozen[N];
      if(free_gradient_norm(x, g, lb, ub, frozen) < options.gtol) break;
      Vector step;
      if(!damped_step(A, g, frozen, mu, options, step))
      {
        if(!raise_damping(mu, nu)) break;
        continue;
      }
      Vector x_trial = x + step;
      clamp_to_box(x_trial, lb, ub);
      const Vector s = x_trial - x;
      if(s.squaredNorm() == 0.) break;
      const double predicted = -(g.dot(s) + 0.5 * s.dot(A * s));

      // After an accepted step the next one is likely accepted too: evaluate the Jacobian with
      // the trial (it is the Jacobian of the new point). After a rejection, residuals only.
      const bool with_jacobian = last_accepted;
      const double F_trial = evaluate(problem, x_trial, with_jacobian, A_trial, g_trial, report);
      const double actual = F - F_trial;
      last_accepted = std::isfinite(F_trial) && predicted > 0. && actual > 0.;
      if(!last_accepted)
      {
        if(!raise_damping(mu, nu)) break;
        continue;
      }
      const double gain = actual / predicted;
      x = x_trial;
      problem.accept(x);
      ++report.accepted_steps;
      const bool small_decrease = actual < options.ftol * F;
      const bool small_step = s.norm() < options.xtol * (options.xtol + x.norm());
      mu *= (std::max)(1. / 3., 1. - std::pow(2. * gain - 1., 3));
      nu = 2.;
      F = F_trial;
      report.final_cost = F;
      if(small_decrease || small_step || report.evaluations >= options.maximum_evaluations) break;
      if(with_jacobian)
      {
        A = A_trial;
        g = g_trial;
      }
      else
      {
        F = evaluate(problem, x, true, A, g, report);
        report.final_cost = F;
      }
    }
    return report;
  }

private:
  static void clamp_to_box(Vector& x, const Vector& lb, const Vector& ub)
  {
    for(int i = 0; i < N; ++i) x[i] = (std::min)(ub[i], (std::max)(lb[i], x[i]));
  }

  // The cost at `x`, with the normal equations `A` and `g` if `with_jacobian`; counts the evaluation.
  template <typename Problem>
  static double evaluate(Problem& problem, const Vector& x, bool with_jacobian, Matrix& A, Vector& g, Report& report)
  {
    const double F = with_jacobian ? problem.cost_and_normal_equations(x, A, g) : problem.cost(x);
    ++report.evaluations;
    if(with_jacobian) ++report.jacobian_evaluations;
    return F;
  }

  // Nielsen's rule after a rejected step; false once the damping is so large that steps vanish.
  static bool raise_damping(double& mu, double& nu)
  {
    mu *= nu;
    nu *= 2.;
    return !(mu > 1e20);
  }

  // Freezes the variables at a bound that the gradient pushes outward; returns the largest
  // gradient component of the free ones.
  static double free_gradient_norm(const Vector& x, const Vector& g, const Vector& lb, const Vector& ub, bool frozen[N])
  {
    double pg = 0.;
    for(int i = 0; i < N; ++i)
    {
      frozen[i] = (x[i] <= lb[i] && g[i] > 0.) || (x[i] >= ub[i] && g[i] < 0.);
      if(!frozen[i]) pg = (std::max)(pg, std::abs(g[i]));
    }
    return pg;
  }

  // The step of (A + mu D) step = -g on the free variables (0 on the frozen ones); false if the
  // system cannot be solved.
  static bool damped_step(const Matrix& A, const Vector& g, const bool frozen[N], double mu, const Options& options,
                          Vector& step)
  {
    Matrix M = A;
    Vector rhs = -g;
    for(int i = 0; i < N; ++i)
    {
      const double s = options.scale[i];
      M(i, i) += mu * (std::max)(A(i, i), 1e-12) / (s * s);
    }
    for(int i = 0; i < N; ++i)
      if(frozen[i])
      {
        M.row(i).setZero();
        M.col(i).setZero();
        M(i, i) = 1.;
        rhs[i] = 0.;
      }
    Eigen::LDLT<Matrix> ldlt(M);
    step = ldlt.solve(rhs);
    return ldlt.info() == Eigen::Success && step.allFinite();
  }
};

} // namespace internal
} // namespace Part_decomposition
} // namespace CGAL

#endif // CGAL_PART_DECOMPOSITION_INTERNAL_BOUNDED_LEAST_SQUARES_H
