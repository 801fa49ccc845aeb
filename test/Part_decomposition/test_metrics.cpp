// Segmentation metrics (hand-computed answers and brute-force references) and area-weighted
// sampling.
#include <catch2/catch.hpp>

#include "segmentation_metrics.h"
#include "test_shapes.h"

#include <cmath>
#include <cstdint>
#include <map>
#include <vector>

namespace PD = CGAL::Part_decomposition;
using test_shapes::Mesh;
using test_shapes::Point;

namespace {

void check_perfect(const PD::Segmentation_scores& s)
{
  CHECK(s.mean_iou == 1.);
  CHECK(s.rand_index == 1.);
  CHECK(s.variation_of_information == Approx(0.).margin(1e-12));
  CHECK(s.segmentation_covering == 1.);
}

// Straight from the definitions of the paper (Appendix A): O(N^2) pairs, entropies, IoU of sets.
PD::Segmentation_scores brute_force(const std::vector<int>& g, const std::vector<int>& p)
{
  const std::size_t n = g.size();
  PD::Segmentation_scores s;
  std::size_t agree = 0, pairs = 0;
  for(std::size_t u = 0; u < n; ++u)
    for(std::size_t v = u + 1; v < n; ++v, ++pairs)
      agree += ((g[u] == g[v]) == (p[u] == p[v]));
  s.rand_index = double(agree) / double(pairs);

  std::map<int, double> pg, pp;
  std::map<std::pair<int, int>, double> pgp;
  for(std::size_t k = 0; k < n; ++k)
  {
    pg[g[k]] += 1. / n;
    pp[p[k]] += 1. / n;
    pgp[{g[k], p[k]}] += 1. / n;
  }
  double hg = 0., hp = 0., mi = 0.;
  for(auto& e : pg) hg -= e.second * std::log(e.second);
  for(auto& e : pp) hp -= e.second * std::log(e.second);
  for(auto& e : pgp) mi += e.second * std::log(e.second / (pg[e.first.first] * pp[e.first.second]));
  s.variation_of_information = hg + hp - 2. * mi;

  double sum_iou = 0., covering = 0.;
  for(auto& gi : pg)
  {
    double best = 0.;
    for(auto& pj : pp)
    {
      std::size_t inter = 0, uni = 0;
      for(std::size_t k = 0; k < n; ++k)
      {
        const bool a = g[k] == gi.first, b = p[k] == pj.first;
        inter += (a && b);
        uni += (a || b);
      }
      best = std::max(best, double(inter) / double(uni));
    }
    sum_iou += best;
    covering += gi.second * best;
  }
  s.mean_iou = sum_iou / double(pg.size());
  s.segmentation_covering = covering;
  return s;
}

// Three disjoint triangles of areas 1, 2 and 5 (in face order) and one of area 0.
Mesh make_weighted_triangles()
{
  Mesh m;
  auto tri = [&](double x0, double base, double height) {
    auto a = m.add_vertex(Point(x0, 0, 0)), b = m.add_vertex(Point(x0 + base, 0, 0)),
         c = m.add_vertex(Point(x0, height, 0));
    m.add_face(a, b, c);
  };
  tri(0., 1., 2.);   // area 1
  tri(10., 2., 2.);  // area 2
  tri(20., 2., 5.);  // area 5
  auto a = m.add_vertex(Point(30, 0, 0)), b = m.add_vertex(Point(31, 0, 0)), c = m.add_vertex(Point(32, 0, 0));
  m.add_face(a, b, c); // collinear: area 0
  return m;
}

} // namespace

TEST_CASE("identical partitions score perfectly, whatever the label values", "[metrics]")
{
  const std::vector<int> g = {0, 0, 1, 1, 1, 2, 2, 0};
  check_perfect(PD::compare_segmentations(g, g));
  const std::vector<long> renamed = {5, 5, -9, -9, -9, 70, 70, 5};
  const PD::Segmentation_scores s = PD::compare_segmentations(g, renamed);
  check_perfect(s);
  CHECK(s.number_of_samples == 8);
  CHECK(s.number_of_ground_truth_parts == 3);
  CHECK(s.number_of_predicted_parts == 3);
}

