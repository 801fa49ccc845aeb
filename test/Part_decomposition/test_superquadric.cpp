// Tests of the superquadric type, its stable distance and Jacobian, its leaves on an adaptive
// grid, the bounded least-squares solver, FitSDF (Alg. A.3) and SDFSQFit (Alg. A.2) on the
// adaptive and the uniform grids.
#include <CGAL/Part_decomposition/Adaptive_grid.h>
#include <CGAL/Part_decomposition/Superquadric.h>
#include <CGAL/Part_decomposition/flow_freeze_prior.h>
#include <CGAL/Part_decomposition/superquadric_fitting.h>
#include <CGAL/Part_decomposition/tsdf.h>
#include <CGAL/Part_decomposition/internal/fitting/bounded_least_squares.h>
#include <CGAL/Part_decomposition/internal/fitting/fit_sdf.h>
#include <CGAL/Part_decomposition/internal/fitting/superquadric_distance.h>
#include <CGAL/Part_decomposition/internal/fitting/superquadric_leaves.h>

#include <CGAL/AABB_face_graph_triangle_primitive.h>
#include <CGAL/AABB_traits.h>
#include <CGAL/AABB_tree.h>
#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Polygon_mesh_processing/measure.h>
#include <CGAL/Polygon_mesh_processing/orientation.h>
#include <CGAL/Surface_mesh.h>
#include <CGAL/boost/graph/helpers.h>

#include <catch2/catch.hpp>

#include "method_switches.h"
#include "test_shapes.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <memory>
#include <random>
#include <vector>

namespace PD = CGAL::Part_decomposition;
namespace PDI = CGAL::Part_decomposition::internal;
typedef CGAL::Exact_predicates_inexact_constructions_kernel K;
typedef K::Point_3 Point;
typedef PD::Superquadric<K> SQ;

namespace {

std::array<double, 9> rotation_matrix(std::array<double, 3> axis, double angle)
{
  const double n = std::sqrt(axis[0] * axis[0] + axis[1] * axis[1] + axis[2] * axis[2]);
  for(double& v : axis) v /= n;
  const double c = std::cos(angle), s = std::sin(angle), x = axis[0], y = axis[1], z = axis[2];
  return {{c + x * x * (1 - c), x * y * (1 - c) - z * s, x * z * (1 - c) + y * s,
           y * x * (1 - c) + z * s, c + y * y * (1 - c), y * z * (1 - c) - x * s,
           z * x * (1 - c) - y * s, z * y * (1 - c) + x * s, c + z * z * (1 - c)}};
}

std::array<double, 9> random_rotation(std::mt19937& rng)
{
  std::uniform_real_distribution<double> u(-1., 1.), ang(0., 3.1);
  return rotation_matrix({{u(rng), u(rng), u(rng)}}, ang(rng));
}

PDI::Superquadric_data make_data(std::array<double, 3> a, double e1, double e2, const std::array<double, 9>& R,
                                 std::array<double, 3> c)
{
  PDI::Superquadric_data q;
  for(int i = 0; i < 3; ++i) q.a[i] = a[i], q.c[i] = c[i];
  q.e1 = e1;
  q.e2 = e2;
  std::copy(R.begin(), R.end(), q.R);
  return q;
}

struct Reference_case
{
  std::array<double, 3> a;
  double e1, e2;
  std::array<double, 9> R;
  std::array<double, 3> c, p;
  double d; // 60-digit mpmath value of r (1 - F^(-e1/2)), rounded
};

// Hard points (tiny exponents, points within 1e-12 .. 1e-8 of the centre, exponent 2), reference
// values computed once with mpmath at 60 digits from the naive formula on the same doubles.
const Reference_case reference_cases[] = {
  {{0.2, 0.1, 0.05}, 0.003, 0.003, {1.0, 0, 0, 0, 1.0, 0, 0, 0, 1.0}, {0, 0, 0}, {0.15, 0.08, 0.03}, -0.04315669125408017832076837},
  {{0.2, 0.1, 0.05}, 0.003, 0.003, {1.0, 0, 0, 0, 1.0, 0, 0, 0, 1.0}, {0, 0, 0}, {0.25, 0.05, 0.01}, 0.05102940328869228365769071},
  {{0.2, 0.1, 0.05}, 0.001, 0.001, {1.0, 0, 0, 0, 1.0, 0, 0, 0, 1.0}, {0, 0, 0}, {0.199, 0.0999, 0.0499}, -0.0002139311384009973602022762},
  {{0.2, 0.1, 0.05}, 0.001, 0.001, {1.0, 0, 0, 0, 1.0, 0, 0, 0, 1.0}, {0, 0, 0}, {0.3, 0.2, 0.1}, 0.1871476960861354775497554},
  {{0.3, 0.2, 0.1}, 1.9, 0.05, {1.0, 0, 0, 0, 1.0, 0, 0, 0, 1.0}, {0, 0, 0}, {3e-10, 5e-10, 8e-10}, -0.09687319991987370211627651},
  {{0.3, 0.2, 0.1}, 0.5, 0.5, {1.0, 0, 0, 0, 1.0, 0, 0, 0, 1.0}, {0, 0, 0}, {1e-12, -2e-12, 3e-12}, -0.1243352321095192219436355},
  {{0.3, 0.2, 0.1}, 0.001, 0.001, {1.0, 0, 0, 0, 1.0, 0, 0, 0, 1.0}, {0, 0, 0}, {1e-10, 1e-10, 1e-10}, -0.1732050805836826582106703},
  {{0.3, 0.2, 0.1}, 2.0, 2.0, {1.0, 0, 0, 0, 1.0, 0, 0, 0, 1.0}, {0, 0, 0}, {0.1, 0.05, 0.02}, -0.03141523765761853215490692},
  {{0.3, 0.2, 0.1}, 2.0, 2.0, {1.0, 0, 0, 0, 1.0, 0, 0, 0, 1.0}, {0, 0, 0}, {0.4, -0.3, 0.2}, 0.4270992778072192963272858},
  {{0.3, 0.2, 0.1}, 0.001, 2.0, {1.0, 0, 0, 0, 1.0, 0, 0, 0, 1.0}, {0, 0, 0}, {0.2, 0.1, 0.05}, 0.03273268353539886938996612},
  {{0.3, 0.2, 0.1}, 2.0, 0.001, {1.0, 0, 0, 0, 1.0, 0, 0, 0, 1.0}, {0, 0, 0}, {-0.2, 0.15, 0.05}, 0.05099019513592783817571408},
  {{0.05, 0.05, 1.0}, 0.01, 1.0, {1.0, 0, 0, 0, 1.0, 0, 0, 0, 1.0}, {0, 0, 0}, {0.04, 0.01, 0.9}, -0.1001048831426845581693332},
  {{0.5, 0.025, 0.5}, 0.1, 0.1, {1.0, 0, 0, 0, 1.0, 0, 0, 0, 1.0}, {0, 0, 0}, {0.3, 0.03, -0.2}, 0.06030018943141678270073971},
  {{0.2, 0.2, 0.2}, 1.0, 1.0, {1.0, 0, 0, 0, 1.0, 0, 0, 0, 1.0}, {0, 0, 0}, {0.001, 0.002, 0.35}, 0.1500071427842580138983356},
  {{0.2, 0.1, 0.05}, 0.002, 1.5, {1.0, 0, 0, 0, 1.0, 0, 0, 0, 1.0}, {0, 0, 0}, {0.0, 0.0, 0.07}, 0.02000000000000000388578059},
  {{0.3, 0.05, 0.15}, 1.95, 0.001, {0.9806349312562712, -0.06939746096306937, -0.18313689964583216, 0.0858622509212019, 0.9927972177053997, 0.08355452341532206, 0.17601933265057249, -0.09766103075585626, 0.9795302535424574}, {0.16388162525724093, -0.11412072766573532, -0.16562110652433135}, {0.1147849160796966, -0.2697229275895203, -0.13499275424949989}, 0.1147455402255302697997289},
  {{0.3, 0.05, 0.15}, 0.001, 0.01, {0.3255279271485625, -0.7674464981818618, -0.5523200531166308, 0.5770871130039641, -0.3014626859477006, 0.7590063985144975, -0.749000689352894, -0.5658145645081927, 0.3447489607515797}, {-0.1813669277528975, 0.14338738361947184, -0.0841562854673295}, {-0.18136693486779584, 0.14338737597531662, -0.08415628929769302}, -0.05599695329282657249701728},
  {{0.1, 0.05, 0.01}, 1.95, 0.001, {0.30265750942489184, -0.816237607123617, -0.49209206527420624, -0.4800253640215, 0.3154991149184971, -0.8185572419700846, 0.8233918155317965, 0.4839591689417168, -0.29632657814056224}, {0.04760383726942155, -0.0014342019546032814, 0.012688098632074263}, {0.21394110225790572, -0.022073082450798892, 0.26675292881539114}, 0.2859679197885518674124616},
  {{0.02, 0.2, 0.15}, 0.05, 1.99, {-0.5196318528185169, 0.8542711826399543, -0.014264783465909592, -0.2160970827103068, -0.11525681419704747, 0.9695452117489117, 0.8266104211661562, 0.5068891528648855, 0.24449662232314928}, {-0.0848248940439254, 0.19206993899703284, -0.15277368869801516}, {-0.08482489568146896, 0.19206994413985143, -0.15277369565832447}, -0.02686740829401968043007886},
  {{0.3, 0.2, 0.15}, 2.0, 0.5, {-0.6607336162362238, -0.2219848773500851, -0.7170451886759092, 0.29218521326786207, 0.803864635273193, -0.518101775044933, 0.6914180280575685, -0.5518372607798101, -0.46627968869769515}, {0.03774795084200738, 0.03195808171299688, -0.01751786747943479}, {0.24172861914953225, 0.2987667387777594, -0.0330588650276481}, 0.2134208146422313820551607},
  {{0.3, 0.2, 0.15}, 2.0, 1.99, {-0.22129461691879432, -0.7449608892425919, -0.6293345422123682, -0.009082677350130186, 0.6468807607808884, -0.7625370720848219, 0.9751647027527799, -0.16302930666118293, -0.1499174695446014}, {0.15481611689523672, -0.061197897724619754, 0.17625942665843752}, {0.15481611400451892, -0.06119789550622889, 0.17625942653229743}, -0.1765700657147263587799608},
};

} // namespace

TEST_CASE("stable radial distance matches high-precision references", "[superquadric]")
{
  for(const Reference_case& rc : reference_cases)
  {
    const PDI::Superquadric_data q = make_data(rc.a, rc.e1, rc.e2, rc.R, rc.c);
    const double p[3] = {rc.p[0], rc.p[1], rc.p[2]};
    const double d = PDI::superquadric_radial_distance(q, p);
    INFO("eps " << rc.e1 << " " << rc.e2 << " expected " << rc.d << " got " << d);
    CHECK(std::abs(d - rc.d) <= 1e-12 * std::abs(rc.d) + 1e-15);
    double J[11];
    const double d2 = PDI::superquadric_radial_distance_and_gradient(q, p, J);
    CHECK(d2 == Approx(d).epsilon(1e-14));
    for(double v : J) CHECK(std::isfinite(v));
  }
}

