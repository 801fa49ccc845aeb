// Copyright (c) 2026 The Part_decomposition authors.
// All rights reserved.
//
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Author(s)     : The Part_decomposition authors

// Builds a data set of shapes with known parts for benchmark_segmentation: each shape is the union
// (CGAL corefinement) of 2-6 superquadrics, remeshed isotropically, in four families: `thin`
// (plates, fins and rods of aspect 1:8 to 1:40 on bodies), `boxy` (rounded boxes), `round`
// (ellipsoids) and `mixed`. The whole shape and its parts are posed with random oblique rotations.
// Everything is drawn from a splitmix64 stream seeded per shape: the same files on every run.
//
// Output (default folder bench/data/sq_unions):
//   manifest.tsv     shape, category, faces
//   NAME.off         the surface, written face by face in the order of the .seg file
//   NAME.seg         one label per face: the part whose (meshed) surface is nearest the face centroid
//   NAME.parts.tsv   the true superquadrics (see parts_tsv.h)
//
// Usage: generate_superquadric_unions [output_folder] [--seed S] [--only NAME1,NAME2]
#include <CGAL/Exact_predicates_exact_constructions_kernel.h>
#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Surface_mesh.h>
#include <CGAL/boost/graph/copy_face_graph.h>

#include <CGAL/Polygon_mesh_processing/connected_components.h>
#include <CGAL/Polygon_mesh_processing/corefinement.h>
#include <CGAL/Polygon_mesh_processing/measure.h>
#include <CGAL/Polygon_mesh_processing/orientation.h>
#include <CGAL/Polygon_mesh_processing/polygon_soup_to_polygon_mesh.h>
#include <CGAL/Polygon_mesh_processing/self_intersections.h>
#include <CGAL/Polygon_mesh_processing/shape_predicates.h>
#include <CGAL/boost/graph/helpers.h>

#include "generated_shapes.h"
#include "parts_tsv.h"

#include <algorithm>
#include <array>
#include <chrono>
#include <cmath>
#include <cstdint>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <functional>
#include <iomanip>
#include <iostream>
#include <map>
#include <memory>
#include <sstream>
#include <string>
#include <vector>

namespace PMP = CGAL::Polygon_mesh_processing;
namespace fs = std::filesystem;
typedef CGAL::Exact_predicates_inexact_constructions_kernel K;
typedef K::Point_3 Point;
typedef CGAL::Surface_mesh<Point> Mesh;
// The unions are computed with exact constructions and rounded to double once at the end, not
// after each union.
typedef CGAL::Exact_predicates_exact_constructions_kernel EK;
typedef CGAL::Surface_mesh<EK::Point_3> Exact_mesh;
typedef pd_benchmark::True_primitive Part;
typedef std::array<double, 3> Vec3;
typedef std::array<double, 9> Mat3;

namespace {

const double pi = std::acos(-1.);
const double degree = pi / 180.;

// ------------------------------------------------------------------------------------------
// Random numbers: splitmix64, so that the data set does not depend on the standard library.

class Random
{
public:
  explicit Random(std::uint64_t seed) : m_state(seed) {}
  double uniform()
  {
    std::uint64_t z = (m_state += 0x9E3779B97F4A7C15ull);
    z = (z ^ (z >> 30)) * 0xBF58476D1CE4E5B9ull;
    z = (z ^ (z >> 27)) * 0x94D049BB133111EBull;
    return double((z ^ (z >> 31)) >> 11) * (1. / 9007199254740992.);
  }
  double uniform(double a, double b) { return a + (b - a) * uniform(); }
  // for ratios: as many below the geometric mean as above
  double log_uniform(double a, double b) { return std::exp(uniform(std::log(a), std::log(b))); }
  int integer(int a, int b) { return (std::min)(b, a + int(uniform() * (b - a + 1))); }
  bool coin(double p = 0.5) { return uniform() < p; }

private:
  std::uint64_t m_state;
};

// ------------------------------------------------------------------------------------------
// Rotations: row-major 3x3, column j = local axis j in world coordinates.

Mat3 identity() { return {{1, 0, 0, 0, 1, 0, 0, 0, 1}}; }

Mat3 multiply(const Mat3& a, const Mat3& b)
{
  Mat3 c{};
  for(int i = 0; i < 3; ++i)
    for(int j = 0; j < 3; ++j)
      for(int k = 0; k < 3; ++k) c[3 * i + j] += a[3 * i + k] * b[3 * k + j];
  return c;
}

Vec3 rotated(const Mat3& m, const Vec3& v)
{
  return {{m[0] * v[0] + m[1] * v[1] + m[2] * v[2], m[3] * v[0] + m[4] * v[1] + m[5] * v[2],
           m[6] * v[0] + m[7] * v[1] + m[8] * v[2]}};
}

Vec3 add(const Vec3& a, const Vec3& b, double s = 1.) { return {{a[0] + s * b[0], a[1] + s * b[1], a[2] + s * b[2]}}; }

Vec3 cross(const Vec3& a, const Vec3& b)
{
  return {{a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]}};
}

Vec3 normalized(const Vec3& v)
{
  const double n = std::sqrt(v[0] * v[0] + v[1] * v[1] + v[2] * v[2]);
  return {{v[0] / n, v[1] / n, v[2] / n}};
}

// Rodrigues' formula.
Mat3 axis_angle(const Vec3& axis, double angle)
{
  const Vec3 u = normalized(axis);
  const double c = std::cos(angle), s = std::sin(angle), t = 1. - c;
  return {{t * u[0] * u[0] + c, t * u[0] * u[1] - s * u[2], t * u[0] * u[2] + s * u[1],
           t * u[0] * u[1] + s * u[2], t * u[1] * u[1] + c, t * u[1] * u[2] - s * u[0],
           t * u[0] * u[2] - s * u[1], t * u[1] * u[2] + s * u[0], t * u[2] * u[2] + c}};
}

// The rotation whose columns are x, y and x cross y (x, y orthonormal).
Mat3 frame(const Vec3& x, const Vec3& y)
{
  const Vec3 z = cross(x, y);
  return {{x[0], y[0], z[0], x[1], y[1], z[1], x[2], y[2], z[2]}};
}