TEST_CASE("an all-in-one prediction", "[metrics]")
{
  // |G| = 2, 3, 1 of N = 6; P = one part.
  const std::vector<int> g = {0, 0, 1, 1, 1, 2};
  const std::vector<int> p(6, 7);
  const PD::Segmentation_scores s = PD::compare_segmentations(g, p);
  CHECK(s.mean_iou == Approx((2. / 6 + 3. / 6 + 1. / 6) / 3.)); // IoU(G_i, P) = |G_i| / N
  CHECK(s.segmentation_covering == Approx((4. + 9. + 1.) / 36.));
  // 15 pairs; together in G: 1 + 3 = 4, all 15 together in P -> 4 agree.
  CHECK(s.rand_index == Approx(4. / 15.));
  // VoI = H(G) when P is constant.
  CHECK(s.variation_of_information ==
        Approx(std::log(3.) / 3. + std::log(2.) / 2. + std::log(6.) / 6.));
  CHECK(s.number_of_predicted_parts == 1);
}

TEST_CASE("a prediction splitting one part in two halves", "[metrics]")
{
  const std::vector<int> g = {0, 0, 0, 0, 1, 1, 1, 1};
  const std::vector<int> p = {0, 0, 1, 1, 2, 2, 2, 2};
  const PD::Segmentation_scores s = PD::compare_segmentations(g, p);
  CHECK(s.mean_iou == Approx((0.5 + 1.) / 2.));
  CHECK(s.segmentation_covering == Approx(0.5 * 0.5 + 0.5 * 1.));
  // 28 pairs, the 4 pairs across the two halves of G_0 disagree.
  CHECK(s.rand_index == Approx(24. / 28.));
  // H(G|P) = 0, H(P|G) = 1/2 ln 2.
  CHECK(s.variation_of_information == Approx(std::log(2.) / 2.));
}

TEST_CASE("a prediction merging two parts", "[metrics]")
{
  const std::vector<int> g = {0, 0, 1, 1, 2, 2, 2, 2};
  const std::vector<int> p = {0, 0, 0, 0, 1, 1, 1, 1};
  const PD::Segmentation_scores s = PD::compare_segmentations(g, p);
  // Many-to-one: G_0 and G_1 both take P_0 (IoU 1/2).
  CHECK(s.mean_iou == Approx((0.5 + 0.5 + 1.) / 3.));
  CHECK(s.segmentation_covering == Approx(0.25 * 0.5 + 0.25 * 0.5 + 0.5 * 1.));
  CHECK(s.rand_index == Approx(24. / 28.));
  CHECK(s.variation_of_information == Approx(std::log(2.) / 2.));
}

TEST_CASE("an uneven overlap computed by hand", "[metrics]")
{
  // cells: (G0,P0) = 2, (G0,P1) = 1, (G1,P1) = 1
  const std::vector<int> g = {0, 0, 0, 1};
  const std::vector<int> p = {0, 0, 1, 1};
  const PD::Segmentation_scores s = PD::compare_segmentations(g, p);
  CHECK(s.mean_iou == Approx((2. / 3. + 1. / 2.) / 2.));
  CHECK(s.segmentation_covering == Approx(0.75 * 2. / 3. + 0.25 * 0.5));
  CHECK(s.rand_index == Approx(3. / 6.));
  CHECK(s.variation_of_information == Approx(0.75 * std::log(3.)));
  // SC is not symmetric, RI and VoI are: G'_0 = {0,1} takes P'_0 (2/3), G'_1 = {2,3} takes P'_1 (1/2).
  const PD::Segmentation_scores t = PD::compare_segmentations(p, g);
  CHECK(t.mean_iou == Approx((2. / 3. + 1. / 2.) / 2.));
  CHECK(t.segmentation_covering == Approx(0.5 * 2. / 3. + 0.5 * 0.5));
  CHECK(t.rand_index == Approx(s.rand_index));
  CHECK(t.variation_of_information == Approx(s.variation_of_information));
}

