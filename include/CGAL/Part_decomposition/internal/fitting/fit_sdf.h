// Copyright (c) 2026 The Part_decomposition authors.
// All rights reserved.
//
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Author(s)     : The Part_decomposition authors

#ifndef CGAL_PART_DECOMPOSITION_INTERNAL_FIT_SDF_H
#define CGAL_PART_DECOMPOSITION_INTERNAL_FIT_SDF_H

#include <CGAL/Part_decomposition/internal/fitting/bounded_least_squares.h>
#include <CGAL/Part_decomposition/internal/fitting/superquadric_distance.h>
#include <CGAL/Part_decomposition/internal/toolbox/toolbox.h>

#include <CGAL/assertions.h>
#include <CGAL/tags.h>

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <vector>

namespace CGAL {
namespace Part_decomposition {
namespace internal {

// The samples of one fit (structure of arrays): positions in the normalized cube, their values of
// d_M and the volumes they stand for (weights of the residuals).
struct Fit_samples
{
  std::vector<double> x, y, z, d, volume;
  std::size_t size() const { return d.size(); }
  void clear()
  {
    x.clear();
    y.clear();
    z.clear();
    d.clear();
    volume.clear();
  }
  void push_back(double px, double py, double pz, double pd, double pv = 1.)
  {
    x.push_back(px);
    y.push_back(py);
    z.push_back(pz);
    d.push_back(pd);
    volume.push_back(pv);
  }
};

struct Fit_sdf_settings
{
  double truncation = 0.125;          // tau
  // mu_ext and the evaluations per solve (one per outer pass): defaults::exterior_penalty and
  // defaults::maximum_solver_evaluations (checked in superquadric_fitting.h)
  double exterior_penalty = 5.;
  double near_surface_fraction = 0.3; // near-surface band and clip: 0.3 tau
  double active_multiplier = 3.;      // active set |d~(theta0)| < 3 tau
  double outlier_probability = 0.99;  // w_o of the MPS Gaussian inlier weight
  bool reestimate_variance = true;    // MPS rule: sigma^2 = sum w r^2 / sum w after each outer pass
  int maximum_outer_iterations = 4;   // outer passes of the MPS rule
  int maximum_evaluations = 40;
  double function_tolerance = 1e-8;   // stop a solve when an accepted step gains less (relative)
  double relative_cost_tolerance = 1e-3; // stop the outer passes when the cost changes less
  double semi_axis_scale = 1.;        // eta: x_scale of the semi-axes
};

struct Fit_sdf_result
{
  Superquadric_data theta;
  double cost = 0.;                // sum w r^2 / |P_a| at theta
  std::size_t active = 0;          // |P_a|
  int evaluations = 0;             // residual evaluations (with or without Jacobian)
  int solves = 0;                  // least-squares solves (outer passes)
  bool valid = false;              // false: too few active samples or a non-finite cost
};

// Parameter vector x = (ax, ay, az, e1, e2, d0, d1, d2, cx, cy, cz); d is a rotation increment
// around the problem's current rotation, folded into it after every accepted step.
typedef Bounded_least_squares<superquadric_number_of_parameters> Superquadric_solver;
typedef Superquadric_solver::Vector Superquadric_vector;

inline Superquadric_vector to_vector(const Superquadric_data& q)
{
  Superquadric_vector x;
  x << q.a[0], q.a[1], q.a[2], q.e1, q.e2, 0., 0., 0., q.c[0], q.c[1], q.c[2];
  return x;
}

// Per-block sums of one evaluation: 1/2 |f|^2 and, with the Jacobian, J^T J (lower triangle) and
// J^T f of the block's residuals.
struct Fit_sdf_block_sums
{
  double cost = 0.;
  Superquadric_solver::Matrix A;
  Superquadric_vector g;
};

// The weighted, two-stage clipped TSDF residuals of Alg. A.3 over the active samples. The samples
// are cut into fixed blocks of `block_size` whose sums are added in block order: the result does
// not depend on the number of threads, and the blocks are small enough to keep two threads busy
// on the few hundred samples of a small region of interest.
template <typename ConcurrencyTag>
class Fit_sdf_problem
{
public:
  typedef Superquadric_solver::Matrix Matrix;
  static constexpr std::size_t block_size = 128;