// Uniform on SO(3): a uniform unit quaternion (Shoemake 1992).
Mat3 random_rotation(Random& r)
{
  const double u1 = r.uniform(), u2 = 2 * pi * r.uniform(), u3 = 2 * pi * r.uniform();
  const double a = std::sqrt(1 - u1), b = std::sqrt(u1);
  const double w = a * std::sin(u2), x = a * std::cos(u2), y = b * std::sin(u3), z = b * std::cos(u3);
  return {{1 - 2 * (y * y + z * z), 2 * (x * y - z * w), 2 * (x * z + y * w),
           2 * (x * y + z * w), 1 - 2 * (x * x + z * z), 2 * (y * z - x * w),
           2 * (x * z - y * w), 2 * (y * z + x * w), 1 - 2 * (x * x + y * y)}};
}

const Vec3 X = {{1, 0, 0}}, Y = {{0, 1, 0}}, Z = {{0, 0, 1}};

Part sq(const Vec3& c, const Vec3& a, double e1, double e2, const Mat3& R = identity())
{
  Part p;
  p.center = c;
  p.semi_axes = a;
  p.epsilon1 = e1;
  p.epsilon2 = e2;
  p.rotation = R;
  return p;
}

// ------------------------------------------------------------------------------------------
// Superquadric surface: the lattice on the faces of the cube [-1,1]^3 projected along rays from
// the centre onto the unit superquadric, then scaled, rotated and moved. Closed, manifold and
// outward oriented by construction; rays meet a star-shaped surface once, so no fold.

// The point of the surface on the ray through u: F(r u) = r^(2/e1) F(u) = 1.
Vec3 surface_point(const Part& p, const Vec3& u)
{
  const double e1 = p.epsilon1, e2 = p.epsilon2;
  const double xy = std::pow(std::pow(std::abs(u[0]), 2 / e2) + std::pow(std::abs(u[1]), 2 / e2), e2 / e1);
  const double F = xy + std::pow(std::abs(u[2]), 2 / e1);
  const double r = std::pow(F, -e1 / 2);
  const Vec3 local = {{p.semi_axes[0] * r * u[0], p.semi_axes[1] * r * u[1], p.semi_axes[2] * r * u[2]}};
  return add(p.center, rotated(p.rotation, local));
}

// `h`: the target spacing along each semi-axis; at least `minimum` cells per axis.
Mesh superquadric_mesh(const Part& p, double h, int minimum = 4)
{
  int n[3];
  for(int a = 0; a < 3; ++a) n[a] = std::clamp(int(std::ceil(2 * p.semi_axes[a] / h)), minimum, 160);
  // Round shapes: equi-angular spacing on the cube evens out the projection; boxy ones keep the
  // uniform lattice, which is already where their surface lies.
  const double w = std::clamp((std::min(p.epsilon1, p.epsilon2) - 0.3) / 0.7, 0., 1.);
  auto coordinate = [&](int i, int a) {
    const double s = -1. + 2. * i / n[a];
    return (1 - w) * s + w * std::tan(pi / 4 * s);
  };
  std::vector<Point> points;
  std::vector<std::array<std::size_t, 3> > triangles;
  pd_benchmark::lattice_box_soup({{n[0], n[1], n[2]}}, [&](const std::array<int, 3>& c) {
    const Vec3 q = surface_point(p, {{coordinate(c[0], 0), coordinate(c[1], 1), coordinate(c[2], 2)}});
    return Point(q[0], q[1], q[2]);
  }, points, triangles);
  Mesh m;
  PMP::polygon_soup_to_polygon_mesh(points, triangles, m);
  return m;
}

double area_of(const Part& p) { return PMP::area(superquadric_mesh(p, 1e9, 24)); }

// ------------------------------------------------------------------------------------------
// Recipes: the parts of one shape in a design frame of about unit size. Thin parts take their
// thickness from an aspect ratio: plates and fins 1:8 to 1:40, rods 1:8 to 1:30.

double plate_ratio(Random& r) { return r.log_uniform(1. / 40., 1. / 8.); }
double rod_ratio(Random& r) { return r.log_uniform(1. / 30., 1. / 8.); }
double boxy(Random& r) { return r.uniform(0.1, 0.3); }
double roundish(Random& r) { return r.uniform(0.75, 1.); }

// Two plates at an edge, the second leaning by up to 25 degrees. Parts never meet in nearly
// coincident surfaces (here and below): the remeshing would leave slivers there.
std::vector<Part> l_bracket(Random& r)
{
  const double l1 = r.uniform(0.35, 0.5), l2 = r.uniform(0.25, 0.45), w = r.uniform(0.2, 0.35);
  const double t1 = plate_ratio(r) * std::max(l1, w), t2 = plate_ratio(r) * std::max(l2, w);
  std::vector<Part> p = {sq({{0, 0, 0}}, {{l1, w, t1}}, boxy(r), boxy(r))};
  const double theta = r.uniform(-25., 25.) * degree;
  const Vec3 up = {{-std::sin(theta), 0, std::cos(theta)}}; // the second plate's long axis
  // the first plate overhangs the second by 5% of its length; the second ends inside the first
  const Vec3 hinge = {{l1 - t2 - 0.05 * l1, 0, 0}};
  p.push_back(sq(add(hinge, up, l2 - 0.5 * t1), {{l2, w * r.uniform(0.8, 1.), t2}}, boxy(r), boxy(r), frame(up, Y)));
  return p;
}

// A plate standing on the middle of another (a T beam), sometimes with a third on top (I beam).
std::vector<Part> t_beam(Random& r)
{
  const double l = r.uniform(0.4, 0.5), w = r.uniform(0.15, 0.3), h = r.uniform(0.12, 0.25);
  const double ta = plate_ratio(r) * l, tb = plate_ratio(r) * l;
  std::vector<Part> p = {sq({{0, 0, 0}}, {{l, w, ta}}, boxy(r), boxy(r))};
  const double tilt = r.uniform(-15., 15.) * degree;
  const Vec3 up = {{0, -std::sin(tilt), std::cos(tilt)}};
  const Vec3 y0 = {{0, r.uniform(-0.3, 0.3) * w, 0}};
  p.push_back(sq(add(y0, up, h - 0.5 * ta), {{l * r.uniform(0.7, 1.), h, tb}}, boxy(r), boxy(r), frame(X, up)));
  if(r.coin())
  {
    // a flange capping the web: the web's top end inside it
    const double tc = plate_ratio(r) * l;
    p.push_back(sq(add(y0, up, 2 * h - 0.5 * ta - 0.5 * tc), {{l * r.uniform(0.6, 0.9), w * r.uniform(0.6, 1.), tc}},
                   boxy(r), boxy(r), frame(X, cross(up, X))));
  }
  return p;
}