TEST_CASE("radial distance identities", "[superquadric]")
{
  std::mt19937 rng(11);
  std::uniform_real_distribution<double> u(-0.4, 0.4);
  const double eps[] = {1e-3, 0.01, 0.1, 0.5, 1., 1.5, 1.9, 2.};
  // sphere: d = |p - c| - a
  for(int t = 0; t < 200; ++t)
  {
    const auto R = random_rotation(rng);
    const PDI::Superquadric_data q = make_data({{0.2, 0.2, 0.2}}, 1., 1., R, {{0.05, -0.1, 0.02}});
    const double p[3] = {u(rng), u(rng), u(rng)};
    const double r = std::sqrt((p[0] - 0.05) * (p[0] - 0.05) + (p[1] + 0.1) * (p[1] + 0.1) + (p[2] - 0.02) * (p[2] - 0.02));
    CHECK(PDI::superquadric_radial_distance(q, p) == Approx(r - 0.2).margin(1e-14));
  }
  // on a local axis: d = |x_i| - a_i for every exponent
  const std::array<double, 9> I = {{1, 0, 0, 0, 1, 0, 0, 0, 1}};
  for(double e1 : eps)
    for(double e2 : eps)
      for(int axis = 0; axis < 3; ++axis)
        for(double t : {-0.37, -0.05, 0.01, 0.2, 0.3})
        {
          const PDI::Superquadric_data q = make_data({{0.3, 0.05, 0.15}}, e1, e2, I, {{0., 0., 0.}});
          double p[3] = {0., 0., 0.};
          p[axis] = t;
          CHECK(PDI::superquadric_radial_distance(q, p) == Approx(std::abs(t) - q.a[axis]).margin(1e-15));
        }
  // swapping ax and ay together with a quarter turn about the local z axis changes nothing
  for(int t = 0; t < 200; ++t)
  {
    const auto R = random_rotation(rng);
    const double e1 = eps[t % 8], e2 = eps[(t / 8) % 8];
    const PDI::Superquadric_data q = make_data({{0.3, 0.1, 0.2}}, e1, e2, R, {{0.01, 0.02, 0.03}});
    PDI::Superquadric_data q2 = q;
    std::swap(q2.a[0], q2.a[1]);
    // new local x = old local y, new local y = -old local x
    for(int i = 0; i < 3; ++i)
    {
      q2.R[3 * i] = q.R[3 * i + 1];
      q2.R[3 * i + 1] = -q.R[3 * i];
    }
    const double p[3] = {u(rng), u(rng), u(rng)};
    CHECK(PDI::superquadric_radial_distance(q2, p) ==
          Approx(PDI::superquadric_radial_distance(q, p)).margin(1e-13));
  }
}

TEST_CASE("analytic Jacobian matches central finite differences", "[superquadric]")
{
  std::mt19937 rng(5);
  std::normal_distribution<double> gauss(0., 0.15);
  const double eps[] = {1e-3, 0.01, 0.1, 0.5, 1., 1.5, 1.9, 1.99, 2.};
  const std::array<double, 3> axes[] = {{{0.2, 0.2, 0.2}}, {{0.3, 0.1, 0.05}}, {{0.02, 0.4, 0.1}},
                                        {{0.4, 0.02, 0.4}}, {{0.01, 0.01, 0.2}}};
  std::size_t checked = 0;
  double worst = 0.;
  for(double e1 : eps)
    for(double e2 : eps)
      for(const auto& a : axes)
        for(int t = 0; t < 6; ++t)
        {
          const auto R = random_rotation(rng);
          const std::array<double, 3> c = {{gauss(rng) * 0.3, gauss(rng) * 0.3, gauss(rng) * 0.3}};
          const PDI::Superquadric_data q = make_data(a, e1, e2, R, c);
          double p[3];
          if(t < 4)
            for(int i = 0; i < 3; ++i) p[i] = c[i] + gauss(rng);
          else
          {
            // near a local plane (t = 4) or a local axis (t = 5)
            double x[3] = {gauss(rng), gauss(rng), gauss(rng)};
            x[t % 3] = 1e-2 * a[t % 3];
            if(t == 5) x[(t + 1) % 3] = -2e-2 * a[(t + 1) % 3];
            q.to_world(x, p);
          }
          double x[3];
          q.to_local(p, x);
          const double r = std::sqrt(x[0] * x[0] + x[1] * x[1] + x[2] * x[2]);
          // exclusions: d~ is not differentiable at the centre, nor (for eps near 2) on local planes
          if(r < 1e-3 * std::min({a[0], a[1], a[2]})) continue;
          bool kink = false;
          for(int i = 0; i < 3; ++i)
            if(std::abs(x[i]) < 1e-3 * a[i] && (e1 > 1.8 || e2 > 1.8)) kink = true;
          if(kink) continue;

          double J[11];
          PDI::superquadric_radial_distance_and_gradient(q, p, J);
          for(int k = 0; k < 11; ++k)
          {
            // steps scaled to the thinnest axis: the local curvature of d~ grows like 1/min(a)
            const double amin = std::min({a[0], a[1], a[2]});
            double h;
            if(k < 3) h = 1e-5 * a[k];
            else if(k < 5) h = std::min(1e-6, 1e-3 * (k == 3 ? e1 : e2));
            else if(k < 8) h = 1e-5 * amin / std::max(r, amin);
            else h = 1e-5 * amin;
            auto eval = [&](double s) {
              PDI::Superquadric_data qq = q;
              if(k < 3) qq.a[k] += s;
              else if(k == 3) qq.e1 += s;
              else if(k == 4) qq.e2 += s;
              else if(k < 8)
              {
                double dlt[3] = {0., 0., 0.};
                dlt[k - 5] = s;
                PDI::apply_rotation_increment(qq.R, dlt);
              }
              else qq.c[k - 8] += s;
              return PDI::superquadric_radial_distance(qq, p);
            };
            // one-sided at the upper exponent bound
            double fd;
            if((k == 3 && e1 + 2. * h > 2.) || (k == 4 && e2 + 2. * h > 2.))
              fd = (eval(0.) - eval(-h)) / h;
            else // fourth-order central difference
              fd = (8. * (eval(h) - eval(-h)) - (eval(2. * h) - eval(-2. * h))) / (12. * h);
            const bool one_sided = (k == 3 && e1 + 2. * h > 2.) || (k == 4 && e2 + 2. * h > 2.);
            const double err = std::abs(J[k] - fd) / (1. + std::abs(fd));
            const double tol = one_sided ? 1e-4 : 1e-6;
            worst = std::max(worst, one_sided ? 0. : err);
            INFO("param " << k << " eps " << e1 << " " << e2 << " a " << a[0] << " " << a[1] << " " << a[2]
                          << " J " << J[k] << " fd " << fd);
            CHECK(err < tol);
            ++checked;
          }
        }
  INFO("worst relative error " << worst << " over " << checked << " derivatives");
  CHECK(checked > 20000);
}

TEST_CASE("Superquadric queries, rasterization, sampling and meshing", "[superquadric]")
{
  std::mt19937 rng(3);
  const auto R = rotation_matrix({{1., 2., 0.5}}, 0.7);
  for(double e1 : {0.1, 1., 1.8})
    for(double e2 : {0.1, 1., 2.})
    {
      const SQ sq({{0.3, 0.12, 0.2}}, e1, e2, R, Point(0.05, -0.02, 0.01));
      INFO("eps " << e1 << " " << e2);
      // inside-outside and distance agree on the side
      std::uniform_real_distribution<double> u(-0.45, 0.45);
      for(int t = 0; t < 500; ++t)
      {
        const Point p(u(rng), u(rng), u(rng));
        CHECK((sq.inside_outside(p) <= 1.) == (sq.signed_distance(p) <= 0.));
        CHECK((sq.inside_outside(p) <= 1.) == sq.has_on_bounded_side_or_boundary(p));
      }
      // the fast rasterization visits exactly the voxel centres found by brute force
      const int r = 40;
      std::vector<std::size_t> fast, brute;
      sq.for_each_covered_voxel(r, [&](int, int, int, std::size_t idx) { fast.push_back(idx); });
      std::vector<std::size_t> fast_margin, brute_margin;
      sq.for_each_covered_voxel(r, [&](int, int, int, std::size_t idx) { fast_margin.push_back(idx); }, 0.04);
      PD::Voxel_grid<std::uint8_t> grid(r, 0);
      for(std::size_t idx = 0; idx < grid.size(); ++idx)
      {
        const auto c = grid.center(idx);
        const Point p(c[0], c[1], c[2]);
        if(sq.inside_outside(p) <= 1.) brute.push_back(idx);
        if(sq.signed_distance(p) <= 0.04) brute_margin.push_back(idx);
      }
      CHECK(fast == brute);
      CHECK(fast_margin == brute_margin);
      CHECK(sq.rasterize(grid, std::uint8_t(1)) == brute.size());
      // voxel volume approaches the analytic volume
      const double h = 1. / 128.;
      std::size_t n128 = 0;
      sq.for_each_covered_voxel(128, [&](int, int, int, std::size_t) { ++n128; });
      CHECK(double(n128) * h * h * h == Approx(sq.volume()).epsilon(0.03));
      // the box contains the solid
      const CGAL::Bbox_3 box = sq.bbox();
      std::vector<Point> samples;
      sq.sample_surface(0.01, std::back_inserter(samples));
      CHECK(samples.size() > 1000);
      for(const Point& p : samples)
      {
        CHECK(std::abs(sq.signed_distance(p)) < 1e-12);
        CHECK(p.x() >= box.xmin() - 1e-12);
        CHECK(p.x() <= box.xmax() + 1e-12);
        CHECK(p.z() >= box.zmin() - 1e-12);
        CHECK(p.z() <= box.zmax() + 1e-12);
      }
      // a closed, outward-oriented triangle mesh of about the right volume
      CGAL::Surface_mesh<Point> mesh;
      sq.to_triangle_mesh(mesh, 48);
      CHECK(CGAL::is_valid_polygon_mesh(mesh));
      CHECK(CGAL::is_closed(mesh));
      CHECK(CGAL::is_triangle_mesh(mesh));
      CHECK(CGAL::Polygon_mesh_processing::volume(mesh) == Approx(sq.volume()).epsilon(0.03));
      for(auto v : vertices(mesh)) CHECK(std::abs(sq.signed_distance(mesh.point(v))) < 1e-12);
    }
  // analytic volumes: ball and box limit
  const std::array<double, 9> I = {{1, 0, 0, 0, 1, 0, 0, 0, 1}};
  CHECK(SQ({{0.1, 0.2, 0.3}}, 1., 1., I, Point(0, 0, 0)).volume() == Approx(4. / 3. * CGAL_PI * 0.006));
  CHECK(SQ({{0.1, 0.2, 0.3}}, 0., 0., I, Point(0, 0, 0)).volume() == Approx(8. * 0.006).epsilon(0.01));
}