  Fit_sdf_problem(const std::vector<double>& px, const std::vector<double>& py, const std::vector<double>& pz,
                  const std::vector<double>& d, const std::vector<double>& sqrt_w,
                  const std::vector<double>& clip, std::vector<Fit_sdf_block_sums>& block_sums,
                  const double R[9])
    : m_px(px), m_py(py), m_pz(pz), m_d(d), m_sw(sqrt_w), m_clip(clip), m_block_sums(block_sums)
  {
    std::copy(R, R + 9, m_R);
  }

  Superquadric_data shape(const Superquadric_vector& x) const
  {
    Superquadric_data q;
    for(int i = 0; i < 3; ++i) q.a[i] = x[i];
    q.e1 = x[3];
    q.e2 = x[4];
    std::copy(m_R, m_R + 9, q.R);
    const double d[3] = {x[5], x[6], x[7]};
    if(d[0] != 0. || d[1] != 0. || d[2] != 0.) apply_rotation_increment(q.R, d);
    for(int i = 0; i < 3; ++i) q.c[i] = x[8 + i];
    return q;
  }

  double cost(const Superquadric_vector& x) { return evaluate(x, nullptr, nullptr); }
  double cost_and_normal_equations(const Superquadric_vector& x, Matrix& A, Superquadric_vector& g)
  {
    return evaluate(x, &A, &g);
  }

  void accept(Superquadric_vector& x)
  {
    const double d[3] = {x[5], x[6], x[7]};
    if(d[0] != 0. || d[1] != 0. || d[2] != 0.) apply_rotation_increment(m_R, d);
    x[5] = x[6] = x[7] = 0.;
  }

  const double* rotation() const { return m_R; }

private:
  static constexpr int n = superquadric_number_of_parameters;

  double evaluate(const Superquadric_vector& x, Matrix* A, Superquadric_vector* g)
  {
    typedef Eigen::Matrix<double, Eigen::Dynamic, n, Eigen::RowMajor> Rows;
    const Superquadric_data q = shape(x);
    const std::size_t m = m_d.size();
    const std::size_t blocks = (m + block_size - 1) / block_size;
    if(m_block_sums.size() < blocks) m_block_sums.resize(blocks);
    const bool normal_equations = A != nullptr;
    auto run = [&](std::size_t begin, std::size_t end) {
      // the unclipped rows of the block (a clipped residual is constant: zero row)
      double rows[block_size * n];
      double values[block_size];
      Eigen::Index kept = 0;
      double sum = 0.;
      for(std::size_t i = begin; i < end; ++i)
      {
        const double p[3] = {m_px[i], m_py[i], m_pz[i]};
        double* row = rows + n * kept;
        const double dt = normal_equations ? superquadric_radial_distance_and_gradient(q, p, row)
                                           : superquadric_radial_distance(q, p);
        const double r = dt - m_d[i];
        const double c = m_clip[i];
        const double fi = m_sw[i] * (std::abs(r) < c ? r : (r > 0. ? c : -c));
        sum += fi * fi;
        if(normal_equations && std::abs(r) < c)
        {
          for(int k = 0; k < n; ++k) row[k] *= m_sw[i];
          values[kept++] = fi;
        }
      }
      Fit_sdf_block_sums& out = m_block_sums[begin / block_size];
      out.cost = sum;
      if(!normal_equations) return;
      const Eigen::Map<const Rows> J(rows, kept, n);
      const Eigen::Map<const Eigen::VectorXd> f(values, kept);
      out.A.setZero();
      out.A.template selfadjointView<Eigen::Lower>().rankUpdate(J.transpose());
      out.g.noalias() = J.transpose() * f;
    };
    for_each_block<ConcurrencyTag>(m, block_size, run);
    double total = 0.;
    if(normal_equations)
    {
      A->setZero();
      g->setZero();
    }
    for(std::size_t b = 0; b < blocks; ++b)
    {
      total += m_block_sums[b].cost;
      if(normal_equations)
      {
        *A += m_block_sums[b].A;
        *g += m_block_sums[b].g;
      }
    }
    if(normal_equations) *A = A->template selfadjointView<Eigen::Lower>();
    return 0.5 * total;
  }