// An ellipsoidal body with a tail fin, maybe a dorsal fin and side fins.
std::vector<Part> finned_body(Random& r)
{
  const double ax = r.uniform(0.4, 0.55), ay = r.uniform(0.13, 0.2), az = r.uniform(0.13, 0.2);
  std::vector<Part> p = {sq({{0, 0, 0}}, {{ax, ay, az}}, r.uniform(0.6, 1.), roundish(r))};
  // vertical fins: local x along the body, local y up, thin across
  const double lf = r.uniform(0.15, 0.25), hf = r.uniform(0.15, 0.25);
  const Mat3 sweep = axis_angle(Y, r.uniform(-20., 20.) * degree);
  p.push_back(sq({{-0.85 * ax - 0.5 * lf, 0, 0.25 * hf}}, {{lf, hf, plate_ratio(r) * std::max(lf, hf)}},
                 r.uniform(0.3, 1.), roundish(r), multiply(sweep, frame(X, Z))));
  if(r.coin())
  {
    const double ld = r.uniform(0.12, 0.2), hd = r.uniform(0.1, 0.16);
    p.push_back(sq({{r.uniform(-0.3, 0.2) * ax, 0, 0.8 * az + 0.7 * hd}}, {{ld, hd, plate_ratio(r) * ld}},
                   r.uniform(0.3, 1.), roundish(r), multiply(axis_angle(Y, r.uniform(-25., 0.) * degree), frame(X, Z))));
  }
  if(r.coin())
  {
    const double lp = r.uniform(0.1, 0.16), wp = r.uniform(0.12, 0.2), tp = plate_ratio(r) * wp, dihedral = r.uniform(-20., 20.) * degree;
    for(int s : {-1, 1})
      p.push_back(sq({{0.3 * ax, s * (0.7 * ay + wp), 0}}, {{lp, wp, tp}}, r.uniform(0.3, 1.), roundish(r),
                     axis_angle(X, s * dihedral)));
  }
  return p;
}

// A sofa: a boxy seat with a thin back leaning backwards and two thin arms.
std::vector<Part> sofa(Random& r)
{
  const double ls = r.uniform(0.4, 0.55), ws = r.uniform(0.22, 0.3), hs = r.uniform(0.08, 0.12);
  std::vector<Part> p = {sq({{0, 0, 0}}, {{ls, ws, hs}}, boxy(r), boxy(r))};
  const double hb = r.uniform(0.2, 0.3), tb = plate_ratio(r) * ls, lean = r.uniform(5., 20.) * degree;
  const Vec3 up = {{0, -std::sin(lean), std::cos(lean)}};
  // back and arms 0.03 inside the seat's sides
  p.push_back(sq(add({{0, -ws + tb + 0.03, 0.2 * hs}}, up, hb), {{ls, hb, tb}}, boxy(r), boxy(r), frame(X, up)));
  const double ha = r.uniform(0.12, 0.2), wa = ws * r.uniform(0.8, 1.), ta = plate_ratio(r) * std::max(ha, wa);
  for(int s : {-1, 1})
    p.push_back(sq({{s * (ls - ta - 0.03), 0.1 * ws, 0.2 * hs + ha}}, {{wa, ha, ta}}, boxy(r), boxy(r), frame(Y, Z)));
  return p;
}

// A round or boxy body with an axle through it, sometimes a second rod across (a spinning top).
std::vector<Part> axle(Random& r)
{
  const double R = r.uniform(0.3, 0.4), h = r.uniform(0.14, 0.24);
  const bool box_body = r.coin(0.3);
  std::vector<Part> p = {sq({{0, 0, 0}}, {{R, R * r.uniform(0.8, 1.), h}}, box_body ? boxy(r) : r.uniform(0.5, 1.),
                            box_body ? boxy(r) : 1.)};
  const double la = r.uniform(0.4, 0.5), ra = rod_ratio(r) * la, tilt = r.uniform(0., 10.) * degree;
  const Mat3 lean = axis_angle(X, tilt);
  p.push_back(sq(rotated(lean, {{0, 0, r.uniform(0., 0.15)}}), {{ra, ra, la}}, boxy(r), 1., lean));
  if(r.coin(0.4))
  {
    const double lc = r.uniform(0.3, 0.45), rc = rod_ratio(r) * lc;
    p.push_back(sq({{0, 0, r.uniform(-0.3, 0.3) * h}}, {{rc, rc, lc}}, boxy(r), 1., frame(Y, Z)));
  }
  return p;
}

// A thin table top on four rods, splayed outwards.
std::vector<Part> table(Random& r)
{
  const double lx = r.uniform(0.42, 0.55), ly = r.uniform(0.28, 0.4), t = plate_ratio(r) * lx;
  std::vector<Part> p = {sq({{0, 0, 0}}, {{lx, ly, t}}, boxy(r), boxy(r))};
  const double hl = r.uniform(0.25, 0.35), rl = rod_ratio(r) * hl, splay = r.uniform(0., 12.) * degree;
  const double e1 = boxy(r);
  for(int sx : {-1, 1})
    for(int sy : {-1, 1})
    {
      const Vec3 top = {{sx * (lx - 2 * rl - 0.04), sy * (ly - 2 * rl - 0.04), 0}};
      const Vec3 down = normalized({{sx * std::sin(splay), sy * std::sin(splay), -std::cos(splay)}});
      const Vec3 side = normalized(cross(down, X));
      p.push_back(sq(add(top, down, hl), {{rl, rl, hl}}, e1, 1., frame(side, cross(down, side))));
    }
  return p;
}