namespace {

// The grid whose cells down to depth 2 are split, and the deeper ones while `split(cell)` holds,
// down to the finest resolution.
template <typename Split>
PD::Adaptive_grid grid_split_where(int finest, const Split& split)
{
  typedef PD::Adaptive_grid::Cell Cell;
  const int D = PD::Adaptive_grid::depth_of(finest);
  std::vector<Cell> cells, stack(1, Cell{0, {{0, 0, 0}}});
  while(!stack.empty())
  {
    const Cell c = stack.back();
    stack.pop_back();
    if(c.depth == D || (c.depth >= 2 && !split(c)))
    {
      cells.push_back(c);
      continue;
    }
    for(std::uint32_t child = 0; child < 8; ++child)
      stack.push_back(Cell{c.depth + 1, {{2 * c.position[0] + (child & 1), 2 * c.position[1] + ((child >> 1) & 1),
                                          2 * c.position[2] + ((child >> 2) & 1)}}});
  }
  return PD::Adaptive_grid(finest, cells);
}

// A grid of leaves of every size: the cells below depth 2 split at random (probability `p`).
PD::Adaptive_grid random_adaptive_grid(int finest, double p, std::mt19937& rng)
{
  std::bernoulli_distribution split(p);
  return grid_split_where(finest, [&](const PD::Adaptive_grid::Cell&) { return split(rng); });
}

} // namespace

TEST_CASE("for_each_leaf_within visits exactly the leaves whose centre is within the margin", "[superquadric]")
{
  std::mt19937 rng(7);
  const PD::Adaptive_grid adaptive = random_adaptive_grid(64, 0.4, rng);
  const PD::Adaptive_grid uniform = PD::Adaptive_grid::uniform(32);
  // the random grid mixes every leaf size from 1/4 to 1/64
  for(int d = 2; d <= 6; ++d) REQUIRE(adaptive.number_of_leaves_of_depth(d) > 0);
  const auto R = rotation_matrix({{1., 2., 0.5}}, 0.7);
  // inside the cube, across its border, outside it
  const Point centers[] = {Point(0.05, -0.02, 0.01), Point(0.4, -0.35, 0.1), Point(0.9, 0., 0.)};
  for(const PD::Adaptive_grid* grid : {&adaptive, &uniform})
    for(double e1 : {0.1, 1., 1.8})
      for(double e2 : {0.1, 1., 2.})
        for(const Point& c : centers)
          for(double margin : {0., 0.01, 0.04})
          {
            const SQ sq({{0.3, 0.12, 0.2}}, e1, e2, R, c);
            INFO((grid == &uniform ? "uniform" : "adaptive") << " grid, eps " << e1 << " " << e2 << " centre " << c
                                                             << " margin " << margin);
            std::vector<std::size_t> fast;
            PDI::for_each_leaf_within(sq.data(), *grid, margin, [&](std::size_t l) { fast.push_back(l); });
            const std::size_t visits = fast.size();
            std::sort(fast.begin(), fast.end());
            fast.erase(std::unique(fast.begin(), fast.end()), fast.end());
            CHECK(fast.size() == visits); // each leaf once
            // brute force over the leaf centres: the radial distance, or the inside test at margin 0
            std::vector<std::size_t> brute;
            for(std::size_t l = 0; l < grid->number_of_leaves(); ++l)
            {
              const std::array<double, 3> p = grid->center(l);
              const Point q(p[0], p[1], p[2]);
              if(margin == 0. ? sq.inside_outside(q) <= 1. : sq.signed_distance(q) <= margin) brute.push_back(l);
            }
            CHECK(fast == brute);
            CHECK(brute.empty() == (c.x() > 0.5));
            // on the uniform grid, leaf indices are the voxel indices of the dense rasterization
            if(grid == &uniform)
            {
              std::vector<std::size_t> voxels;
              sq.for_each_covered_voxel(32, [&](int, int, int, std::size_t v) { voxels.push_back(v); }, margin);
              CHECK(fast == voxels);
            }
          }
}

TEST_CASE("Superquadric in input coordinates", "[superquadric]")
{
  const PD::Normalization n({{10., -5., 2.}}, 0.25);
  const auto R = rotation_matrix({{0.3, -1., 0.2}}, 1.1);
  const SQ unit({{0.2, 0.05, 0.1}}, 0.3, 1.4, R, Point(0.1, 0.05, -0.2));
  const SQ input = unit.in_input_coordinates(n);
  CHECK(input.scales()[0] == Approx(0.8));
  const auto c = n.from_unit({{0.1, 0.05, -0.2}});
  CHECK(input.center().x() == Approx(c[0]));
  std::mt19937 rng(1);
  std::uniform_real_distribution<double> u(-0.4, 0.4);
  for(int t = 0; t < 100; ++t)
  {
    const std::array<double, 3> pu = {{u(rng), u(rng), u(rng)}};
    const auto pi = n.from_unit(pu);
    // lengths scale by 1 / scale
    CHECK(input.signed_distance(Point(pi[0], pi[1], pi[2])) ==
          Approx(unit.signed_distance(Point(pu[0], pu[1], pu[2])) / 0.25).margin(1e-12));
  }
  const SQ back = input.in_normalized_coordinates(n);
  CHECK(back.scales()[1] == Approx(0.05));
  CHECK(back.center().z() == Approx(-0.2));
}

namespace {

// min 1/2 sum (x_i - t_i)^2 + 1/2 sum_i (x_i x_{i+1} - s_i)^2, recording every evaluated x.
struct Recording_problem
{
  typedef PDI::Bounded_least_squares<4>::Vector Vector;
  typedef PDI::Bounded_least_squares<4>::Matrix Matrix;
  Vector t;
  std::vector<Vector> evaluated;
  double residuals(const Vector& x, double* f)
  {
    evaluated.push_back(x);
    for(int i = 0; i < 4; ++i) f[i] = x[i] - t[i];
    for(int i = 0; i < 3; ++i) f[4 + i] = x[i] * x[i + 1] - 0.5 * (i + 1);
    double s = 0.;
    for(int i = 0; i < 7; ++i) s += f[i] * f[i];
    return 0.5 * s;
  }
  double residuals_and_jacobian(const Vector& x, double* f, double* J)
  {
    const double F = residuals(x, f);
    std::fill(J, J + 28, 0.);
    for(int i = 0; i < 4; ++i) J[4 * i + i] = 1.;
    for(int i = 0; i < 3; ++i)
    {
      J[4 * (4 + i) + i] = x[i + 1];
      J[4 * (4 + i) + i + 1] = x[i];
    }
    return F;
  }
  double cost(const Vector& x)
  {
    double f[7];
    return residuals(x, f);
  }
  double cost_and_normal_equations(const Vector& x, Matrix& A, Vector& g)
  {
    double f[7], J[28];
    const double F = residuals_and_jacobian(x, f, J);
    const Eigen::Map<const Eigen::Matrix<double, 7, 4, Eigen::RowMajor> > Jm(J);
    const Eigen::Map<const Eigen::Matrix<double, 7, 1> > fm(f);
    A = Jm.transpose() * Jm;
    g = Jm.transpose() * fm;
    return F;
  }
  void accept(Vector&) {}
};

} // namespace

TEST_CASE("bounded least squares never leaves its bounds and finds the constrained minimum", "[solver]")
{
  std::mt19937 rng(9);
  std::uniform_real_distribution<double> u(-3., 3.);
  for(int trial = 0; trial < 200; ++trial)
  {
    Recording_problem pb;
    PDI::Bounded_least_squares<4>::Vector lb, ub, x;
    for(int i = 0; i < 4; ++i)
    {
      pb.t[i] = u(rng);
      const double a = u(rng), b = u(rng);
      lb[i] = std::min(a, b) - 0.1;
      ub[i] = std::max(a, b) + 0.1;
      x[i] = u(rng) * 2.; // may start outside: the solver clips it
    }
    PDI::Bounded_least_squares<4> solver;
    PDI::Bounded_least_squares<4>::Options opt;
    opt.maximum_evaluations = 200;
    opt.ftol = 1e-14;
    opt.xtol = 1e-14;
    opt.scale[0] = 0.25;
    const auto report = solver.solve(pb, x, lb, ub, opt);
    for(const auto& y : pb.evaluated)
      for(int i = 0; i < 4; ++i)
      {
        CHECK(y[i] >= lb[i]);
        CHECK(y[i] <= ub[i]);
      }
    CHECK(report.final_cost <= report.initial_cost);
    // first-order optimality of the bound-constrained problem (KKT), checked numerically
    double f[7];
    double J[28];
    pb.residuals_and_jacobian(x, f, J);
    for(int i = 0; i < 4; ++i)
    {
      double g = 0.;
      for(int k = 0; k < 7; ++k) g += J[4 * k + i] * f[k];
      if(x[i] > lb[i] + 1e-9 && x[i] < ub[i] - 1e-9) CHECK(std::abs(g) < 1e-5);
      else if(x[i] <= lb[i] + 1e-9) CHECK(g > -1e-5);
      else CHECK(g < 1e-5);
    }
  }
}

namespace {

typedef CGAL::Surface_mesh<Point> Mesh;
typedef CGAL::AABB_face_graph_triangle_primitive<Mesh> AABB_primitive;
typedef CGAL::AABB_tree<CGAL::AABB_traits<K, AABB_primitive> > AABB_tree;

// The truncated signed distance field of a union of superquadrics: the min of the shapes' fields
// (exact outside, the usual CSG approximation inside), each the distance to a fine triangulation
// of its surface signed by its inside test, clipped to +-tau. Defined at every point, so that the
// dense and the adaptive grids sample the same field.
class Union_field
{
public:
  Union_field(const std::vector<SQ>& shapes, double tau) : m_shapes(shapes), m_tau(tau), m_meshes(shapes.size())
  {
    for(std::size_t s = 0; s < shapes.size(); ++s)
    {
      shapes[s].to_triangle_mesh(m_meshes[s], 64);
      m_trees.emplace_back(new AABB_tree(faces(m_meshes[s]).first, faces(m_meshes[s]).second, m_meshes[s]));
      m_trees.back()->accelerate_distance_queries();
    }
  }

  double truncation() const { return m_tau; }

  double operator()(const std::array<double, 3>& c) const
  {
    double d = m_tau;
    for(std::size_t s = 0; s < m_shapes.size(); ++s)
    {
      // beyond tau from the bounding box every distance is clipped anyway
      const CGAL::Bbox_3 box = m_shapes[s].bbox();
      if(c[0] < box.xmin() - m_tau || c[0] > box.xmax() + m_tau || c[1] < box.ymin() - m_tau ||
         c[1] > box.ymax() + m_tau || c[2] < box.zmin() - m_tau || c[2] > box.zmax() + m_tau)
        continue;
      const Point p(c[0], c[1], c[2]);
      const double u = std::sqrt(m_trees[s]->squared_distance(p));
      d = std::min(d, std::max(-m_tau, std::min(m_tau, m_shapes[s].has_on_bounded_side_or_boundary(p) ? -u : u)));
    }
    return d;
  }

  // at the voxel centres of the r-grid
  PD::Voxel_grid<double> on_voxels(int r) const
  {
    PD::Voxel_grid<double> d(r, m_tau);
    for(std::size_t v = 0; v < d.size(); ++v) d[v] = (*this)(d.center(v));
    return d;
  }