TEST_CASE("random labelings match the definitions and ignore relabelling", "[metrics]")
{
  PD::internal::Splitmix64 rng(42);
  for(int trial = 0; trial < 20; ++trial)
  {
    const std::size_t n = 50 + std::size_t(rng.uniform() * 250);
    const int kg = 1 + int(rng.uniform() * 8), kp = 1 + int(rng.uniform() * 12);
    std::vector<int> g(n), p(n);
    for(std::size_t k = 0; k < n; ++k)
    {
      g[k] = int(rng.uniform() * kg);
      // correlated with g half of the time
      p[k] = rng.uniform() < 0.5 ? g[k] % kp : int(rng.uniform() * kp);
    }
    const PD::Segmentation_scores s = PD::compare_segmentations(g, p);
    const PD::Segmentation_scores r = brute_force(g, p);
    CHECK(s.mean_iou == Approx(r.mean_iou));
    CHECK(s.rand_index == Approx(r.rand_index));
    CHECK(s.variation_of_information == Approx(r.variation_of_information).margin(1e-12));
    CHECK(s.segmentation_covering == Approx(r.segmentation_covering));

    // A bijective renaming of either side (other type, sparse, negative) changes nothing.
    std::vector<std::int64_t> g2(n);
    std::vector<unsigned> p2(n);
    for(std::size_t k = 0; k < n; ++k)
    {
      g2[k] = -1000003 * std::int64_t(g[k]) + 17;
      p2[k] = unsigned((p[k] * 7919 + 3) % 100000);
    }
    const PD::Segmentation_scores s2 = PD::compare_segmentations(g2, p2);
    CHECK(s2.mean_iou == s.mean_iou);
    CHECK(s2.rand_index == s.rand_index);
    CHECK(s2.variation_of_information == s.variation_of_information);
    CHECK(s2.segmentation_covering == s.segmentation_covering);
  }
}

TEST_CASE("degenerate labelings", "[metrics]")
{
  const std::vector<int> empty;
  const PD::Segmentation_scores e = PD::compare_segmentations(empty, empty);
  CHECK(e.number_of_samples == 0);
  CHECK(std::isnan(e.mean_iou));
  CHECK(std::isnan(e.rand_index));
  const std::vector<int> one = {3}, other = {8};
  check_perfect(PD::compare_segmentations(one, other)); // no pair: RI = 1
  const std::vector<int> two = {1, 2};
  CHECK_THROWS_AS(PD::compare_segmentations(one, two), std::invalid_argument);
}

TEST_CASE("samples fall on faces in proportion to their area, reproducibly", "[sampling]")
{
  const Mesh m = make_weighted_triangles();
  const std::size_t n = 80000;
  const std::vector<std::size_t> s =
    PD::sample_faces_by_area(m, CGAL::parameters::number_of_points_on_faces(n).random_seed(7u));
  REQUIRE(s.size() == n);
  std::vector<double> count(5, 0.);
  for(std::size_t f : s) count[std::min<std::size_t>(f, 4)] += 1.;
  CHECK(count[4] == 0.); // no index out of range
  const double area[3] = {1., 2., 5.};
  for(int f = 0; f < 3; ++f)
  {
    const double prob = area[f] / 8.;
    const double sigma = std::sqrt(n * prob * (1. - prob));
    CHECK(std::abs(count[f] - n * prob) < 5. * sigma);
  }
  CHECK(count[3] == 0.); // zero area, never drawn

  // Same seed, same samples; another seed, other samples; the default N is 10000.
  CHECK(PD::sample_faces_by_area(m, CGAL::parameters::number_of_points_on_faces(n).random_seed(7u)) == s);
  CHECK(PD::sample_faces_by_area(m, CGAL::parameters::number_of_points_on_faces(n).random_seed(8u)) != s);
  CHECK(PD::sample_faces_by_area(m).size() == 10000);
  CHECK(PD::sample_faces_by_area(m) == PD::sample_faces_by_area(m, CGAL::parameters::random_seed(0u)));
}