// A hub with two to four pitched blades.
std::vector<Part> propeller(Random& r)
{
  const double rh = r.uniform(0.1, 0.14);
  std::vector<Part> p = {sq({{0, 0, 0}}, {{rh, rh, rh * r.uniform(0.8, 1.2)}}, 1., 1.)};
  const int n = r.integer(2, 4);
  const double lb = r.uniform(0.3, 0.4), wb = r.uniform(0.07, 0.12), pitch = r.uniform(15., 40.) * degree;
  const double t = plate_ratio(r) * lb, e1 = r.uniform(0.3, 0.8), e2 = r.uniform(0.5, 1.);
  for(int k = 0; k < n; ++k)
  {
    const double phi = 2 * pi * k / n;
    const Vec3 radial = {{std::cos(phi), std::sin(phi), 0}};
    const Vec3 across = rotated(axis_angle(radial, pitch), {{-std::sin(phi), std::cos(phi), 0}});
    p.push_back(sq(add({{0, 0, 0}}, radial, 0.5 * rh + lb), {{lb, wb, t}}, e1, e2, frame(radial, across)));
  }
  return p;
}

// A rounded box with one or two rods (antennas) from inside it, pointing obliquely out.
std::vector<Part> antenna_box(Random& r)
{
  const Vec3 a = {{r.uniform(0.25, 0.35), r.uniform(0.2, 0.3), r.uniform(0.15, 0.25)}};
  std::vector<Part> p = {sq({{0, 0, 0}}, a, boxy(r), boxy(r))};
  const int n = r.integer(1, 2);
  for(int k = 0; k < n; ++k)
  {
    const double polar = r.uniform(10., 50.) * degree, azimuth = r.uniform(0., 2 * pi);
    const Vec3 dir = {{std::sin(polar) * std::cos(azimuth), std::sin(polar) * std::sin(azimuth), std::cos(polar)}};
    const double l = r.uniform(0.25, 0.4), rr = rod_ratio(r) * l;
    const Vec3 start = {{r.uniform(-0.5, 0.5) * a[0], r.uniform(-0.5, 0.5) * a[1], 0.6 * a[2]}};
    const Vec3 side = normalized(cross(dir, std::abs(dir[0]) < 0.9 ? X : Y));
    p.push_back(sq(add(start, dir, l), {{rr, rr, l}}, boxy(r), 1., frame(side, cross(dir, side))));
  }
  return p;
}

// Two rounded boxes in an L, the upright one turned and tilted a little.
std::vector<Part> l_block(Random& r)
{
  const Vec3 a = {{r.uniform(0.35, 0.45), r.uniform(0.15, 0.25), r.uniform(0.1, 0.16)}};
  std::vector<Part> p = {sq({{0, 0, 0}}, a, boxy(r), boxy(r))};
  const Vec3 b = {{r.uniform(0.1, 0.16), r.uniform(0.15, 0.25), r.uniform(0.25, 0.35)}};
  const Mat3 turn = multiply(axis_angle(Z, r.uniform(-30., 30.) * degree), axis_angle(Y, r.uniform(-10., 10.) * degree));
  p.push_back(sq({{a[0] - 0.8 * b[0], 0, b[2] + 0.2 * a[2]}}, b, boxy(r), boxy(r), turn));
  return p;
}

// Two or three rounded boxes stacked, each turned about the vertical.
std::vector<Part> stack(Random& r)
{
  Vec3 a = {{r.uniform(0.35, 0.45), r.uniform(0.25, 0.35), r.uniform(0.1, 0.15)}};
  std::vector<Part> p = {sq({{0, 0, 0}}, a, boxy(r), boxy(r))};
  double z = a[2];
  const int n = r.coin(0.6) ? 3 : 2;
  for(int k = 1; k < n; ++k)
  {
    a = {{a[0] * r.uniform(0.5, 0.75), a[1] * r.uniform(0.5, 0.8), r.uniform(0.08, 0.12)}};
    p.push_back(sq({{r.uniform(-0.1, 0.1), r.uniform(-0.05, 0.05), z + 0.75 * a[2]}}, a, boxy(r), boxy(r),
                   axis_angle(Z, r.uniform(0., 45.) * degree)));
    z += 1.5 * a[2];
  }
  return p;
}

// Three bars along three tilted axes through one point.
std::vector<Part> cross_bars(Random& r)
{
  std::vector<Part> p;
  const Mat3 axes[3] = {identity(), frame(Y, Z), frame(Z, X)}; // local x along X, Y, Z
  for(int k = 0; k < 3; ++k)
  {
    const Mat3 tilt = axis_angle({{r.uniform(-1., 1.), r.uniform(-1., 1.), r.uniform(-1., 1.)}}, r.uniform(0., 15.) * degree);
    p.push_back(sq({{r.uniform(-0.03, 0.03), r.uniform(-0.03, 0.03), r.uniform(-0.03, 0.03)}},
                   {{r.uniform(0.35, 0.45), r.uniform(0.08, 0.12), r.uniform(0.08, 0.12)}}, boxy(r), boxy(r),
                   multiply(tilt, axes[k])));
  }
  return p;
}

// Three rounded boxes of rising heights side by side.
std::vector<Part> stairs(Random& r)
{
  std::vector<Part> p;
  const double w = r.uniform(0.12, 0.16), d = r.uniform(0.22, 0.3), step = r.uniform(0.08, 0.12);
  for(int k = 0; k < 3; ++k)
  {
    // bottoms and sides apart: coplanar faces leave slivers in the union
    const double h = 0.08 + step * k;
    p.push_back(sq({{1.7 * w * k, r.uniform(-0.03, 0.03), h + 0.02 * k}}, {{w, d * (1. - 0.08 * k), h}}, boxy(r), boxy(r),
                   axis_angle(Z, r.uniform(-8., 8.) * degree)));
  }
  return p;
}