  // at the leaf centres of a grid
  std::vector<double> on_leaves(const PD::Adaptive_grid& grid) const
  {
    std::vector<double> d(grid.number_of_leaves());
    for(std::size_t l = 0; l < d.size(); ++l) d[l] = (*this)(grid.center(l));
    return d;
  }

  // the surfaces of the shapes in one mesh (overlapping where the shapes do)
  Mesh mesh() const
  {
    Mesh m;
    for(const Mesh& s : m_meshes) m.join(s);
    return m;
  }

private:
  std::vector<SQ> m_shapes;
  double m_tau;
  std::vector<Mesh> m_meshes;
  std::vector<std::unique_ptr<AABB_tree> > m_trees;
};

// The grid compute_tsdf() builds for the mesh of the shapes without a prior (the surface at the
// finest of the default voxel resolutions, 64): coarse inside and away from the surface.
PD::Adaptive_grid library_grid(const Union_field& field)
{
  return PD::compute_tsdf(field.mesh(), PD::parameters::normalization(PD::Normalization())).grid;
}

double angle_degrees(const K::Vector_3& u, const K::Vector_3& v)
{
  const double c = std::abs(u * v) / std::sqrt(u.squared_length() * v.squared_length());
  return std::acos(std::min(1., c)) * 180. / CGAL_PI;
}

// One FitSDF run as SDFSQFit would start it from a seed: samples = leaf centres of the ball of
// radius rho around the seed with d_M < 1.5 h, each weighted by its volume in voxels of side h;
// ball of radius 1/32, axis-aligned, eps = 1.
PDI::Fit_sdf_result fit_from_seed(const PD::Adaptive_grid& grid, const std::vector<double>& tsdf, double h,
                                  const std::array<double, 3>& seed, double tau, bool reestimate)
{
  const double rho = 0.25;
  PDI::Fit_samples P;
  for(std::size_t l = 0; l < grid.number_of_leaves(); ++l)
  {
    const auto c = grid.center(l);
    const double d2 = (c[0] - seed[0]) * (c[0] - seed[0]) + (c[1] - seed[1]) * (c[1] - seed[1]) +
                      (c[2] - seed[2]) * (c[2] - seed[2]);
    if(d2 <= rho * rho && tsdf[l] < 1.5 * h) P.push_back(c[0], c[1], c[2], tsdf[l], grid.volume(l) / (h * h * h));
  }
  PDI::Superquadric_data q0;
  for(int i = 0; i < 3; ++i) q0.a[i] = 1. / 32., q0.c[i] = seed[i];
  PDI::Superquadric_vector lb, ub;
  lb << 1. / 128, 1. / 128, 1. / 128, 1e-3, 1e-3, -1e300, -1e300, -1e300, seed[0] - rho / 2, seed[1] - rho / 2,
      seed[2] - rho / 2;
  ub << rho, rho, rho, 2., 2., 1e300, 1e300, 1e300, seed[0] + rho / 2, seed[1] + rho / 2, seed[2] + rho / 2;
  PDI::Fit_sdf_settings settings;
  settings.truncation = tau;
  settings.reestimate_variance = reestimate;
  PDI::Fit_sdf_workspace ws;
  return PDI::fit_sdf<CGAL::Sequential_tag>(P, q0, lb, ub, settings, ws);
}

} // namespace

TEST_CASE("FitSDF recovers a single superquadric from its own TSDF", "[fit_sdf]")
{
  const int r = 64;
  const double h = 1. / r, tau = 8. * h;
  struct Case { const char* name; std::array<double, 3> a; double e1, e2; std::array<double, 9> R; };
  const std::array<double, 9> I = {{1, 0, 0, 0, 1, 0, 0, 0, 1}};
  const Case cases[] = {
    {"sphere", {{0.15, 0.15, 0.15}}, 1., 1., I},
    {"ellipsoid", {{0.2, 0.12, 0.08}}, 1., 1., rotation_matrix({{1., 0.5, 0.2}}, 0.35)},
    {"box-like", {{0.2, 0.12, 0.08}}, 0.1, 0.1, I},
    {"rotated box-like", {{0.2, 0.12, 0.08}}, 0.1, 0.1, rotation_matrix({{0.2, 1., 0.4}}, 0.45)},
    {"cylinder-like", {{0.1, 0.1, 0.2}}, 0.1, 1., rotation_matrix({{1., 0., 0.3}}, 0.3)},
  };
  const PD::Adaptive_grid dense = PD::Adaptive_grid::uniform(r);
  for(const Case& cs : cases)
  {
    const Point center(0.013, -0.021, 0.008);
    const SQ truth(cs.a, cs.e1, cs.e2, cs.R, center);
    const Union_field field({truth}, tau);
    // the dense grid of the paper (unit weights), and the library's adaptive grid of the shape,
    // whose large inner leaves weigh their volume
    const PD::Adaptive_grid adaptive = library_grid(field);
    REQUIRE(adaptive.number_of_leaves() < dense.number_of_leaves() / 4);
    // seed: the centre of the voxel of h that holds the true centre, on both grids
    const auto seed = dense.center(dense.locate(center.x(), center.y(), center.z()));
    for(const PD::Adaptive_grid* grid : {&dense, &adaptive})
    {
      const std::vector<double> values = field.on_leaves(*grid);
      for(bool reestimate : {true, false})
      {
        const PDI::Fit_sdf_result fit = fit_from_seed(*grid, values, h, seed, tau, reestimate);
        REQUIRE(fit.valid);
        const SQ sq(fit.theta);
        INFO(cs.name << (grid == &dense ? " (dense grid" : " (adaptive grid")
                     << (reestimate ? ", MPS variance)" : ", one-shot variance)") << ": a = " << sq.scales()[0]
                     << " " << sq.scales()[1] << " " << sq.scales()[2] << " eps " << sq.epsilon1() << " "
                     << sq.epsilon2() << " c " << sq.center() << " evaluations " << fit.evaluations);
        CHECK(std::sqrt(CGAL::squared_distance(sq.center(), center)) < h);
        // match every true axis with the fitted axis most parallel to it
        for(int i = 0; i < 3; ++i)
        {
          int best = 0;
          double best_angle = 180.;
          for(int j = 0; j < 3; ++j)
          {
            const double ang = angle_degrees(truth.axis(i), sq.axis(j));
            if(ang < best_angle) best_angle = ang, best = j;
          }
          CHECK(std::abs(sq.scales()[best] - cs.a[i]) < h);
          // orientation only means something for distinct axes
          const bool distinct = std::abs(cs.a[i] - cs.a[(i + 1) % 3]) > 0.02 && std::abs(cs.a[i] - cs.a[(i + 2) % 3]) > 0.02;
          if(distinct) CHECK(best_angle < 4.);
        }
      }
    }
  }
}

namespace {

// A hand-made prior at `resolutions` from the field `d` on the grid of the finest one, r:
// carrier = voxels whose centre is within half a diagonal of the surface; carrier voxels for which
// `is_freeze(centre)` holds are Freeze leaves of resolution r, the others Flow leaves of the
// coarsest resolution; interior voxels have R_map = 0. A real prior too has classes on the
// carrier only.
template <typename F>
PD::Hierarchical_prior synthetic_prior(const PD::Voxel_grid<double>& d, const F& is_freeze,
                                       const std::vector<int>& resolutions = {16, 32, 64})
{
  const int r = d.resolution();
  PD::Hierarchical_prior prior;
  prior.resolutions = resolutions;
  prior.classes = PD::Voxel_grid<PD::Voxel_class>(r, PD::Voxel_class::EMPTY);
  prior.leaf_resolution = PD::Voxel_grid<std::uint16_t>(r, 0);
  for(std::size_t i = 0; i < d.size(); ++i)
    if(std::abs(d[i]) <= 0.87 / r)
    {
      const bool fr = is_freeze(d.center(i));
      prior.classes[i] = fr ? PD::Voxel_class::FREEZE : PD::Voxel_class::FLOW;
      prior.leaf_resolution[i] = std::uint16_t(fr ? r : resolutions.front());
    }
  return prior;
}

// The distance field of a hand-made case: the grid compute_tsdf() builds for the mesh of the
// shapes and `prior` (adaptive, or with adaptive_grid(false) one leaf per voxel of the prior's
// finest resolution; `grid_resolution` 0: the default), carrying the analytic field at its leaf
// centres.
PD::Truncated_signed_distance_field synthetic_tsdf(const Union_field& field, const PD::Hierarchical_prior& prior,
                                                   bool adaptive, int grid_resolution = 0)
{
  namespace P = PD::parameters;
  const int r = prior.resolutions.back();
  PD::Truncated_signed_distance_field tsdf = PD::compute_tsdf(
    field.mesh(), prior,
    P::combine(P::voxel_resolutions(prior.resolutions), P::normalization(PD::Normalization()),
               P::tsdf_truncation(field.truncation() * r), switches(&Variant::adaptive_grid, adaptive),
               P::grid_resolution(grid_resolution == 0 ? PD::defaults::grid_resolution : grid_resolution)));
  tsdf.values = field.on_leaves(tsdf.grid);
  return tsdf;
}

PD::Fitting_zones synthetic_zones(const PD::Hierarchical_prior& prior, const PD::Truncated_signed_distance_field& tsdf)
{
  return PD::compute_fitting_zones(prior, tsdf, {16, 32});
}

PD::Superquadric_fitting_result<K> run_fitter(const PD::Hierarchical_prior& prior,
                                              const PD::Truncated_signed_distance_field& tsdf,
                                              PD::Interior_weight_mode mode = PD::Interior_weight_mode::ONE_SHOT,
                                              bool verbose = false)
{
  const PD::Fitting_zones zones = synthetic_zones(prior, tsdf);
  namespace P = PD::parameters;
  return PD::fit_superquadrics<CGAL::Sequential_tag, K>(
    prior, tsdf, zones, P::combine(P::coverage_target(0.95), switches(&Variant::interior_weight_mode, mode), CGAL::parameters::verbose(verbose)));
}

} // namespace

