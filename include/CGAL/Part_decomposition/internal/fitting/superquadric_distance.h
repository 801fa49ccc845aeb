// Copyright (c) 2026 The Part_decomposition authors.
// All rights reserved.
//
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Author(s)     : The Part_decomposition authors

#ifndef CGAL_PART_DECOMPOSITION_INTERNAL_SUPERQUADRIC_DISTANCE_H
#define CGAL_PART_DECOMPOSITION_INTERNAL_SUPERQUADRIC_DISTANCE_H

#include <algorithm>
#include <cmath>
#include <cstddef>

namespace CGAL {
namespace Part_decomposition {
namespace internal {

// Exponents below this are clamped: p = 2/eps stays <= 2000, so no power can overflow.
constexpr double superquadric_minimum_exponent = 1e-3;

inline double clamp_exponent(double e)
{
  return (std::min)(2., (std::max)(superquadric_minimum_exponent, e));
}

// The parameters of a superquadric in plain doubles.
// R is row-major and its columns are the local axes in world coordinates: world = c + R * local.
struct Superquadric_data
{
  double a[3] = {1., 1., 1.};
  double e1 = 1., e2 = 1.;
  double R[9] = {1., 0., 0., 0., 1., 0., 0., 0., 1.};
  double c[3] = {0., 0., 0.};