TEST_CASE("sampling a mesh of zero area or without faces", "[sampling]")
{
  Mesh flat;
  for(int t = 0; t < 2; ++t)
  {
    auto a = flat.add_vertex(Point(3 * t, 0, 0)), b = flat.add_vertex(Point(3 * t + 1, 0, 0)),
         c = flat.add_vertex(Point(3 * t + 2, 0, 0));
    flat.add_face(a, b, c);
  }
  const std::vector<std::size_t> s =
    PD::sample_faces_by_area(flat, CGAL::parameters::number_of_points_on_faces(1000));
  REQUIRE(s.size() == 1000);
  std::size_t first = 0;
  for(std::size_t f : s) first += (f == 0);
  CHECK(first > 400); // uniform over the two faces
  CHECK(first < 600);

  const Mesh empty;
  CHECK(PD::sample_faces_by_area(empty).empty());
}

TEST_CASE("evaluating face labelings of a sphere", "[metrics][sampling]")
{
  Mesh m = test_shapes::make_sphere(Point(0, 0, 0), 1., 3);
  typedef Mesh::Face_index Face;
  auto upper = m.add_property_map<Face, int>("f:upper", 0).first;
  auto octant = m.add_property_map<Face, std::size_t>("f:octant", 0).first;
  auto whole = m.add_property_map<Face, int>("f:whole", 0).first;
  for(Face f : faces(m))
  {
    double c[3] = {0., 0., 0.};
    for(auto v : vertices_around_face(halfedge(f, m), m))
      for(int a = 0; a < 3; ++a) c[a] += m.point(v)[a];
    upper[f] = c[2] > 0. ? 1 : 0;
    octant[f] = (c[0] > 0.) + 2 * (c[1] > 0.) + 4 * (c[2] > 0.);
  }
  check_perfect(PD::evaluate_segmentation(m, upper, upper));
  check_perfect(PD::evaluate_segmentation(m, octant, octant));

  // All in one against two hemispheres: mIoU = (|G_0| + |G_1|) / (2N) = 1/2 exactly;
  // SC = sum (|G_i|/N)^2 = 1/2 up to the sampling and tessellation noise.
  const PD::Segmentation_scores s = PD::evaluate_segmentation(m, upper, whole);
  CHECK(s.mean_iou == Approx(0.5));
  CHECK(s.segmentation_covering == Approx(0.5).margin(0.01));
  CHECK(s.number_of_samples == 10000);

  // Octants refine hemispheres: every hemisphere is 4 octants of about a quarter of its area.
  const PD::Segmentation_scores t = PD::evaluate_segmentation(
    m, upper, octant, CGAL::parameters::number_of_points_on_faces(20000).random_seed(3u));
  CHECK(t.number_of_samples == 20000);
  CHECK(t.mean_iou == Approx(0.25).margin(0.03));
  CHECK(t.variation_of_information == Approx(std::log(4.)).margin(0.03)); // H(P|G) = ln 4
}