TEST_CASE("SDFSQFit: one primitive per lobe, none across a Freeze wall", "[sdfsqfit]")
{
  const int r = 64;
  const double h = 1. / r, tau = 8. * h;
  const std::array<double, 9> I = {{1, 0, 0, 0, 1, 0, 0, 0, 1}};
  const auto z_to_x = rotation_matrix({{0., 1., 0.}}, CGAL_PI / 2.); // local z along world x
  const auto z_to_y = rotation_matrix({{1., 0., 0.}}, -CGAL_PI / 2.); // local z along world y
  // lobes along x, joined by thin necks of radius two voxels; Freeze on the carrier at the necks
  const SQ left({{0.15, 0.12, 0.12}}, 1., 1., I, Point(-0.22, 0., 0.));
  const SQ right({{0.13, 0.11, 0.12}}, 0.2, 0.2, I, Point(0.2, 0., 0.));
  const SQ neck({{0.03, 0.03, 0.08}}, 0.1, 1., z_to_x, Point(-0.01, 0., 0.));
  const SQ top({{0.09, 0.09, 0.08}}, 0.5, 1., z_to_y, Point(0.2, 0.27, 0.));
  const SQ neck2({{0.03, 0.03, 0.06}}, 0.1, 1., z_to_y, Point(0.2, 0.13, 0.));

  for(int lobes : {2, 3})
  {
    std::vector<SQ> parts = {left, right, neck};
    if(lobes == 3)
    {
      parts.push_back(top);
      parts.push_back(neck2);
    }
    const Union_field field(parts, tau);
    // walls: carrier voxels around the necks
    auto is_freeze = [&](const std::array<double, 3>& c) {
      const bool wall1 = c[0] > -0.09 && c[0] < 0.075 && std::abs(c[1]) < 0.06 && std::abs(c[2]) < 0.06;
      const bool wall2 = lobes == 3 && c[1] > 0.1 && c[1] < 0.19 && std::abs(c[0] - 0.2) < 0.06 && std::abs(c[2]) < 0.06;
      return wall1 || wall2;
    };
    const PD::Hierarchical_prior prior = synthetic_prior(field.on_voxels(r), is_freeze);
    std::vector<SQ> lobe_shapes = {left, right};
    if(lobes == 3) lobe_shapes.push_back(top);
    for(bool adaptive : {true, false})
    {
      const PD::Truncated_signed_distance_field tsdf = synthetic_tsdf(field, prior, adaptive);
      const PD::Adaptive_grid& grid = tsdf.grid;
      // the uniform grid is the dense 64-grid, the adaptive one much smaller
      if(adaptive) CHECK(grid.number_of_leaves() < std::size_t(r * r * r / 4));
      else CHECK(grid == PD::Adaptive_grid::uniform(r));
      const PD::Fitting_zones zones = synthetic_zones(prior, tsdf);
      for(auto mode : {PD::Interior_weight_mode::ONE_SHOT, PD::Interior_weight_mode::MPS_REESTIMATED})
      {
        const auto res = run_fitter(prior, tsdf, mode);
        INFO(lobes << " lobes, " << (adaptive ? "adaptive" : "uniform") << " grid of " << grid.number_of_leaves()
                   << " leaves, mode " << int(mode) << ": " << res.primitives.size() << " primitives, "
                   << res.number_of_seeds << " seeds, " << res.number_of_solves << " solves");
        REQUIRE(res.labels.size() == grid.number_of_leaves());
        // each lobe: most of its volume belongs to one primitive centred in it
        std::size_t big = 0;
        for(std::size_t k = 0; k < res.primitives.size(); ++k)
        {
          double in_lobe[3] = {0., 0., 0.};
          for(std::size_t l : res.claimed_leaves[k])
          {
            const auto c = grid.center(l);
            for(std::size_t i = 0; i < lobe_shapes.size(); ++i)
              if(lobe_shapes[i].has_on_bounded_side_or_boundary(Point(c[0], c[1], c[2]))) in_lobe[i] += grid.volume(l);
          }
          // no primitive claims leaves in two lobes (every path between lobes crosses a wall)
          int lobes_touched = 0;
          for(std::size_t i = 0; i < lobe_shapes.size(); ++i) lobes_touched += in_lobe[i] > 0. ? 1 : 0;
          CHECK(lobes_touched <= 1);
          for(std::size_t i = 0; i < lobe_shapes.size(); ++i)
            if(in_lobe[i] > 0.5 * lobe_shapes[i].volume())
            {
              ++big;
              CHECK(lobe_shapes[i].has_on_bounded_side_or_boundary(res.primitives[k].center()));
            }
        }
        CHECK(big == lobe_shapes.size());
        // labels never sit on Freeze or exterior leaves
        for(std::size_t l = 0; l < res.labels.size(); ++l)
          if(res.labels[l] >= 0) CHECK(zones.freeze_zone[l] == 0);
        CHECK(res.number_of_solves > 0);
      }
    }
  }
}

TEST_CASE("fit_superquadrics: public entry, switches, parameters and determinism", "[sdfsqfit]")
{
  const int r = 64;
  const double h = 1. / r, tau = 8. * h;
  const std::array<double, 9> I = {{1, 0, 0, 0, 1, 0, 0, 0, 1}};
  const auto z_to_x = rotation_matrix({{0., 1., 0.}}, CGAL_PI / 2.);
  const Union_field field({SQ({{0.15, 0.12, 0.12}}, 1., 1., I, Point(-0.22, 0., 0.)),
                           SQ({{0.13, 0.11, 0.12}}, 0.2, 0.2, I, Point(0.2, 0., 0.)),
                           SQ({{0.03, 0.03, 0.08}}, 0.1, 1., z_to_x, Point(-0.01, 0., 0.))},
                          tau);
  PD::Hierarchical_prior prior = synthetic_prior(field.on_voxels(r), [](const std::array<double, 3>& c) {
    return c[0] > -0.09 && c[0] < 0.075 && std::abs(c[1]) < 0.06 && std::abs(c[2]) < 0.06;
  });
  const PD::Truncated_signed_distance_field tsdf = synthetic_tsdf(field, prior, true);
  prior.normalization = PD::Normalization({{1., 2., 3.}}, 0.5);

  const auto seq = PD::fit_superquadrics<CGAL::Sequential_tag, K>(prior, tsdf);
  REQUIRE(seq.primitives.size() >= 2);
  CHECK(seq.labels.size() == tsdf.grid.number_of_leaves());
  CHECK(seq.primitives.size() == seq.input_primitives.size());
  CHECK(seq.primitives.size() == seq.claimed_leaves.size());
  CHECK(seq.stage_resolution.size() == seq.primitives.size());
  CHECK(seq.seed_leaf.size() == seq.primitives.size());
  CHECK(seq.number_of_solves >= seq.primitives.size());
  CHECK(seq.stage_coverage.size() == 3);
  std::size_t claimed = 0;
  for(std::size_t k = 0; k < seq.primitives.size(); ++k)
  {
    // input coordinates through the normalization
    const auto c = prior.normalization.from_unit({{CGAL::to_double(seq.primitives[k].center().x()),
                                                   CGAL::to_double(seq.primitives[k].center().y()),
                                                   CGAL::to_double(seq.primitives[k].center().z())}});
    CHECK(seq.input_primitives[k].center().x() == Approx(c[0]));
    CHECK(seq.input_primitives[k].scales()[0] == Approx(seq.primitives[k].scales()[0] / 0.5));
    CHECK(std::is_sorted(seq.claimed_leaves[k].begin(), seq.claimed_leaves[k].end()));
    for(std::size_t l : seq.claimed_leaves[k]) CHECK(seq.labels[l] == int(k));
    claimed += seq.claimed_leaves[k].size();
  }
  // the claimed leaves are all the labelled ones
  CHECK(claimed == std::size_t(std::count_if(seq.labels.begin(), seq.labels.end(), [](std::int32_t k) { return k >= 0; })));
#ifdef CGAL_LINKED_WITH_TBB
  // bit-identical with threads
  const auto par = PD::fit_superquadrics<CGAL::Parallel_tag, K>(prior, tsdf);
  CHECK(par.labels == seq.labels);
  REQUIRE(par.primitives.size() == seq.primitives.size());
  for(std::size_t k = 0; k < seq.primitives.size(); ++k)
  {
    CHECK(par.primitives[k].scales() == seq.primitives[k].scales());
    CHECK(par.primitives[k].rotation() == seq.primitives[k].rotation());
    CHECK(par.primitives[k].center() == seq.primitives[k].center());
  }
  CHECK(par.number_of_evaluations == seq.number_of_evaluations);
#endif

  namespace P = PD::parameters;
  // ablations run and keep their guarantees
  const auto no_body = PD::fit_superquadrics<CGAL::Sequential_tag, K>(prior, tsdf, switches(&Variant::use_body_seeds, false));
  CHECK(no_body.number_of_body_seeds == 0);
  CHECK(no_body.primitives.size() >= 1);
  const auto no_tsdf = PD::fit_superquadrics<CGAL::Sequential_tag, K>(prior, tsdf, switches(&Variant::use_tsdf_guidance, false));
  CHECK(no_tsdf.primitives.size() >= 1);
  const auto no_freeze = PD::fit_superquadrics<CGAL::Sequential_tag, K>(prior, tsdf, switches(&Variant::use_freeze_zone, false));
  CHECK(no_freeze.primitives.size() >= 1);
  REQUIRE(PD::fitting_resolutions(prior.resolutions) == std::vector<int>{16, 32});
  CHECK(PD::fitting_resolutions({8}) == std::vector<int>{4});
  CHECK(PD::fitting_resolutions({16, 64}) == std::vector<int>{16});
  const PD::Fitting_zones zones = PD::compute_fitting_zones(prior, tsdf, {16, 32});
  // zones computed beforehand give the same fit; zones that miss a resolution are refused
  const auto with_zones = PD::fit_superquadrics<CGAL::Sequential_tag, K>(prior, tsdf, zones);
  CHECK(with_zones.labels == seq.labels);
  CHECK(with_zones.primitives.size() == seq.primitives.size());
  CHECK(with_zones.number_of_evaluations == seq.number_of_evaluations);
  CHECK_THROWS_AS(PD::fit_superquadrics(prior, tsdf, PD::compute_fitting_zones(prior, tsdf, {16})), PD::Invalid_input);
  for(const auto* res : {&no_body, &no_tsdf, &no_freeze})
    for(std::size_t l = 0; l < res->labels.size(); ++l)
      if(res->labels[l] >= 0) CHECK(zones.exterior[l] == 0);
  // the cap holds
  const auto capped = PD::fit_superquadrics<CGAL::Sequential_tag, K>(prior, tsdf, P::maximum_number_of_primitives(1));
  CHECK(capped.primitives.size() == 1);
  // bad parameters throw in every build type
  CHECK_THROWS_AS(PD::fit_superquadrics(prior, tsdf, P::trust_region_scales(std::vector<double>{})), PD::Invalid_input);
  CHECK_THROWS_AS(PD::fit_superquadrics(prior, tsdf, P::coverage_target(1.5)), PD::Invalid_input);
  CHECK_THROWS_AS(PD::fit_superquadrics(prior, tsdf, P::roi_radius(0.)), PD::Invalid_input);
  CHECK_THROWS_AS(PD::fit_superquadrics(prior, tsdf, P::maximum_number_of_primitives(std::size_t(0))), PD::Invalid_input);
  CHECK_THROWS_AS(PD::fit_superquadrics(prior, tsdf, P::exterior_penalty(-1.)), PD::Invalid_input);
}