// A blocky chair: seat, back and four square legs.
std::vector<Part> chair(Random& r)
{
  const double s = r.uniform(0.26, 0.32), hs = r.uniform(0.06, 0.08);
  std::vector<Part> p = {sq({{0, 0, 0}}, {{s, s, hs}}, boxy(r), boxy(r))};
  const double hb = r.uniform(0.22, 0.3), tb = r.uniform(0.05, 0.07), lean = r.uniform(0., 15.) * degree;
  const Vec3 up = {{0, -std::sin(lean), std::cos(lean)}};
  p.push_back(sq(add({{0, -s + 1.8 * tb, 0}}, up, hb), {{0.95 * s, tb, hb}}, boxy(r), boxy(r), frame(X, cross(up, X))));
  const double leg = r.uniform(0.045, 0.06), hl = r.uniform(0.18, 0.24);
  for(int sx : {-1, 1})
    for(int sy : {-1, 1})
      p.push_back(sq({{sx * (s - 1.8 * leg), sy * (s - 1.8 * leg), -hl + 0.5 * hs}}, {{leg, leg, hl}}, boxy(r), boxy(r)));
  return p;
}

// A rounded box with a bar across its top, sometimes a block on its side.
std::vector<Part> box_handle(Random& r)
{
  const Vec3 a = {{r.uniform(0.3, 0.4), r.uniform(0.25, 0.3), r.uniform(0.2, 0.25)}};
  std::vector<Part> p = {sq({{0, 0, 0}}, a, boxy(r), boxy(r))};
  const Vec3 b = {{r.uniform(0.2, 0.28), r.uniform(0.06, 0.08), r.uniform(0.06, 0.08)}};
  p.push_back(sq({{0, 0, a[2] + 0.4 * b[2]}}, b, boxy(r), boxy(r), axis_angle(Z, r.uniform(-40., 40.) * degree)));
  if(r.coin())
  {
    const Vec3 c = {{r.uniform(0.1, 0.14), r.uniform(0.12, 0.18), r.uniform(0.1, 0.15)}};
    p.push_back(sq({{a[0] + 0.6 * c[0], r.uniform(-0.1, 0.1), r.uniform(-0.1, 0.05)}}, c, boxy(r), boxy(r),
                   axis_angle(Y, r.uniform(-20., 20.) * degree)));
  }
  return p;
}

// Three balls stacked, slightly off the vertical.
std::vector<Part> snowman(Random& r)
{
  std::vector<Part> p;
  double radius = r.uniform(0.25, 0.3), z = 0.;
  for(int k = 0; k < 3; ++k)
  {
    if(k > 0)
    {
      const double next = radius * r.uniform(0.6, 0.8);
      z += radius + 0.5 * next;
      radius = next;
    }
    p.push_back(sq({{r.uniform(-0.03, 0.03), r.uniform(-0.03, 0.03), z}},
                   {{radius * r.uniform(0.9, 1.1), radius * r.uniform(0.9, 1.1), radius}}, 1., 1.));
  }
  return p;
}

// Two balls joined by an elongated ellipsoid.
std::vector<Part> dumbbell(Random& r)
{
  const double l = r.uniform(0.4, 0.5), rb = r.uniform(0.07, 0.1);
  std::vector<Part> p = {sq({{0, 0, 0}}, {{l, rb, rb * r.uniform(0.9, 1.1)}}, roundish(r), 1.)};
  for(int s : {-1, 1})
  {
    const double R = r.uniform(0.16, 0.24);
    p.push_back(sq({{s * l * 0.9, 0, 0}}, {{R, R * r.uniform(0.85, 1.), R * r.uniform(0.85, 1.)}}, 1., 1.));
  }
  return p;
}

// A body, a head and four legs, all ellipsoids.
std::vector<Part> animal(Random& r)
{
  const Vec3 b = {{r.uniform(0.35, 0.42), r.uniform(0.15, 0.2), r.uniform(0.14, 0.18)}};
  std::vector<Part> p = {sq({{0, 0, 0}}, b, roundish(r), 1.)};
  const double hr = r.uniform(0.1, 0.14);
  p.push_back(sq({{b[0] + 0.4 * hr, 0, 0.6 * b[2] + 0.5 * hr}}, {{1.2 * hr, hr, hr}}, 1., 1.,
                 axis_angle(Y, r.uniform(-30., 10.) * degree)));
  const double lr = r.uniform(0.05, 0.065), ll = r.uniform(0.16, 0.22);
  for(int sx : {-1, 1})
    for(int sy : {-1, 1})
      p.push_back(sq({{sx * 0.6 * b[0], sy * 0.5 * b[1], -0.5 * b[2] - 0.8 * ll}}, {{lr, lr, ll}}, roundish(r), 1.,
                     axis_angle(Y, sx * r.uniform(0., 15.) * degree)));
  return p;
}

// A ball with two to four smaller ellipsoids sunk into it in spread directions.
std::vector<Part> molecule(Random& r)
{
  const double R = r.uniform(0.2, 0.25);
  std::vector<Part> p = {sq({{0, 0, 0}}, {{R, R, R}}, 1., 1.)};
  const int n = r.integer(2, 4);
  const Mat3 spin = random_rotation(r);
  for(int k = 0; k < n; ++k)
  {
    // directions spread on a spiral, then jittered
    const double zk = 1. - (2. * k + 1.) / n, phi = 2.4 * k + r.uniform(-0.3, 0.3);
    const Vec3 dir = normalized(rotated(spin, {{std::sqrt(1 - zk * zk) * std::cos(phi), std::sqrt(1 - zk * zk) * std::sin(phi), zk}}));
    const double rs = r.uniform(0.1, 0.16);
    const Vec3 side = normalized(cross(dir, std::abs(dir[0]) < 0.9 ? X : Y));
    p.push_back(sq(add({{0, 0, 0}}, dir, R + 0.5 * rs), {{rs, rs, rs * r.uniform(1., 1.5)}}, roundish(r), 1.,
                   frame(side, cross(dir, side))));
  }
  return p;
}

// Three to five ellipsoids along a wavy line.
std::vector<Part> caterpillar(Random& r)
{
  std::vector<Part> p;
  const int n = r.integer(3, 5);
  double x = 0.;
  for(int k = 0; k < n; ++k)
  {
    const Vec3 a = {{r.uniform(0.12, 0.16), r.uniform(0.1, 0.13), r.uniform(0.1, 0.13)}};
    if(k > 0) x += 0.7 * (p.back().semi_axes[0] + a[0]);
    p.push_back(sq({{x, 0.04 * std::sin(2. * k), 0.05 * std::cos(1.7 * k)}}, a, roundish(r), 1.,
                   axis_angle(Z, r.uniform(-20., 20.) * degree)));
  }
  return p;
}