namespace {

typedef Mesh::Face_index Face;

// The box [-1,1]^3 with each side split into 20 x 20 squares: the planes x = -1 + k/10 are
// unions of edges.
Mesh make_cube() { return test_shapes::make_box(Point(-1, -1, -1), Point(1, 1, 1), 20); }

Point face_centroid(const Mesh& m, Face f)
{
  double c[3] = {0., 0., 0.};
  for(auto v : vertices_around_face(halfedge(f, m), m))
    for(int a = 0; a < 3; ++a) c[a] += m.point(v)[a] / 3.;
  return Point(c[0], c[1], c[2]);
}

// Faces labelled by the number of cut planes x = cuts[i] their centroid lies beyond.
Mesh::Property_map<Face, int> label_by_planes(Mesh& m, const std::string& name, const std::vector<double>& cuts)
{
  auto labels = m.add_property_map<Face, int>(name, 0).first;
  for(Face f : faces(m))
    for(double x : cuts) labels[f] += face_centroid(m, f).x() > x ? 1 : 0;
  return labels;
}

// Mean distance from the surface of [-1,1]^3 to its centre, by the midpoint rule on one side
// (all six are alike): (1/4) * integral over [-1,1]^2 of sqrt(1 + y^2 + z^2).
double cube_average_radius()
{
  const int n = 2000;
  double sum = 0.;
  for(int i = 0; i < n; ++i)
    for(int j = 0; j < n; ++j)
    {
      const double y = -1. + (i + 0.5) * 2. / n, z = -1. + (j + 0.5) * 2. / n;
      sum += std::sqrt(1. + y * y + z * z);
    }
  return sum * (4. / (double(n) * n)) / 4.;
}

} // namespace

TEST_CASE("the cut discrepancy of identical segmentations is 0", "[metrics][cut_discrepancy]")
{
  Mesh m = test_shapes::make_sphere(Point(0, 0, 0), 1., 3);
  auto octant = m.add_property_map<Face, int>("f:octant", 0).first;
  auto renamed = m.add_property_map<Face, long>("f:renamed", 0).first;
  for(Face f : faces(m))
  {
    const Point c = face_centroid(m, f);
    octant[f] = (c.x() > 0.) + 2 * (c.y() > 0.) + 4 * (c.z() > 0.);
    renamed[f] = 1000 - 7 * long(octant[f]);
  }
  CHECK(PD::cut_discrepancy(m, octant, octant) == 0.);
  CHECK(PD::cut_discrepancy(m, octant, renamed) == 0.); // labels are compared for equality only
}

TEST_CASE("the cut discrepancy of two parallel cuts of a box is 2d over the average radius",
          "[metrics][cut_discrepancy]")
{
  Mesh m = make_cube();
  const double d = 0.3;
  auto at_0 = label_by_planes(m, "f:at_0", {0.});
  auto at_d = label_by_planes(m, "f:at_d", {d});
  const double radius = cube_average_radius();
  CHECK(radius == Approx(1.2808).epsilon(1e-3)); // the known mean distance of a cube's surface

  // Every point of one square loop is at distance d from the other loop.
  CHECK(PD::cut_discrepancy(m, at_0, at_d) == Approx(2. * d / radius).epsilon(1e-4));
  // One point per cut edge (its midpoint): the same, the distance being to the nearest edge.
  CHECK(PD::cut_discrepancy(m, at_0, at_d, CGAL::parameters::grid_spacing(0.)) ==
        Approx(2. * d / radius).epsilon(1e-4));
  // The box scaled by 5: the same, the measure has no unit.
  Mesh big = make_cube();
  for(auto v : vertices(big)) big.point(v) = Point(5 * big.point(v).x(), 5 * big.point(v).y(), 5 * big.point(v).z());
  auto big_0 = label_by_planes(big, "f:at_0", {0.});
  auto big_d = label_by_planes(big, "f:at_d", {5. * d});
  CHECK(PD::cut_discrepancy(big, big_0, big_d) == Approx(2. * d / radius).epsilon(1e-4));
}

TEST_CASE("the cut discrepancy is a mean per unit length of cut", "[metrics][cut_discrepancy]")
{
  // One loop at x = 0 against loops at x = 0 and x = d: the first lies on the second's cuts
  // (mean 0); half of the second's length is at distance d from the first (mean d / 2).
  Mesh m = make_cube();
  const double d = 0.4;
  auto one = label_by_planes(m, "f:one", {0.});
  auto two = label_by_planes(m, "f:two", {0., d});
  const double expected = (0. + d / 2.) / cube_average_radius();
  CHECK(PD::cut_discrepancy(m, one, two) == Approx(expected).epsilon(1e-4));
  CHECK(PD::cut_discrepancy(m, two, one) == PD::cut_discrepancy(m, one, two));
}