namespace {

// A hand-made prior and the distance field on the library's grid for it.
struct Synthetic_case
{
  PD::Hierarchical_prior prior;
  PD::Truncated_signed_distance_field tsdf;
};

// A box of half-sizes (0.3, 0.15, 0.15) with a prior at `resolutions` (finest 32) whose carrier is
// all Flow, R_map = the coarsest resolution.
Synthetic_case box_case(std::vector<int> resolutions = {16, 32}, bool adaptive = true, int grid_resolution = 0)
{
  const int r = 32;
  const std::array<double, 9> I = {{1, 0, 0, 0, 1, 0, 0, 0, 1}};
  const Union_field field({SQ({{0.3, 0.15, 0.15}}, 0.1, 0.1, I, Point(0., 0., 0.))}, 8. / r);
  Synthetic_case out;
  out.prior = synthetic_prior(field.on_voxels(r), [](const std::array<double, 3>&) { return false; }, resolutions);
  out.tsdf = synthetic_tsdf(field, out.prior, adaptive, grid_resolution);
  return out;
}

// A plate of half-sizes (0.3, 0.15, 0.025), resolutions {16, 32}: its whole thickness is in the
// carrier, which is Freeze with R_map = 32 at 0 < x < 1/32, Flow with R_map = 16 elsewhere: a
// Freeze band across the plate, as a real prior puts on a crease, which the distance field does
// not see. One voxel wide: the fit of a plain ball spans a band without samples if it is narrow.
Synthetic_case plate_case(bool adaptive = true)
{
  const int r = 32;
  const std::array<double, 9> I = {{1, 0, 0, 0, 1, 0, 0, 0, 1}};
  const Union_field field({SQ({{0.3, 0.15, 0.025}}, 0.1, 0.1, I, Point(0., 0., 0.))}, 8. / r);
  Synthetic_case out;
  out.prior = synthetic_prior(field.on_voxels(r), [](const std::array<double, 3>& c) { return c[0] > 0. && c[0] < 1. / 32; },
                              {16, 32});
  out.tsdf = synthetic_tsdf(field, out.prior, adaptive);
  return out;
}

typedef PD::Superquadric_fitting_result<K> Fit;

void check_same_fit(const Fit& a, const Fit& b)
{
  CHECK(a.labels == b.labels);
  REQUIRE(a.primitives.size() == b.primitives.size());
  for(std::size_t k = 0; k < a.primitives.size(); ++k)
  {
    CHECK(a.primitives[k].scales() == b.primitives[k].scales());
    CHECK(a.primitives[k].rotation() == b.primitives[k].rotation());
    CHECK(a.primitives[k].center() == b.primitives[k].center());
  }
  CHECK(a.stage_resolution == b.stage_resolution);
  CHECK(a.body_seeded == b.body_seeded);
  CHECK(a.seed_leaf == b.seed_leaf);
  CHECK(a.semi_axis_scale == b.semi_axis_scale);
  CHECK(a.fit_cost == b.fit_cost);
  CHECK(a.claimed_leaves == b.claimed_leaves);
  CHECK(a.number_of_seeds == b.number_of_seeds);
  CHECK(a.number_of_body_seeds == b.number_of_body_seeds);
  CHECK(a.number_of_rejected_seeds == b.number_of_rejected_seeds);
  CHECK(a.rejected_by_flow_zone == b.rejected_by_flow_zone);
  CHECK(a.rejected_by_volume == b.rejected_by_volume);
  CHECK(a.rejected_degenerate == b.rejected_degenerate);
  CHECK(a.number_of_solves == b.number_of_solves);
  CHECK(a.number_of_evaluations == b.number_of_evaluations);
  CHECK(a.number_of_samples == b.number_of_samples);
  CHECK(a.merged_leaves == b.merged_leaves);
  CHECK(a.stage_coverage == b.stage_coverage);
}

// Whether some primitive claims leaves on both sides of the plane x = 0.
bool some_claim_crosses_the_wall(const Fit& fit, const PD::Adaptive_grid& grid)
{
  for(const std::vector<std::size_t>& leaves : fit.claimed_leaves)
  {
    bool left = false, right = false;
    for(std::size_t l : leaves) (grid.center(l)[0] < 0. ? left : right) = true;
    if(left && right) return true;
  }
  return false;
}

} // namespace

TEST_CASE("fit_superquadrics and compute_fitting_zones: default named parameters are the defaults", "[sdfsqfit]")
{
  namespace P = PD::parameters;
  namespace D = PD::defaults;
  const Synthetic_case c = plate_case();
  const auto explicit_zone_parameters = P::combine(P::flow_zone_tolerance(D::flow_zone_tolerance));
  const std::vector<int> fit_res = PD::fitting_resolutions(c.prior.resolutions);
  const PD::Fitting_zones z1 = PD::compute_fitting_zones(c.prior, c.tsdf, fit_res);
  const PD::Fitting_zones z2 = PD::compute_fitting_zones(c.prior, c.tsdf, fit_res, explicit_zone_parameters);
  CHECK(z1.classes == z2.classes);
  CHECK(z1.leaf_resolution == z2.leaf_resolution);
  CHECK(z1.occupied == z2.occupied);
  CHECK(z1.exterior == z2.exterior);
  CHECK(z1.freeze_zone == z2.freeze_zone);
  CHECK(z1.flow_zone == z2.flow_zone);
  // and they differ from other values: the comparison is not idle
  const PD::Fitting_zones z3 = PD::compute_fitting_zones(c.prior, c.tsdf, fit_res, P::flow_zone_tolerance(1.));
  CHECK(z3.flow_zone != z1.flow_zone);

  const Fit by_default = PD::fit_superquadrics<CGAL::Sequential_tag, K>(c.prior, c.tsdf);
  const Fit given = PD::fit_superquadrics<CGAL::Sequential_tag, K>(
    c.prior, c.tsdf,
    P::combine(explicit_zone_parameters, P::trust_region_scales(D::trust_region_scales),
               P::body_seed_threshold(D::body_seed_threshold), P::minimum_body_volume(D::minimum_body_volume),
               P::minimum_surface_volume(D::minimum_surface_volume), P::exterior_penalty(D::exterior_penalty),
               P::coverage_target(D::coverage_target), P::roi_radius(D::roi_radius),
               P::method_variant(PD::Method_variant()),
               P::maximum_number_of_primitives(D::maximum_number_of_primitives),
               P::fitting_resolution_cap(D::fitting_resolution_cap),
               P::maximum_solver_evaluations(D::maximum_solver_evaluations),
               P::maximum_rejections_in_a_row(D::maximum_rejections_in_a_row), CGAL::parameters::verbose(false)));
  REQUIRE(by_default.primitives.size() >= 2);
  check_same_fit(by_default, given);
}

TEST_CASE("fit_superquadrics: the switches of the paper's literal version", "[sdfsqfit]")
{
  namespace P = PD::parameters;
  typedef CGAL::Sequential_tag Seq;

  SECTION("use_reachable_regions: only the plain ball lets a claim cross a Freeze wall")
  {
    // The distance field sees one plate; the Freeze band splits it. The ball of the first seed
    // holds both halves: without the reachable region, the fit sees the whole plate.
    for(bool adaptive : {true, false})
    {
      INFO((adaptive ? "adaptive" : "uniform") << " grid");
      const Synthetic_case c = plate_case(adaptive);
      const Fit reachable = PD::fit_superquadrics<Seq, K>(c.prior, c.tsdf);
      const Fit ball = PD::fit_superquadrics<Seq, K>(c.prior, c.tsdf, switches(&Variant::use_reachable_regions, false));
      REQUIRE(reachable.primitives.size() >= 2);
      CHECK_FALSE(some_claim_crosses_the_wall(reachable, c.tsdf.grid));
      CHECK(some_claim_crosses_the_wall(ball, c.tsdf.grid));
    }
  }

  // Every seed rejected (V_min above the grid's volume), one stage: the run is a sequence of body
  // seeds at the EDT maxima of a fixed Omega_Body, and nothing else changes between seeds (the
  // fits, cut short to keep the test fast, do not matter).
  auto all_rejected = [](const auto&... np) {
    return P::combine(P::minimum_body_volume(1e9), P::minimum_surface_volume(1e9),
                      P::trust_region_scales(std::vector<double>{1.}), P::maximum_solver_evaluations(1), np...);
  };

  SECTION("maximum_rejections_in_a_row and use_seed_exclusion")
  {
    for(bool adaptive : {true, false})
    {
      INFO((adaptive ? "adaptive" : "uniform") << " grid");
      const Synthetic_case c = box_case({32}, adaptive);
      const PD::Adaptive_grid& grid = c.tsdf.grid;
      const Fit never = PD::fit_superquadrics<Seq, K>(c.prior, c.tsdf, all_rejected(P::maximum_rejections_in_a_row(0)));
      const Fit three = PD::fit_superquadrics<Seq, K>(c.prior, c.tsdf, all_rejected(P::maximum_rejections_in_a_row(3)));
      const Fit one = PD::fit_superquadrics<Seq, K>(c.prior, c.tsdf, all_rejected(P::maximum_rejections_in_a_row(1)));
      // no fit accepted: one box-like superquadric of the whole volume stands for the shape and
      // claims every leaf that is neither exterior nor Freeze
      REQUIRE(never.primitives.size() == 1);
      CHECK(never.number_of_rejected_seeds == never.number_of_seeds);
      CHECK(!never.body_seeded[0]);
      const PD::Fitting_zones zones =
        PD::compute_fitting_zones(c.prior, c.tsdf, PD::fitting_resolutions(c.prior.resolutions));
      std::size_t claimable = 0;
      double claimable_volume = 0.;
      for(std::size_t l = 0; l < zones.freeze_zone.size(); ++l)
      {
        claimable += zones.freeze_zone[l] ? 0 : 1;
        claimable_volume += zones.freeze_zone[l] ? 0. : grid.volume(l);
        CHECK(never.labels[l] == (zones.freeze_zone[l] ? -1 : 0));
      }
      CHECK(never.claimed_leaves[0].size() == claimable);
      // the claimed leaves cover the box (every leaf with a point inside is inside or crossed)
      const std::array<double, 9> I = {{1, 0, 0, 0, 1, 0, 0, 0, 1}};
      CHECK(claimable_volume >= SQ({{0.3, 0.15, 0.15}}, 0.1, 0.1, I, Point(0., 0., 0.)).volume());
      // Its superquadric is their box, on the coordinate axes as the box is: it holds the cubes
      // of the claimed leaves and exceeds them by at most half the largest leaf (brute force).
      const SQ& fallback = never.primitives[0];
      const Point o = fallback.center();
      CHECK(o.x() == Approx(0.).margin(0.5 / 32));
      std::array<double, 3> extent = {{0., 0., 0.}};
      double largest = 0.;
      for(std::size_t l : never.claimed_leaves[0])
      {
        const auto p = grid.center(l);
        const double s = grid.size(l);
        largest = std::max(largest, s);
        for(int j = 0; j < 3; ++j) extent[j] = std::max(extent[j], std::abs(p[j] - o[j]) + s / 2);
      }
      for(int i = 0; i < 3; ++i)
      {
        const K::Vector_3 u = fallback.axis(i);
        const double ua[3] = {std::abs(u.x()), std::abs(u.y()), std::abs(u.z())};
        const int j = int(std::max_element(ua, ua + 3) - ua);
        CHECK(ua[j] == Approx(1.).margin(1e-9));
        CHECK(fallback.scales()[i] >= extent[j] - 1e-12);
        CHECK(fallback.scales()[i] <= extent[j] + largest / 2 + 1e-12);
      }
      // the box [-0.3, 0.3] x [-0.15, 0.15]^2 up to the surface leaves that straddle it
      CHECK(extent[0] == Approx(0.3).margin(1.5 / 32));
      CHECK(extent[1] == Approx(0.15).margin(1.5 / 32));
      CHECK(extent[2] == Approx(0.15).margin(1.5 / 32));
      // a stage ends after the given number of rejections in a row
      REQUIRE(never.number_of_seeds > 3);
      CHECK(three.number_of_seeds == 3);
      CHECK(one.number_of_seeds == 1);
      // Without exclusion balls, each rejection removes the seed leaf only: every leaf deep enough
      // for a body seed is tried, while an exclusion ball (radius >= 1 voxel) removes at least the
      // deepest leaf's neighbours, some of which are deep enough (the box is more than one voxel
      // deeper than the body-seed threshold).
      const Fit seed_only = PD::fit_superquadrics<Seq, K>(
        c.prior, c.tsdf, all_rejected(P::maximum_rejections_in_a_row(0), switches(&Variant::use_seed_exclusion, false)));
      CHECK(seed_only.number_of_seeds > never.number_of_seeds);
      CHECK(seed_only.number_of_body_seeds == seed_only.number_of_seeds);
    }
  }

  SECTION("use_exterior_band_samples: the exterior band leaves are the only difference in the samples")
  {
    // One seed (the first is the same in both runs), a region of interest that covers the grid.
    auto one_seed = [](bool band) {
      return P::combine(P::maximum_number_of_primitives(1), P::maximum_rejections_in_a_row(1), P::roi_radius(16.),
                        switches(&Variant::use_exterior_band_samples, band));
    };
    for(bool adaptive : {true, false})
    {
      INFO((adaptive ? "adaptive" : "uniform") << " grid");
      // finest leaves of 1/32: on the default grid (Delta = 1/128) no exterior leaf next to this
      // surface is fine enough to lie in the band
      const Synthetic_case c = box_case({32}, adaptive, 32);
      const Fit with_band = PD::fit_superquadrics<Seq, K>(c.prior, c.tsdf, one_seed(true));
      const Fit without = PD::fit_superquadrics<Seq, K>(c.prior, c.tsdf, one_seed(false));
      REQUIRE(with_band.number_of_seeds == 1);
      REQUIRE(without.number_of_seeds == 1);
      const PD::Fitting_zones zones = PD::compute_fitting_zones(c.prior, c.tsdf, PD::fitting_resolutions({32}));
      // the band is d_M < 1.5 Delta, Delta being the side of the finest leaves
      const double delta = 1. / c.tsdf.grid.finest_resolution();
      std::size_t band = 0;
      for(std::size_t l = 0; l < zones.exterior.size(); ++l)
        if(zones.exterior[l] && c.tsdf.values[l] < 1.5 * delta) ++band;
      REQUIRE(band > 0);
      CHECK(with_band.number_of_samples == without.number_of_samples + band);
    }
  }

  SECTION("maximum_solver_evaluations bounds the evaluations of every solve")
  {
    const Synthetic_case c = box_case({32});
    const Fit by_default = PD::fit_superquadrics<Seq, K>(c.prior, c.tsdf);
    const Fit two = PD::fit_superquadrics<Seq, K>(c.prior, c.tsdf, P::maximum_solver_evaluations(2));
    REQUIRE(by_default.number_of_solves > 0);
    CHECK(by_default.number_of_evaluations > 2 * by_default.number_of_solves); // the bound is not idle
    CHECK(two.number_of_solves > 0);
    CHECK(two.number_of_evaluations <= 2 * two.number_of_solves);
  }

  SECTION("fitting_resolution_cap: r_fit = min(r, cap), in the zones and in the fit")
  {
    CHECK(PD::fitting_resolutions({16, 32, 64}, 32) == std::vector<int>{16, 32});
    CHECK(PD::fitting_resolutions({32, 64, 128}, 32) == std::vector<int>{32});
    CHECK(PD::fitting_resolutions({16, 32, 64}, 8) == std::vector<int>{8});
    CHECK(PD::fitting_resolutions({8, 16}, 32) == std::vector<int>{8, 16});
    CHECK(PD::fitting_resolutions({8, 16}) == std::vector<int>{8});
    const Synthetic_case b = plate_case();
    const PD::Fitting_zones default_zones =
      PD::compute_fitting_zones(b.prior, b.tsdf, PD::fitting_resolutions(b.prior.resolutions));
    const PD::Fitting_zones capped_zones =
      PD::compute_fitting_zones(b.prior, b.tsdf, PD::fitting_resolutions(b.prior.resolutions, 32));
    // zones without r_fit = 32 are refused, zones with it give the fit that computes its own
    CHECK_THROWS_AS(PD::fit_superquadrics(b.prior, b.tsdf, default_zones, P::fitting_resolution_cap(32)),
                    PD::Invalid_input);
    const Fit own = PD::fit_superquadrics<Seq, K>(b.prior, b.tsdf, P::fitting_resolution_cap(32));
    const Fit given = PD::fit_superquadrics<Seq, K>(b.prior, b.tsdf, capped_zones, P::fitting_resolution_cap(32));
    check_same_fit(own, given);
    REQUIRE(!own.primitives.empty());
    // semi-axes are bounded by rho = roi_radius / r_fit: 8/32 in the stage r = 32
    for(std::size_t k = 0; k < own.primitives.size(); ++k)
      for(int i = 0; i < 3; ++i)
        CHECK(CGAL::to_double(own.primitives[k].scales()[i]) <= 8. / (std::min)(own.stage_resolution[k], 32) + 1e-12);
  }
}