// A round-ended stem under a flat cap.
std::vector<Part> mushroom(Random& r)
{
  const double rs = r.uniform(0.07, 0.11), hs = r.uniform(0.2, 0.3);
  std::vector<Part> p = {sq({{0, 0, 0}}, {{rs, rs, hs}}, r.uniform(0.15, 0.3), 1.)};
  const double rc = r.uniform(0.28, 0.35), hc = r.uniform(0.1, 0.16);
  p.push_back(sq({{0, 0, hs + 0.2 * hc}}, {{rc, rc * r.uniform(0.9, 1.), hc}}, r.uniform(0.6, 1.), 1.,
                 axis_angle(X, r.uniform(-15., 15.) * degree)));
  return p;
}

// A flat base, a thin rod and a shade at its top.
std::vector<Part> lamp(Random& r)
{
  const double bs = r.uniform(0.2, 0.25), bh = r.uniform(0.04, 0.06);
  std::vector<Part> p = {sq({{0, 0, 0}}, {{bs, bs * r.uniform(0.8, 1.), bh}}, boxy(r), boxy(r))};
  const double h = r.uniform(0.3, 0.4), rr = rod_ratio(r) * h, tilt = r.uniform(-15., 15.) * degree;
  const Vec3 up = {{std::sin(tilt), 0, std::cos(tilt)}};
  p.push_back(sq(add({{0, 0, 0}}, up, h), {{rr, rr, h}}, boxy(r), 1., frame(Y, cross(Y, up))));
  const double sr = r.uniform(0.14, 0.2), sh = r.uniform(0.1, 0.14);
  p.push_back(sq(add({{0, 0, 0}}, up, 2 * h + 0.3 * sh), {{sr, sr, sh}}, r.uniform(0.3, 1.), 1.));
  return p;
}

// A long body, a nose and three thin fins at the tail.
std::vector<Part> rocket(Random& r)
{
  const double rb = r.uniform(0.09, 0.12), hb = r.uniform(0.35, 0.42);
  std::vector<Part> p = {sq({{0, 0, 0}}, {{rb, rb, hb}}, r.uniform(0.3, 0.6), 1.)};
  p.push_back(sq({{0, 0, hb}}, {{0.9 * rb, 0.9 * rb, r.uniform(0.15, 0.22)}}, 1., 1.));
  const double lf = r.uniform(0.1, 0.14), hf = r.uniform(0.12, 0.18), t = plate_ratio(r) * hf;
  const double phase = r.uniform(0., 2 * pi);
  for(int k = 0; k < 3; ++k)
  {
    const Vec3 radial = {{std::cos(phase + 2 * pi * k / 3), std::sin(phase + 2 * pi * k / 3), 0}};
    p.push_back(sq(add({{0, 0, -hb + 0.8 * hf}}, radial, 0.7 * rb + lf), {{lf, hf, t}}, boxy(r), r.uniform(0.3, 1.),
                   frame(radial, Z)));
  }
  return p;
}

// A rounded box with one or two balls sunk into its faces.
std::vector<Part> box_ball(Random& r)
{
  const Vec3 a = {{r.uniform(0.3, 0.35), r.uniform(0.25, 0.3), r.uniform(0.2, 0.25)}};
  std::vector<Part> p = {sq({{0, 0, 0}}, a, boxy(r), boxy(r))};
  const int n = r.coin() ? 2 : 1;
  for(int k = 0; k < n; ++k)
  {
    const int axis = k == 0 ? 2 : 0;
    const double R = r.uniform(0.14, 0.2);
    Vec3 c = {{r.uniform(-0.3, 0.3) * a[0], r.uniform(-0.3, 0.3) * a[1], r.uniform(-0.3, 0.3) * a[2]}};
    c[axis] = a[axis] + 0.5 * R;
    p.push_back(sq(c, {{R, R, R * r.uniform(0.8, 1.)}}, 1., 1.));
  }
  return p;
}

// A rod handle with a boxy head across its end.
std::vector<Part> hammer(Random& r)
{
  const double l = r.uniform(0.35, 0.45), rr = l * r.uniform(1. / 14., 1. / 6.);
  std::vector<Part> p = {sq({{0, 0, 0}}, {{rr, rr, l}}, boxy(r), 1.)};
  const Vec3 h = {{r.uniform(0.2, 0.25), r.uniform(0.07, 0.09), r.uniform(0.07, 0.09)}};
  p.push_back(sq({{0, 0, l - 0.3 * h[2]}}, h, boxy(r), boxy(r), axis_angle(Z, r.uniform(-20., 20.) * degree)));
  return p;
}

struct Recipe
{
  std::string name, category;
  std::function<std::vector<Part>(Random&)> make;
  int count;
};

// 40 shapes: 14 thin, 8 boxy, 8 round, 10 mixed.
std::vector<Recipe> recipes()
{
  return {{"bracket", "thin", l_bracket, 2}, {"tbeam", "thin", t_beam, 1},     {"fish", "thin", finned_body, 2},
          {"sofa", "thin", sofa, 2},         {"top", "thin", axle, 2},          {"table", "thin", table, 2},
          {"propeller", "thin", propeller, 2}, {"antenna", "thin", antenna_box, 1},
          {"lblock", "boxy", l_block, 1},    {"stack", "boxy", stack, 2},       {"cross", "boxy", cross_bars, 2},
          {"stairs", "boxy", stairs, 1},     {"chair", "boxy", chair, 1},       {"handle", "boxy", box_handle, 1},
          {"snowman", "round", snowman, 1},  {"dumbbell", "round", dumbbell, 1}, {"animal", "round", animal, 2},
          {"molecule", "round", molecule, 2}, {"caterpillar", "round", caterpillar, 2},
          {"mushroom", "mixed", mushroom, 2}, {"lamp", "mixed", lamp, 2},       {"rocket", "mixed", rocket, 2},
          {"boxball", "mixed", box_ball, 2}, {"hammer", "mixed", hammer, 2}};
}