TEST_CASE("the cut discrepancy is symmetric", "[metrics][cut_discrepancy]")
{
  Mesh m = test_shapes::make_sphere(Point(0, 0, 0), 1., 3);
  auto upper = m.add_property_map<Face, int>("f:upper", 0).first;
  auto octant = m.add_property_map<Face, std::size_t>("f:octant", 0).first;
  for(Face f : faces(m))
  {
    const Point c = face_centroid(m, f);
    upper[f] = c.z() > 0.3 ? 1 : 0;
    octant[f] = (c.x() > 0.) + 2 * (c.y() > 0.) + 4 * (c.z() > 0.);
  }
  const double ab = PD::cut_discrepancy(m, upper, octant), ba = PD::cut_discrepancy(m, octant, upper);
  CHECK(ab > 0.1);
  CHECK(ab == ba);
}

TEST_CASE("the cut discrepancy of segmentations without cuts", "[metrics][cut_discrepancy]")
{
  Mesh m = make_cube();
  auto whole = m.add_property_map<Face, int>("f:whole", 0).first;
  auto other = m.add_property_map<Face, int>("f:other", 9).first;
  auto halves = label_by_planes(m, "f:halves", {0.});
  CHECK(PD::cut_discrepancy(m, whole, other) == 0.);         // neither has a cut
  CHECK(std::isnan(PD::cut_discrepancy(m, whole, halves)));  // undefined: one has none
  CHECK(std::isnan(PD::cut_discrepancy(m, halves, whole)));

  // Two boxes labelled by box: labels differ across no edge, so there is no cut.
  Mesh two = make_cube();
  test_shapes::append(two, test_shapes::make_box(Point(3, 0, 0), Point(4, 1, 1), 4));
  auto by_box = two.add_property_map<Face, int>("f:by_box", 0).first;
  auto one = two.add_property_map<Face, int>("f:one", 0).first;
  for(Face f : faces(two)) by_box[f] = face_centroid(two, f).x() > 2. ? 1 : 0;
  CHECK(PD::cut_discrepancy(two, by_box, one) == 0.);

  // An open mesh: its border edges are not cuts, so one interior edge is the only cut.
  Mesh strip;
  const auto a = strip.add_vertex(Point(0, 0, 0)), b = strip.add_vertex(Point(1, 0, 0)),
             c = strip.add_vertex(Point(1, 1, 0)), e = strip.add_vertex(Point(0, 1, 0));
  strip.add_face(a, b, c);
  strip.add_face(a, c, e);
  auto split = strip.add_property_map<Face, int>("f:split", 0).first;
  auto same = strip.add_property_map<Face, int>("f:same", 0).first;
  split[*faces(strip).begin()] = 1;
  CHECK(PD::cut_discrepancy(strip, split, split) == 0.);
  CHECK(std::isnan(PD::cut_discrepancy(strip, split, same)));
}