TEST_CASE("fit_superquadrics: out-of-range switches are refused by name", "[sdfsqfit]")
{
  namespace P = PD::parameters;
  const Synthetic_case c = box_case({32});
  auto fit = [&](const auto& np) { return PD::fit_superquadrics(c.prior, c.tsdf, np); };
  CHECK_THROWS_AS(fit(P::fitting_resolution_cap(-1)), PD::Invalid_input);
  CHECK_THROWS_WITH(fit(P::fitting_resolution_cap(-1)), Catch::Contains("fitting_resolution_cap"));
  CHECK_THROWS_WITH(PD::fitting_resolutions({16, 32}, -2), Catch::Contains("fitting_resolution_cap"));
  CHECK_THROWS_AS(fit(P::maximum_solver_evaluations(0)), PD::Invalid_input);
  CHECK_THROWS_WITH(fit(P::maximum_solver_evaluations(0)), Catch::Contains("maximum_solver_evaluations"));
  CHECK_THROWS_WITH(fit(P::maximum_solver_evaluations(-5)), Catch::Contains("maximum_solver_evaluations"));
  CHECK_THROWS_AS(fit(P::maximum_rejections_in_a_row(-1)), PD::Invalid_input);
  CHECK_THROWS_WITH(fit(P::maximum_rejections_in_a_row(-1)), Catch::Contains("maximum_rejections_in_a_row"));
  CHECK_THROWS_WITH(fit(P::maximum_number_of_primitives(-1)), Catch::Contains("maximum_number_of_primitives"));
  // the boolean switches have no out-of-range value; the older parameters name themselves too
  CHECK_THROWS_WITH(fit(P::coverage_target(0.)), Catch::Contains("coverage_target"));
  CHECK_THROWS_WITH(fit(P::flow_zone_tolerance(-1.)), Catch::Contains("flow_zone_tolerance"));
}

namespace {

// The grid of finest resolution r whose cells are split down to r where a face of one of the
// boxes (xmin, ymin, zmin, xmax, ymax, zmax) crosses them, and down to 1/4 everywhere: every
// other leaf lies inside or outside each box.
PD::Adaptive_grid grid_refined_at_faces(int r, const std::vector<std::array<double, 6> >& boxes)
{
  return grid_split_where(r, [&](const PD::Adaptive_grid::Cell& c) {
    const double s = std::ldexp(1., -c.depth);
    bool mixed = false;
    for(const std::array<double, 6>& b : boxes)
    {
      bool meets = true, inside = true;
      for(int a = 0; a < 3; ++a)
      {
        const double lo = -0.5 + c.position[a] * s, hi = lo + s;
        meets = meets && lo < b[a + 3] && hi > b[a];
        inside = inside && lo >= b[a] && hi <= b[a + 3];
      }
      mixed = mixed || (meets && !inside);
    }
    return mixed;
  });
}

// A fitting result on `grid` whose primitive k claims the leaves with centre in boxes[k] (its
// superquadric is that box); the surface leaves of the union (claimed, with an unclaimed face
// neighbour) are Flow, or Freeze where `freeze` holds; the distance is -1 inside the boxes, +1 out.
struct Claimed_boxes
{
  PD::Superquadric_fitting_result<K> fit;
  std::vector<PD::Voxel_class> classes;
  PD::Truncated_signed_distance_field tsdf;
};

template <typename Freeze>
Claimed_boxes claimed_boxes(const PD::Adaptive_grid& grid, const std::vector<std::array<double, 6> >& boxes,
                            const Freeze& freeze)
{
  Claimed_boxes out;
  PD::Superquadric_fitting_result<K>& fit = out.fit;
  const std::size_t n = grid.number_of_leaves();
  out.tsdf.grid = grid;
  out.tsdf.values.assign(n, 1.);
  out.tsdf.truncation = 1.;
  out.tsdf.voxel_size = 1. / grid.finest_resolution();
  fit.labels.assign(n, -1);
  out.classes.assign(n, PD::Voxel_class::EMPTY);
  fit.claimed_leaves.resize(boxes.size());
  const std::array<double, 9> I = {{1, 0, 0, 0, 1, 0, 0, 0, 1}};
  for(std::size_t k = 0; k < boxes.size(); ++k)
  {
    const std::array<double, 6>& b = boxes[k];
    fit.primitives.push_back(SQ({{(b[3] - b[0]) / 2, (b[4] - b[1]) / 2, (b[5] - b[2]) / 2}}, 0.1, 0.1, I,
                                Point((b[0] + b[3]) / 2, (b[1] + b[4]) / 2, (b[2] + b[5]) / 2)));
    for(std::size_t l = 0; l < n; ++l)
    {
      const auto c = grid.center(l);
      if(c[0] > b[0] && c[0] < b[3] && c[1] > b[1] && c[1] < b[4] && c[2] > b[2] && c[2] < b[5])
      {
        fit.labels[l] = std::int32_t(k);
        fit.claimed_leaves[k].push_back(l);
        out.tsdf.values[l] = -1.;
      }
    }
  }
  for(std::size_t l = 0; l < n; ++l)
  {
    if(fit.labels[l] < 0) continue;
    bool surface = false;
    grid.for_each_neighbor(l, [&](std::size_t m) { surface = surface || fit.labels[m] < 0; });
    if(surface) out.classes[l] = freeze(grid.center(l)) ? PD::Voxel_class::FREEZE : PD::Voxel_class::FLOW;
  }
  const std::size_t K_ = boxes.size();
  fit.input_primitives = fit.primitives;
  fit.stage_resolution.assign(K_, grid.finest_resolution());
  fit.body_seeded.assign(K_, true);
  fit.seed_leaf.assign(K_, 0);
  fit.semi_axis_scale.assign(K_, 1.);
  fit.fit_cost.assign(K_, 0.);
  return out;
}

double claimed_volume(const Claimed_boxes& c)
{
  double v = 0.;
  for(const std::vector<std::size_t>& leaves : c.fit.claimed_leaves)
    for(std::size_t l : leaves) v += c.tsdf.grid.volume(l);
  return v;
}

} // namespace