// ------------------------------------------------------------------------------------------
// From parts to a checked, remeshed, labelled surface.

// Turns the parts by a random rotation about the origin, then scales and moves them so that the bounding box of
// their union is centred at the origin with its longest side 1; returns its diagonal.
double pose(std::vector<Part>& parts, Random& r)
{
  const Mat3 G = random_rotation(r);
  for(Part& p : parts)
  {
    // Each part also turns by 0.3 to 1 degree and moves by up to 0.002: recipes align parts on
    // symmetry planes, where the lattices of two parts cross the intersection curve at the same
    // points, and the union then rounds distinct points to one.
    const Mat3 jitter = axis_angle({{r.uniform(-1, 1), r.uniform(-1, 1), r.uniform(-1, 1)}}, r.uniform(0.3, 1.) * degree);
    const Vec3 shift = {{r.uniform(-0.002, 0.002), r.uniform(-0.002, 0.002), r.uniform(-0.002, 0.002)}};
    p.center = rotated(G, add(p.center, shift));
    p.rotation = multiply(G, multiply(jitter, p.rotation));
  }
  CGAL::Bbox_3 box;
  for(const Part& p : parts) box += PMP::bbox(superquadric_mesh(p, 1e9, 32));
  const double side = std::max({box.xmax() - box.xmin(), box.ymax() - box.ymin(), box.zmax() - box.zmin()});
  const Vec3 mid = {{(box.xmin() + box.xmax()) / 2, (box.ymin() + box.ymax()) / 2, (box.zmin() + box.zmax()) / 2}};
  for(Part& p : parts)
  {
    p.center = add(p.center, mid, -1.);
    for(double& x : p.center) x /= side;
    for(double& a : p.semi_axes) a /= side;
  }
  return std::sqrt(std::pow(box.xmax() - box.xmin(), 2) + std::pow(box.ymax() - box.ymin(), 2) +
                   std::pow(box.zmax() - box.zmin(), 2)) / side;
}

double thinnest_over_diagonal(const std::vector<Part>& parts, double diagonal)
{
  double t = 1e9;
  for(const Part& p : parts) t = std::min(t, 2 * p.smallest_semi_axis() / diagonal);
  return t;
}

// The exact union as a double mesh that depends on its geometry only: the corefinement's order of
// vertices and faces, and the rounding of a lazy number (its interval, or its exact value if some
// predicate needed it), vary from run to run. Points are the exact ones rounded, vertices sorted by
// coordinates, each face starting at its smallest vertex, faces sorted.
Mesh canonical_mesh(const Exact_mesh& exact)
{
  std::vector<std::pair<std::array<double, 3>, std::size_t> > points;
  for(auto v : vertices(exact))
  {
    const auto& p = CGAL::exact(exact.point(v));
    points.push_back({{{CGAL::to_double(p.x()), CGAL::to_double(p.y()), CGAL::to_double(p.z())}}, std::size_t(v)});
  }
  std::sort(points.begin(), points.end());
  std::vector<std::size_t> rank(num_vertices(exact));
  for(std::size_t i = 0; i < points.size(); ++i) rank[points[i].second] = i;
  std::vector<std::array<std::size_t, 3> > triangles;
  for(auto f : faces(exact))
  {
    std::array<std::size_t, 3> t;
    int k = 0;
    for(auto v : vertices_around_face(halfedge(f, exact), exact)) t[k++] = rank[std::size_t(v)];
    std::rotate(t.begin(), std::min_element(t.begin(), t.end()), t.end());
    triangles.push_back(t);
  }
  std::sort(triangles.begin(), triangles.end());
  Mesh m;
  for(const auto& p : points) m.add_vertex(Point(p.first[0], p.first[1], p.first[2]));
  for(const auto& t : triangles)
    m.add_face(Mesh::Vertex_index(t[0]), Mesh::Vertex_index(t[1]), Mesh::Vertex_index(t[2]));
  return m;
}

bool sound_part(const Mesh& m)
{
  if(!CGAL::is_valid_polygon_mesh(m) || !CGAL::is_closed(m) || !PMP::is_outward_oriented(m)) return false;
  for(auto f : faces(m))
    if(PMP::is_degenerate_triangle_face(f, m)) return false;
  return !PMP::does_self_intersect(m);
}

struct Built
{
  Mesh mesh;
  std::vector<std::size_t> labels;
  double edge_length = 0., thinnest = 0.; // thinnest: the smallest thickness 2 min(a) of a part
  std::string why_not;                     // empty on success
};