namespace {

// The mean distance from the surface of the L-bracket prism (plates [0,la]x[0,t] and [0,t]x[0,lb],
// z in [0,w]) to its area centroid, by the midpoint rule on the rectangles of its boundary.
double l_bracket_average_radius(double la, double lb, double t, double w)
{
  struct Rectangle { std::array<double, 3> o, u, v; };
  const std::vector<Rectangle> sides = {
    {{0, 0, 0}, {la, 0, 0}, {0, t, 0}}, {{0, t, 0}, {t, 0, 0}, {0, lb - t, 0}},  // cap z = 0
    {{0, 0, w}, {la, 0, 0}, {0, t, 0}}, {{0, t, w}, {t, 0, 0}, {0, lb - t, 0}},  // cap z = w
    {{0, 0, 0}, {la, 0, 0}, {0, 0, w}}, {{la, 0, 0}, {0, t, 0}, {0, 0, w}},      // y = 0, x = la
    {{t, t, 0}, {la - t, 0, 0}, {0, 0, w}}, {{t, t, 0}, {0, lb - t, 0}, {0, 0, w}}, // y = t, x = t
    {{0, lb, 0}, {t, 0, 0}, {0, 0, w}}, {{0, 0, 0}, {0, lb, 0}, {0, 0, w}}};     // y = lb, x = 0
  const int n = 300;
  auto integrate = [&](auto f) {
    double sum = 0.;
    for(const Rectangle& r : sides)
    {
      // u and v are along axes: |u| |v| is the sum of their coordinates
      const double area = (r.u[0] + r.u[1] + r.u[2]) * (r.v[0] + r.v[1] + r.v[2]);
      for(int i = 0; i < n; ++i)
        for(int j = 0; j < n; ++j)
        {
          std::array<double, 3> p;
          for(int a = 0; a < 3; ++a) p[a] = r.o[a] + (i + 0.5) / n * r.u[a] + (j + 0.5) / n * r.v[a];
          sum += f(p) * area / (double(n) * n);
        }
    }
    return sum;
  };
  const double area = integrate([](const std::array<double, 3>&) { return 1.; });
  std::array<double, 3> c;
  for(int a = 0; a < 3; ++a) c[a] = integrate([a](const std::array<double, 3>& p) { return p[a]; }) / area;
  return integrate([&c](const std::array<double, 3>& p) {
           return std::sqrt(std::pow(p[0] - c[0], 2) + std::pow(p[1] - c[1], 2) + std::pow(p[2] - c[2], 2));
         }) / area;
}

} // namespace

TEST_CASE("the L-bracket test shape and the cut discrepancy of its corner", "[metrics][cut_discrepancy]")
{
  const double la = 1., lb = 0.6, t = 0.1, w = 0.4;
  std::vector<int> plate;
  Mesh m = test_shapes::make_l_bracket(la, lb, t, w, 0.05, &plate);
  REQUIRE(plate.size() == num_faces(m));
  CHECK(CGAL::is_closed(m));
  CHECK(CGAL::is_triangle_mesh(m));
  // outward: positive volume (divergence theorem), and the volume of the two plates
  double volume = 0., area_b = 0.;
  for(Face f : faces(m))
  {
    std::vector<Point> p;
    for(auto v : vertices_around_face(halfedge(f, m), m)) p.push_back(m.point(v));
    volume += CGAL::scalar_product(p[0] - CGAL::ORIGIN, CGAL::cross_product(p[1] - CGAL::ORIGIN, p[2] - CGAL::ORIGIN)) / 6.;
    if(plate[std::size_t(f)] == 1) area_b += std::sqrt(CGAL::squared_area(p[0], p[1], p[2]));
  }
  CHECK(volume == Approx((la * t + (lb - t) * t) * w));
  // plate B's faces: its two walls along y, its end and its two caps, above y = t
  CHECK(area_b == Approx(2 * (lb - t) * w + t * w + 2 * t * (lb - t)));

  // The corner square to plate A (truth) or to plate B: the two cuts are the same corner line
  // and two loops t apart (caps: segments meeting at the corner, mean distance t / 2), so each
  // side's mean is t / 2 and CD = t / R.
  auto truth = m.add_property_map<Face, int>("f:truth", 0).first;
  auto corner_to_b = m.add_property_map<Face, int>("f:corner_to_b", 0).first;
  for(Face f : faces(m))
  {
    truth[f] = plate[std::size_t(f)];
    bool right = false; // a vertex with x > t: plate A without the corner
    for(auto v : vertices_around_face(halfedge(f, m), m)) right = right || m.point(v).x() > t;
    corner_to_b[f] = right ? 0 : 1;
  }
  CHECK(PD::cut_discrepancy(m, truth, corner_to_b) == Approx(t / l_bracket_average_radius(la, lb, t, w)).epsilon(1e-3));
}