TEST_CASE("primitives that tile one box are merged into one superquadric of the box", "[sdfsqfit][merge]")
{
  const int r = 32;
  const auto never = [](const std::array<double, 3>&) { return false; };
  // a box [-0.3, 0.3] x [-0.1, 0.1] x [-0.15, 0.15] tiled by three slabs along x
  const std::vector<std::array<double, 6> > slabs = {{{-0.3, -0.1, -0.15, -0.1, 0.1, 0.15}},
                                                     {{-0.1, -0.1, -0.15, 0.1, 0.1, 0.15}},
                                                     {{0.1, -0.1, -0.15, 0.3, 0.1, 0.15}}};
  const std::vector<std::array<double, 6> > l_boxes = {{{-0.3, -0.3, -0.05, 0.3, -0.2, 0.05}},
                                                       {{-0.3, -0.2, -0.05, -0.2, 0.3, 0.05}}};
  // the dense grid, and grids with leaves of 1/4 inside the boxes, 1/32 where their faces pass
  const PD::Adaptive_grid uniform = PD::Adaptive_grid::uniform(r);
  const PD::Adaptive_grid slab_grid = grid_refined_at_faces(r, slabs), l_grid = grid_refined_at_faces(r, l_boxes);
  REQUIRE(slab_grid.number_of_leaves_of_depth(2) > 0);
  REQUIRE(slab_grid.number_of_leaves() < uniform.number_of_leaves() / 2);
  for(bool adaptive : {true, false})
  {
    INFO((adaptive ? "adaptive" : "uniform") << " grid");
    Claimed_boxes c = claimed_boxes(adaptive ? slab_grid : uniform, slabs, never);
    // every leaf lies in or out of each box: the same claimed volume as the dense grid's voxels
    const double volume = claimed_volume(c);
    CHECK(volume == Approx(claimed_volume(claimed_boxes(uniform, slabs, never))).epsilon(1e-12));
    PDI::merge_explained_primitives(c.fit, c.classes, c.tsdf, 1. / r, 0.6, 0.2);
    REQUIRE(c.fit.primitives.size() == 1);
    CHECK(claimed_volume(c) == Approx(volume).epsilon(1e-12));
    for(std::size_t l = 0; l < c.fit.labels.size(); ++l) CHECK(c.fit.labels[l] <= 0);
    CHECK(c.fit.claimed_leaves[0].size() == std::size_t(std::count(c.fit.labels.begin(), c.fit.labels.end(), 0)));
    CHECK(std::is_sorted(c.fit.claimed_leaves[0].begin(), c.fit.claimed_leaves[0].end()));
    // the box, up to half a voxel on each side (the voxel centres span it less half a voxel)
    std::array<double, 3> a = c.fit.primitives[0].scales();
    std::sort(a.begin(), a.end());
    CHECK(a[0] == Approx(0.1).margin(1. / 64));
    CHECK(a[1] == Approx(0.15).margin(1. / 64));
    CHECK(a[2] == Approx(0.3).margin(1. / 64));
    CHECK(std::sqrt(CGAL::squared_distance(c.fit.primitives[0].center(), Point(0, 0, 0))) < 1. / 32);
    CHECK(c.fit.input_primitives.size() == 1);
    CHECK(c.fit.stage_resolution.size() == 1);
    CHECK(c.fit.seed_leaf.size() == 1);

    // a Freeze ring around the common faces of the slabs (a joint) keeps them apart
    Claimed_boxes joint = claimed_boxes(adaptive ? slab_grid : uniform, slabs, [](const std::array<double, 3>& p) {
      return std::abs(std::abs(p[0]) - 0.1) < 1.5 / 32;
    });
    PDI::merge_explained_primitives(joint.fit, joint.classes, joint.tsdf, 1. / r, 0.6, 0.2);
    CHECK(joint.fit.primitives.size() == 3);

    // an L of two boxes is not one box: they stay two
    Claimed_boxes l = claimed_boxes(adaptive ? l_grid : uniform, l_boxes, never);
    PDI::merge_explained_primitives(l.fit, l.classes, l.tsdf, 1. / r, 0.6, 0.2);
    CHECK(l.fit.primitives.size() == 2);
    CHECK(!l.fit.claimed_leaves[0].empty());
    CHECK(!l.fit.claimed_leaves[1].empty());
  }
}


namespace {

// The whole fitting stage on a mesh in the normalized cube: its prior, its distance field on the
// grid of `np` and the fit.
template <typename NamedParameters>
Fit fit_mesh(const Mesh& m, const NamedParameters& np, PD::Truncated_signed_distance_field& tsdf)
{
  namespace P = PD::parameters;
  const auto all = P::combine(P::normalization(PD::Normalization()), np);
  const PD::Hierarchical_prior prior = PD::compute_flow_freeze_prior(m, all);
  tsdf = PD::compute_tsdf(m, prior, all);
  return PD::fit_superquadrics<CGAL::Sequential_tag, K>(prior, tsdf, all);
}

} // namespace

TEST_CASE("fit_superquadrics on the prior and the distance field of a mesh: known answers", "[sdfsqfit]")
{
  namespace P = PD::parameters;
  const double h = 1. / 64;

  SECTION("a superquadric is recovered by one primitive")
  {
    // On the default grid and the dense one: a body seed in a leaf larger than the paper's
    // initial ball starts from a ball that reaches the neighbouring leaves, or it would not move.
    const std::array<double, 9> I = {{1, 0, 0, 0, 1, 0, 0, 0, 1}};
    const SQ shapes[] = {SQ({{0.35, 0.35, 0.35}}, 1., 1., I, Point(0., 0., 0.)),
                         SQ({{0.3, 0.2, 0.15}}, 1., 1., rotation_matrix({{1., 0.5, 0.2}}, 0.35), Point(0.02, -0.01, 0.03)),
                         SQ({{0.3, 0.18, 0.12}}, 0.3, 0.3, rotation_matrix({{0.2, 1., 0.4}}, 0.45), Point(0.02, -0.01, 0.03))};
    for(const SQ& truth : shapes)
    for(bool adaptive : {true, false})
    {
      Mesh m;
      truth.to_triangle_mesh(m, 48);
      PD::Truncated_signed_distance_field tsdf;
      const Fit fit = fit_mesh(m, switches(&Variant::adaptive_grid, adaptive), tsdf);
      INFO((adaptive ? "adaptive grid" : "dense grid"));
      INFO("a = " << truth.scales()[0] << " " << truth.scales()[1] << " " << truth.scales()[2] << " eps "
                  << truth.epsilon1() << " " << truth.epsilon2() << ": " << fit.primitives.size() << " primitives");
      REQUIRE(fit.primitives.size() == 1);
      const SQ& sq = fit.primitives[0];
      INFO("fitted a = " << sq.scales()[0] << " " << sq.scales()[1] << " " << sq.scales()[2] << " eps "
                         << sq.epsilon1() << " " << sq.epsilon2() << " c " << sq.center());
      CHECK(std::sqrt(CGAL::squared_distance(sq.center(), truth.center())) < h);
      CHECK(sq.epsilon1() == Approx(truth.epsilon1()).margin(0.1));
      CHECK(sq.epsilon2() == Approx(truth.epsilon2()).margin(0.1));
      for(int i = 0; i < 3; ++i)
      {
        int best = 0;
        double best_angle = 180.;
        for(int j = 0; j < 3; ++j)
        {
          const double ang = angle_degrees(truth.axis(i), sq.axis(j));
          if(ang < best_angle) best_angle = ang, best = j;
        }
        CHECK(std::abs(sq.scales()[best] - truth.scales()[i]) < h);
      }
      // it claims the solid: the leaves whose centre is inside, but a few along the surface
      double inside = 0., claimed_inside = 0.;
      for(std::size_t l = 0; l < tsdf.grid.number_of_leaves(); ++l)
      {
        const auto c = tsdf.grid.center(l);
        if(!truth.has_on_bounded_side_or_boundary(Point(c[0], c[1], c[2]))) continue;
        inside += tsdf.grid.volume(l);
        claimed_inside += fit.labels[l] == 0 ? tsdf.grid.volume(l) : 0.;
      }
      CHECK(claimed_inside > 0.95 * inside);
    }
  }

  SECTION("a T of two bars gives two primitives, one per bar")
  {
    // bar [-0.45, 0.45] x [-0.36, -0.18] x [-0.09, 0.09], stem [-0.09, 0.09] x [-0.18, 0.36] x [-0.09, 0.09]
    Mesh m = test_shapes::make_union_of_cubes({{{0, 0, 0}}, {{1, 0, 0}}, {{2, 0, 0}}, {{3, 0, 0}}, {{4, 0, 0}},
                                               {{2, 1, 0}}, {{2, 2, 0}}, {{2, 3, 0}}});
    for(auto v : vertices(m))
    {
      const Point& p = m.point(v);
      m.point(v) = Point(0.18 * (p.x() - 2.5), 0.18 * (p.y() - 2.), 0.18 * (p.z() - 0.5));
    }
    const std::array<double, 6> bars[] = {{{-0.45, -0.36, -0.09, 0.45, -0.18, 0.09}}, {{-0.09, -0.18, -0.09, 0.09, 0.36, 0.09}}};
    auto in_bar = [&](std::size_t b, const std::array<double, 3>& c) {
      return c[0] > bars[b][0] && c[0] < bars[b][3] && c[1] > bars[b][1] && c[1] < bars[b][4] && c[2] > bars[b][2] &&
             c[2] < bars[b][5];
    };
    for(bool adaptive : {true, false})
    {
      PD::Truncated_signed_distance_field tsdf;
      const Fit fit = fit_mesh(m, switches(&Variant::adaptive_grid, adaptive), tsdf);
      const PD::Adaptive_grid& grid = tsdf.grid;
      INFO((adaptive ? "adaptive" : "uniform") << " grid of " << grid.number_of_leaves() << " leaves: "
                                               << fit.primitives.size() << " primitives");
      if(adaptive) CHECK(grid.number_of_leaves() < std::size_t(64 * 64 * 64 / 8));
      else CHECK(grid == PD::Adaptive_grid::uniform(64));
      REQUIRE(fit.primitives.size() == 2);
      bool centred[2] = {false, false};
      for(std::size_t k = 0; k < 2; ++k)
      {
        const Point c = fit.primitives[k].center();
        for(std::size_t b = 0; b < 2; ++b)
          if(in_bar(b, {{c.x(), c.y(), c.z()}}))
          {
            centred[b] = true;
            // it claims most of its bar, and little of the other
            double own = 0., other = 0.;
            for(std::size_t l : fit.claimed_leaves[k])
            {
              const auto p = grid.center(l);
              own += in_bar(b, p) ? grid.volume(l) : 0.;
              other += in_bar(1 - b, p) ? grid.volume(l) : 0.;
            }
            const double volume = (bars[b][3] - bars[b][0]) * (bars[b][4] - bars[b][1]) * (bars[b][5] - bars[b][2]);
            CHECK(own > 0.8 * volume);
            CHECK(other < 0.1 * volume);
          }
      }
      CHECK(centred[0]);
      CHECK(centred[1]);
    }
  }
}