  const std::vector<double>& m_px;
  const std::vector<double>& m_py;
  const std::vector<double>& m_pz;
  const std::vector<double>& m_d;
  const std::vector<double>& m_sw;
  const std::vector<double>& m_clip;
  std::vector<Fit_sdf_block_sums>& m_block_sums;
  double m_R[9];
};

// Buffers reused across fits (one per thread when fits run concurrently).
struct Fit_sdf_workspace
{
  std::vector<double> px, py, pz, d, sqrt_w, clip, volume;
  std::vector<double> dt; // d~ of each active sample at the current parameters (theta0 first)
  std::vector<Fit_sdf_block_sums> block_sums;
  std::vector<unsigned char> interior; // interior regime: Gaussian weight
  Superquadric_solver solver;
};

// The active set P_a = {|d~(theta0)| < 3 tau} of FitSDF in `ws`, with the three weight regimes
// at theta0 (the interior weights are set afterwards) and the two-stage clip of each sample.
inline void select_active_samples(const Fit_samples& P, const Superquadric_data& theta0,
                                  const Fit_sdf_settings& settings, Fit_sdf_workspace& ws)
{
  const double tau = settings.truncation;
  const double near_band = settings.near_surface_fraction * tau;
  ws.px.clear(); ws.py.clear(); ws.pz.clear(); ws.d.clear();
  ws.sqrt_w.clear(); ws.clip.clear(); ws.dt.clear(); ws.interior.clear(); ws.volume.clear();
  for(std::size_t i = 0; i < P.size(); ++i)
  {
    const double p[3] = {P.x[i], P.y[i], P.z[i]};
    const double dt = superquadric_radial_distance(theta0, p);
    if(!(std::abs(dt) < settings.active_multiplier * tau)) continue;
    const double dm = P.d[i];
    double w = 1.;
    bool interior = false;
    if(dm > 0.)
      w = 1. + settings.exterior_penalty * (std::max)(0., -dt) / tau;
    else if(std::abs(dm) < near_band)
      w = 1.;
    else
      interior = true;
    ws.px.push_back(p[0]); ws.py.push_back(p[1]); ws.pz.push_back(p[2]); ws.d.push_back(dm);
    ws.sqrt_w.push_back(std::sqrt(w * P.volume[i]));
    ws.volume.push_back(P.volume[i]);
    ws.clip.push_back(std::abs(dm) < near_band ? near_band : tau);
    ws.dt.push_back(dt);
    ws.interior.push_back(interior ? 1 : 0);
  }
}

// The residual of active sample i at d~ = dt, clipped to its band.
inline double clipped_residual(const Fit_sdf_workspace& ws, std::size_t i, double dt)
{
  const double r = dt - ws.d[i];
  return (std::max)(-ws.clip[i], (std::min)(ws.clip[i], r));
}

// The interior weights of the active samples at their d~ (`ws.dt`) for the variance s2.
inline void set_interior_weights(const Fit_sdf_settings& settings, double s2, Fit_sdf_workspace& ws)
{
  const double tau = settings.truncation, wo = settings.outlier_probability;
  const double C = wo * std::sqrt(2. * CGAL_PI * s2) / ((1. - wo) * tau);
  for(std::size_t i = 0; i < ws.d.size(); ++i)
    if(ws.interior[i])
    {
      const double e = clipped_residual(ws, i, ws.dt[i]);
      const double p = std::exp(-e * e / (2. * s2));
      ws.sqrt_w[i] = std::sqrt(ws.volume[i] * p / (C + p));
    }
}

// The cost sum w r^2 / |P_a| of the active samples at theta.
inline double weighted_cost(const Fit_sdf_workspace& ws, const Superquadric_data& theta)
{
  const std::size_t m = ws.d.size();
  double cost = 0.;
  for(std::size_t i = 0; i < m; ++i)
  {
    const double p[3] = {ws.px[i], ws.py[i], ws.pz[i]};
    const double r = clipped_residual(ws, i, superquadric_radial_distance(theta, p));
    cost += ws.sqrt_w[i] * ws.sqrt_w[i] * r * r;
  }
  return cost / double(m);
}

// FitSDF (paper Alg. A.3): active set at theta0, the three weight regimes, two-stage residual
// clipping, bounded least squares with x_scale(a) = eta.
//
// The paper does not say how the variance of the interior Gaussian weight is set. With
// reestimate_variance, the MPS rule: sigma^2 is re-estimated as sum w r^2 / sum w over P_a after
// each outer pass and the interior weights are recomputed at the current parameters. Otherwise
// (one shot) sigma^2 and all weights are computed once at theta0 and a single solve runs. In both
// modes the first sigma^2 is the mean squared clipped residual at theta0 (MPS starts from e^{2T},
// a units accident that makes the first interior weights vanish).
template <typename ConcurrencyTag>
Fit_sdf_result fit_sdf(const Fit_samples& P, const Superquadric_data& theta0,
                       const Superquadric_vector& lb, const Superquadric_vector& ub,
                       const Fit_sdf_settings& settings, Fit_sdf_workspace& ws)
{
  Fit_sdf_result result;
  result.theta = theta0;
  const double tau = settings.truncation;
  select_active_samples(P, theta0, settings, ws);
  const std::size_t m = ws.d.size();
  result.active = m;
  if(m < std::size_t(superquadric_number_of_parameters)) return result;

  // sigma^2 at theta0: mean squared clipped residual, floored at a tiny fraction of tau^2.
  double sigma2 = 0.;
  for(std::size_t i = 0; i < m; ++i)
  {
    const double r = clipped_residual(ws, i, ws.dt[i]);
    sigma2 += r * r;
  }
  sigma2 = (std::max)(sigma2 / double(m), 1e-6 * tau * tau);
  set_interior_weights(settings, sigma2, ws);

  Fit_sdf_problem<ConcurrencyTag> problem(ws.px, ws.py, ws.pz, ws.d, ws.sqrt_w, ws.clip, ws.block_sums,
                                          theta0.R);
  Superquadric_vector x = to_vector(theta0);
  Superquadric_solver::Options options;
  options.maximum_evaluations = settings.maximum_evaluations;
  options.ftol = settings.function_tolerance;
  for(int i = 0; i < 3; ++i) options.scale[i] = settings.semi_axis_scale;

  const int passes = settings.reestimate_variance ? (std::max)(1, settings.maximum_outer_iterations) : 1;
  double previous_cost = -1.;
  for(int pass = 0; pass < passes; ++pass)
  {
    const auto report = ws.solver.solve(problem, x, lb, ub, options);
    result.evaluations += report.evaluations;
    ++result.solves;
    if(!report.finite) return result;
    if(pass + 1 == passes) break;
    // MPS: sigma^2 = sum w r^2 / sum w at the new parameters, then new interior weights.
    const Superquadric_data q = problem.shape(x);
    double swr = 0., sw = 0.;
    for(std::size_t i = 0; i < m; ++i)
    {
      const double p[3] = {ws.px[i], ws.py[i], ws.pz[i]};
      ws.dt[i] = superquadric_radial_distance(q, p);
      const double r = clipped_residual(ws, i, ws.dt[i]);
      const double w = ws.sqrt_w[i] * ws.sqrt_w[i];
      swr += w * r * r;
      sw += w;
    }
    const double cost = swr / double(m);
    if(previous_cost >= 0. && std::abs(previous_cost - cost) <= settings.relative_cost_tolerance * cost) break;
    previous_cost = cost;
    sigma2 = (std::max)(swr / (std::max)(sw, 1e-300), 1e-6 * tau * tau);
    set_interior_weights(settings, sigma2, ws);
  }

  result.theta = problem.shape(x);
  result.cost = weighted_cost(ws, result.theta);
  result.valid = std::isfinite(result.cost);
  return result;
}

} // namespace internal
} // namespace Part_decomposition
} // namespace CGAL

#endif // CGAL_PART_DECOMPOSITION_INTERNAL_FIT_SDF_H