// Meshes the parts, unites them and remeshes the union to ~21k faces, or finer if a part is thin
// (edges at most 3/4 of its thickness, at most ~35k faces); checks every step.
Built build(const std::vector<Part>& parts)
{
  Built b;
  b.thinnest = 1e9;
  for(const Part& p : parts) b.thinnest = std::min(b.thinnest, 2 * p.smallest_semi_axis());
  const double h = 0.015; // along the large semi-axes; thin ones get 4 or 6 cells across anyway
  std::vector<Mesh> meshes;
  for(const Part& p : parts)
  {
    meshes.push_back(superquadric_mesh(p, h, p.epsilon1 > 0.5 ? 6 : 4));
    if(!sound_part(meshes.back())) { b.why_not = "a part mesh is not sound"; return b; }
  }
  Exact_mesh exact;
  CGAL::copy_face_graph(meshes.front(), exact);
  for(std::size_t i = 1; i < meshes.size(); ++i)
  {
    Exact_mesh next, out;
    CGAL::copy_face_graph(meshes[i], next);
    if(!PMP::corefine_and_compute_union(exact, next, out)) { b.why_not = "union failed"; return b; }
    exact = std::move(out);
  }
  exact.collect_garbage();
  b.mesh = canonical_mesh(exact);
  if(num_faces(b.mesh) != num_faces(exact)) { b.why_not = "union not manifold"; return b; }
  if(!CGAL::is_closed(b.mesh)) { b.why_not = "union not closed"; return b; }
  if(PMP::does_self_intersect(b.mesh)) { b.why_not = "union self-intersects"; return b; }
  auto component = b.mesh.add_property_map<Mesh::Face_index, std::size_t>("f:component", 0).first;
  const std::size_t components = PMP::connected_components(b.mesh, component);
  b.mesh.remove_property_map(component);
  if(components != 1) { b.why_not = std::to_string(components) + " components"; return b; }

  const double area = PMP::area(b.mesh), per_face = std::sqrt(3.) / 4.;
  // the remeshing ends with about 4/3 of area / (per_face L^2) faces: ~21k, at most ~35k
  b.edge_length = std::max(std::min(std::sqrt(area / (per_face * 16000.)), 0.75 * b.thinnest),
                           std::sqrt(area / (per_face * 26000.)));
  const Mesh united = b.mesh;
  // a self-intersection (two sides of a thin part meeting): once more slightly finer, then give up
  // (the caller draws new parts), so that the face count stays in range
  for(int retry = 0; retry < 2; ++retry, b.edge_length *= 0.85)
  {
    b.mesh = united;
    pd_benchmark::remesh_keeping_creases(b.mesh, b.edge_length);
    if(CGAL::is_closed(b.mesh) && !PMP::does_self_intersect(b.mesh)) break;
    if(retry == 1) { b.why_not = "remeshing self-intersects"; return b; }
  }
  for(auto f : faces(b.mesh))
    if(PMP::is_degenerate_triangle_face(f, b.mesh)) { b.why_not = "degenerate face after remeshing"; return b; }

  b.labels = pd_benchmark::nearest_part_labels(b.mesh, meshes);
  std::vector<std::size_t> count(parts.size(), 0);
  for(std::size_t l : b.labels) ++count[l];
  for(std::size_t i = 0; i < parts.size(); ++i)
    if(count[i] < 30) { b.why_not = "part " + std::to_string(i) + " has " + std::to_string(count[i]) + " faces"; return b; }
  return b;
}

// Written by hand so that the face order of the file is the order of faces() and of the labels.
void write_off(const std::string& file, const Mesh& m)
{
  std::ofstream out(file);
  out << "OFF\n" << num_vertices(m) << ' ' << num_faces(m) << " 0\n" << std::setprecision(9);
  for(auto v : vertices(m)) out << m.point(v).x() << ' ' << m.point(v).y() << ' ' << m.point(v).z() << '\n';
  for(auto f : faces(m))
  {
    out << '3';
    for(auto v : vertices_around_face(halfedge(f, m), m)) out << ' ' << std::size_t(v);
    out << '\n';
  }
}

} // namespace

int main(int argc, char** argv)
{
  std::string folder = "bench/data/sq_unions";
  std::uint64_t seed = 17;
  std::vector<std::string> only;
  for(int i = 1; i < argc; ++i)
  {
    const std::string a = argv[i];
    if(a == "--seed" && i + 1 < argc) seed = std::strtoull(argv[++i], nullptr, 10);
    else if(a == "--only" && i + 1 < argc) only = pd_benchmark::split(argv[++i], ',');
    else if(!a.empty() && a[0] != '-') folder = a;
    else
    {
      std::cerr << "usage: generate_superquadric_unions [output_folder] [--seed S] [--only NAME1,NAME2]\n";
      return 2;
    }
  }
  fs::create_directories(folder);
  std::ofstream manifest(fs::path(folder) / "manifest.tsv");
  manifest << "shape\tcategory\tfaces\n";
  std::size_t index = 0, written = 0, skipped = 0;
  for(const Recipe& recipe : recipes())
    for(int k = 0; k < recipe.count; ++k, ++index)
    {
      std::ostringstream name;
      name << "sq" << std::setw(2) << std::setfill('0') << index << '_' << recipe.category << '_' << recipe.name;
      if(!only.empty() && std::find(only.begin(), only.end(), name.str()) == only.end()) continue;
      const auto t0 = std::chrono::steady_clock::now();
      Built b;
      std::vector<Part> parts;
      double diagonal = 0.;
      int attempt = 0;
      for(; attempt < 6; ++attempt)
      {
        // one stream per shape and attempt: a shape does not change when another one is retried
        Random r(seed * 0x100000001B3ull + 1000 * index + attempt);
        parts = recipe.make(r);
        diagonal = pose(parts, r);
        if(thinnest_over_diagonal(parts, diagonal) < 0.008) { b.why_not = "a part thinner than 0.008 diagonal"; }
        else try { b = build(parts); }
        catch(const std::exception& e) { b.why_not = std::string("exception: ") + e.what(); }
        if(b.why_not.empty()) break;
        std::cerr << name.str() << " attempt " << attempt << ": " << b.why_not << "\n";
      }
      if(!b.why_not.empty()) { ++skipped; continue; }

      for(std::size_t i = 0; i < parts.size(); ++i)
      {
        parts[i].id = i;
        parts[i].thin = pd_benchmark::is_thin(parts[i].semi_axes);
        parts[i].thickness_over_diagonal = 2 * parts[i].smallest_semi_axis() / diagonal;
      }
      const std::string stem = (fs::path(folder) / name.str()).string();
      write_off(stem + ".off", b.mesh);
      std::ofstream seg(stem + ".seg");
      for(std::size_t l : b.labels) seg << l << '\n';
      std::ofstream tsv(stem + ".parts.tsv");
      pd_benchmark::write_parts_tsv(tsv, parts);
      manifest << name.str() << '\t' << recipe.category << '\t' << num_faces(b.mesh) << '\n';
      ++written;

      std::size_t thin = 0;
      for(const Part& p : parts) thin += p.thin ? 1 : 0;
      std::cout << name.str() << ": " << parts.size() << " parts (" << thin << " thin), " << num_faces(b.mesh)
                << " faces, thinnest / diagonal " << std::setprecision(3) << b.thinnest / diagonal
                << ", edge / thinnest " << b.edge_length / b.thinnest << ", attempt " << attempt << ", "
                << std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count() << " s" << std::endl;
    }
  std::cout << written << " shapes written to " << folder << ", " << skipped << " skipped\n";
  return skipped == 0 ? EXIT_SUCCESS : EXIT_FAILURE;
}