  // local = R^T (p - c)
  void to_local(const double p[3], double x[3]) const
  {
    const double w0 = p[0] - c[0], w1 = p[1] - c[1], w2 = p[2] - c[2];
    x[0] = R[0] * w0 + R[3] * w1 + R[6] * w2;
    x[1] = R[1] * w0 + R[4] * w1 + R[7] * w2;
    x[2] = R[2] * w0 + R[5] * w1 + R[8] * w2;
  }
  void to_world(const double x[3], double p[3]) const
  {
    for(int i = 0; i < 3; ++i)
      p[i] = c[i] + R[3 * i] * x[0] + R[3 * i + 1] * x[1] + R[3 * i + 2] * x[2];
  }
};

// N_p(A,B) = (A^p + B^p)^(1/p), A,B >= 0, p >= 1, computed max-normalised so that no power
// exceeds 1: with m = max, t = min/m, N = m (1 + t^p)^(1/p).
struct P_norm
{
  double N;  // the norm
  double dA; // dN/dA = (A/N)^(p-1)  (0 when A = 0)
  double dB; // dN/dB
  double H;  // entropy of q = ((A/N)^p, (B/N)^p); dN/d(eps) = N H / 2 for p = 2/eps
};

// Below this value of p ln t, t^p / p < 2^-53 and N = m exactly in double; below it for
// (p - 1) ln t, also t^(p-1) (the derivative with respect to the smaller argument) and the entropy
// are below 1e-16. Common for box-like shapes (large p); saves three transcendental calls.
constexpr double p_norm_negligible_log = -40.;

inline double p_norm_value(double A, double B, double p)
{
  const double m = (std::max)(A, B);
  if(!(m > 0.)) return 0.;
  const double t = (std::min)(A, B) / m;
  if(!(t > 0.)) return m;
  const double plt = p * std::log(t);
  if(plt < p_norm_negligible_log) return m;
  return m * std::exp(std::log1p(std::exp(plt)) / p);
}

inline P_norm p_norm(double A, double B, double p)
{
  P_norm out;
  const bool a_max = A >= B;
  const double m = a_max ? A : B;
  if(!(m > 0.))
  {
    out.N = out.dA = out.dB = out.H = 0.;
    return out;
  }
  const double t = (a_max ? B : A) / m;
  const double lt = t > 0. ? std::log(t) : 0.;
  if(!(t > 0.) || (p - 1.) * lt < p_norm_negligible_log)
  {
    out.N = m;
    out.dA = a_max ? 1. : 0.;
    out.dB = a_max ? 0. : 1.;
    out.H = 0.;
    return out;
  }
  const double tp = std::exp(p * lt);
  const double L = std::log1p(tp);
  out.N = m * std::exp(L / p);
  // (m/N)^(p-1) = (N/m) / (1 + t^p); (n/N)^(p-1) = t^(p-1) (m/N)^(p-1)
  const double s = (out.N / m) / (1. + tp);
  const double dm = s;
  const double dn = t > 0. ? (tp / t) * s : 0.;
  // H = -q_m ln q_m - q_n ln q_n with ln q_m = -L, ln q_n = p ln t - L
  const double qn = tp / (1. + tp);
  out.H = L - (tp > 0. ? qn * p * lt : 0.);
  out.dA = a_max ? dm : dn;
  out.dB = a_max ? dn : dm;
  return out;
}

inline double sign_of(double v) { return v > 0. ? 1. : (v < 0. ? -1. : 0.); }

// g(x) = N_{2/e1}(N_{2/e2}(|x|/ax, |y|/ay), |z|/az): the gauge of the superquadric (g^(2/e1) is the
// usual inside-outside function F), for a local point.
inline double superquadric_gauge(const Superquadric_data& q, const double x[3])
{
  const double p1 = 2. / clamp_exponent(q.e1), p2 = 2. / clamp_exponent(q.e2);
  const double h = p_norm_value(std::abs(x[0]) / q.a[0], std::abs(x[1]) / q.a[1], p2);
  return p_norm_value(h, std::abs(x[2]) / q.a[2], p1);
}

// The radial signed distance d~ = r (1 - 1/g(x)) of a world point: the signed distance along the
// ray from the centre, negative inside. Evaluated on the unit direction u = x/r, where
// g(x) = r g(u), as d~ = r - 1/g(u): nothing overflows, also for eps = 1e-3 or r near 0.
// At the centre itself d~ is direction-dependent; -min(a) is returned.
inline double superquadric_radial_distance(const Superquadric_data& q, const double p[3])
{
  double x[3];
  q.to_local(p, x);
  const double r = std::sqrt(x[0] * x[0] + x[1] * x[1] + x[2] * x[2]);
  if(!(r > 0.)) return -(std::min)({q.a[0], q.a[1], q.a[2]});
  const double u[3] = {x[0] / r, x[1] / r, x[2] / r};
  return r - 1. / superquadric_gauge(q, u);
}

// Number of parameters and their order in Jacobian rows: (ax, ay, az, e1, e2, dx, dy, dz, cx, cy, cz),
// where (dx,dy,dz) is a body-frame rotation increment, R <- R Exp(d).
constexpr int superquadric_number_of_parameters = 11;

// d~ and its gradient with respect to the 11 parameters. Returns d~; J is 0 at the centre.
// Analytic formulas (building blocks in P_norm): with G = dg/d(X,Y,Z) evaluated on u,
//   dd/da_i = -G_i U_i / (a_i g^2),  dd/de1 = H1 / (2 g),  dd/de2 = (dg/dh) h H2 / (2 g^2),
//   grad_x d = u (1 - 1/(r g)) + B / r  with B = (G_i sgn(u_i) / a_i) / g^2,
//   dd/d(rotation increment) = B x u,  dd/dc = -R grad_x d.
inline double superquadric_radial_distance_and_gradient(const Superquadric_data& q, const double p[3],
                                                        double J[11])
{
  double x[3];
  q.to_local(p, x);
  const double r = std::sqrt(x[0] * x[0] + x[1] * x[1] + x[2] * x[2]);
  if(!(r > 0.))
  {
    std::fill(J, J + 11, 0.);
    return -(std::min)({q.a[0], q.a[1], q.a[2]});
  }
  const double u[3] = {x[0] / r, x[1] / r, x[2] / r};
  const double p1 = 2. / clamp_exponent(q.e1), p2 = 2. / clamp_exponent(q.e2);
  const double U[3] = {std::abs(u[0]) / q.a[0], std::abs(u[1]) / q.a[1], std::abs(u[2]) / q.a[2]};
  const P_norm n2 = p_norm(U[0], U[1], p2);   // h
  const P_norm n1 = p_norm(n2.N, U[2], p1);   // g
  const double g = n1.N, h = n2.N;
  const double ig = 1. / g, ig2 = ig * ig;
  const double G[3] = {n1.dA * n2.dA, n1.dA * n2.dB, n1.dB};

  J[0] = -G[0] * U[0] / q.a[0] * ig2;
  J[1] = -G[1] * U[1] / q.a[1] * ig2;
  J[2] = -G[2] * U[2] / q.a[2] * ig2;
  J[3] = 0.5 * n1.H * ig;
  J[4] = 0.5 * n1.dA * h * n2.H * ig2;

  const double B[3] = {G[0] * sign_of(u[0]) / q.a[0] * ig2, G[1] * sign_of(u[1]) / q.a[1] * ig2,
                       G[2] * sign_of(u[2]) / q.a[2] * ig2};
  J[5] = B[1] * u[2] - B[2] * u[1];
  J[6] = B[2] * u[0] - B[0] * u[2];
  J[7] = B[0] * u[1] - B[1] * u[0];

  const double radial = 1. - ig / r, ir = 1. / r;
  const double gx[3] = {u[0] * radial + B[0] * ir, u[1] * radial + B[1] * ir, u[2] * radial + B[2] * ir};
  for(int i = 0; i < 3; ++i)
    J[8 + i] = -(q.R[3 * i] * gx[0] + q.R[3 * i + 1] * gx[1] + q.R[3 * i + 2] * gx[2]);
  return r - ig;
}

// R <- R Exp(d) (Rodrigues), re-orthonormalised so that long chains of updates stay rotations.
inline void apply_rotation_increment(double R[9], const double d[3])
{
  const double th2 = d[0] * d[0] + d[1] * d[1] + d[2] * d[2];
  const double th = std::sqrt(th2);
  double A, Bc;
  if(th < 1e-8)
  {
    A = 1. - th2 / 6.;
    Bc = 0.5 - th2 / 24.;
  }
  else
  {
    A = std::sin(th) / th;
    Bc = (1. - std::cos(th)) / th2;
  }
  // E = I + A [d]x + Bc [d]x^2
  const double K[9] = {0., -d[2], d[1], d[2], 0., -d[0], -d[1], d[0], 0.};
  double K2[9];
  for(int i = 0; i < 3; ++i)
    for(int j = 0; j < 3; ++j)
      K2[3 * i + j] = K[3 * i] * K[j] + K[3 * i + 1] * K[3 + j] + K[3 * i + 2] * K[6 + j];
  double E[9];
  for(int i = 0; i < 9; ++i) E[i] = A * K[i] + Bc * K2[i] + ((i % 4) == 0 ? 1. : 0.);
  double M[9];
  for(int i = 0; i < 3; ++i)
    for(int j = 0; j < 3; ++j)
      M[3 * i + j] = R[3 * i] * E[j] + R[3 * i + 1] * E[3 + j] + R[3 * i + 2] * E[6 + j];
  // Gram-Schmidt on the columns.
  double col[3][3];
  for(int j = 0; j < 3; ++j)
    for(int i = 0; i < 3; ++i) col[j][i] = M[3 * i + j];
  auto normalize = [](double v[3]) {
    const double n = std::sqrt(v[0] * v[0] + v[1] * v[1] + v[2] * v[2]);
    for(int i = 0; i < 3; ++i) v[i] /= n;
  };
  normalize(col[0]);
  const double d01 = col[0][0] * col[1][0] + col[0][1] * col[1][1] + col[0][2] * col[1][2];
  for(int i = 0; i < 3; ++i) col[1][i] -= d01 * col[0][i];
  normalize(col[1]);
  col[2][0] = col[0][1] * col[1][2] - col[0][2] * col[1][1];
  col[2][1] = col[0][2] * col[1][0] - col[0][0] * col[1][2];
  col[2][2] = col[0][0] * col[1][1] - col[0][1] * col[1][0];
  for(int j = 0; j < 3; ++j)
    for(int i = 0; i < 3; ++i) R[3 * i + j] = col[j][i];
}

// Half extents of the world axis-aligned box of the superquadric (it lies in its local box for
// eps <= 2): e_i = sum_j |R_ij| a_j.
inline void superquadric_half_extents(const Superquadric_data& q, double e[3])
{
  for(int i = 0; i < 3; ++i)
    e[i] = std::abs(q.R[3 * i]) * q.a[0] + std::abs(q.R[3 * i + 1]) * q.a[1] + std::abs(q.R[3 * i + 2]) * q.a[2];
}

// Whether the point of local coordinates x has d~ <= margin (margin >= 0), or g <= 1 when margin
// == 0 (the plain inside test). Any point with |x_l| > a_l + margin is rejected before any power
// is taken (then d~ > margin).
inline bool local_point_within(const Superquadric_data& q, const double x[3], double margin)
{
  if(std::abs(x[0]) > q.a[0] + margin || std::abs(x[1]) > q.a[1] + margin || std::abs(x[2]) > q.a[2] + margin)
    return false;
  // quick accept: the solid contains the octahedron |X|+|Y|+|Z| <= 1, and the ellipsoid
  // X^2+Y^2+Z^2 <= 1 when both exponents are <= 1 (the gauge decreases with p = 2/eps)
  const double X = std::abs(x[0]) / q.a[0], Y = std::abs(x[1]) / q.a[1], Z = std::abs(x[2]) / q.a[2];
  if(X + Y + Z <= 1. || (q.e1 <= 1. && q.e2 <= 1. && X * X + Y * Y + Z * Z <= 1.)) return true;
  if(margin == 0.)
    return p_norm_value(p_norm_value(X, Y, 2. / clamp_exponent(q.e2)), Z, 2. / clamp_exponent(q.e1)) <= 1.;
  const double rr = std::sqrt(x[0] * x[0] + x[1] * x[1] + x[2] * x[2]);
  const double u[3] = {x[0] / rr, x[1] / rr, x[2] / rr}; // rr > 0: the centre passed the quick accept
  return rr - 1. / superquadric_gauge(q, u) <= margin;
}

// Calls f(i, j, k, linear_index) for every voxel of the r-grid of [-0.5,0.5]^3 whose centre is
// within the superquadric (local_point_within()), in increasing linear index. Local coordinates
// are updated incrementally along i.
template <typename F>
void for_each_voxel_within(const Superquadric_data& q, int r, double margin, const F& f)
{
  double e[3];
  superquadric_half_extents(q, e);
  int lo[3], hi[3];
  const double h = 1. / double(r);
  for(int l = 0; l < 3; ++l)
  {
    // voxel centres -0.5 + (i + 0.5) h within [c - e - margin, c + e + margin]
    const double a = (q.c[l] - e[l] - margin + 0.5) / h - 0.5;
    const double b = (q.c[l] + e[l] + margin + 0.5) / h - 0.5;
    lo[l] = (std::max)(0, int(std::ceil(a)));
    hi[l] = (std::min)(r - 1, int(std::floor(b)));
    if(!(a <= b) || lo[l] > hi[l]) return;
  }
  // local step along the world x axis: R^T e_x h = first row of R times h
  const double step[3] = {q.R[0] * h, q.R[1] * h, q.R[2] * h};
  for(int k = lo[2]; k <= hi[2]; ++k)
    for(int j = lo[1]; j <= hi[1]; ++j)
    {
      const double p0[3] = {-0.5 + (lo[0] + 0.5) * h, -0.5 + (j + 0.5) * h, -0.5 + (k + 0.5) * h};
      double x0[3];
      q.to_local(p0, x0);
      std::size_t idx = std::size_t(lo[0]) + std::size_t(r) * (std::size_t(j) + std::size_t(r) * std::size_t(k));
      for(int i = lo[0]; i <= hi[0]; ++i, ++idx)
      {
        const double t = double(i - lo[0]);
        const double x[3] = {x0[0] + t * step[0], x0[1] + t * step[1], x0[2] + t * step[2]};
        if(local_point_within(q, x, margin)) f(i, j, k, idx);
      }
    }
}

// Calls f(world_point) for points on the surface: a grid of spacing <= `spacing` on each face of
// the local box [-a,a]^3, mapped radially onto the surface (s = b / g(b)). The superquadric is
// star-shaped around its centre and lies in its box, so every ray meets the surface once; the
// density is near-uniform on box-like shapes and stays dense on thin plates, unlike direction
// sampling whose density collapses at grazing rays. f returns false to stop early.
template <typename F>
bool for_each_surface_sample(const Superquadric_data& q, double spacing, const F& f)
{
  int n[3];
  for(int l = 0; l < 3; ++l) n[l] = (std::max)(1, int(std::ceil(2. * q.a[l] / spacing)));
  for(int axis = 0; axis < 3; ++axis)
  {
    const int u = (axis + 1) % 3, v = (axis + 2) % 3;
    for(int side = -1; side <= 1; side += 2)
      for(int iu = 0; iu <= n[u]; ++iu)
        for(int iv = 0; iv <= n[v]; ++iv)
        {
          double b[3];
          b[axis] = side * q.a[axis];
          b[u] = -q.a[u] + 2. * q.a[u] * double(iu) / double(n[u]);
          b[v] = -q.a[v] + 2. * q.a[v] * double(iv) / double(n[v]);
          const double g = superquadric_gauge(q, b);
          const double s[3] = {b[0] / g, b[1] / g, b[2] / g};
          double p[3];
          q.to_world(s, p);
          if(!f(p)) return false;
        }
  }
  return true;
}

} // namespace internal
} // namespace Part_decomposition
} // namespace CGAL

#endif // CGAL_PART_DECOMPOSITION_INTERNAL_SUPERQUADRIC_DISTANCE_H
