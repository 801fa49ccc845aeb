// Copyright (c) 2026 The Part_decomposition authors.
// All rights reserved.
//
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Author(s)     : The Part_decomposition authors

#ifndef CGAL_PART_DECOMPOSITION_BENCHMARK_SEGMENTATION_METRICS_H
#define CGAL_PART_DECOMPOSITION_BENCHMARK_SEGMENTATION_METRICS_H

// The evaluation metrics of the benchmark and of the tests (the paper's protocol, Appendix A): they
// score a decomposition and are not part of it, so they live here and not in the package.

#include <CGAL/Part_decomposition/parameters.h>

#include <CGAL/Bbox_3.h>
#include <CGAL/assertions.h>
#include <CGAL/boost/graph/helpers.h>
#include <CGAL/boost/graph/iterator.h>
#include <CGAL/boost/graph/named_params_helper.h>
#include <CGAL/Orthogonal_k_neighbor_search.h>
#include <CGAL/Search_traits_3.h>
#include <CGAL/Search_traits_adapter.h>
#include <CGAL/number_utils.h>
#include <CGAL/property_map.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <iterator>
#include <limits>
#include <stdexcept>
#include <unordered_map>
#include <vector>

namespace CGAL {
namespace Part_decomposition {

/*!
The agreement between a ground-truth and a predicted partition of the same point samples, as
defined in the evaluation protocol of the Hi-TOPS paper (Appendix A). Every metric is
class-agnostic: only which samples share a part matters, not the values of the labels.
*/
struct Segmentation_scores
{
  /// the mean, over the ground-truth parts \f$G_i\f$, of \f$\max_j \mathrm{IoU}(G_i, P_j)\f$: each
  /// ground-truth part takes its best-overlapping predicted part, several may take the same one.
  double mean_iou = 0.;
  /// the fraction of the sample pairs on which both partitions agree (same part in both, or
  /// different parts in both).
  double rand_index = 0.;
  /// \f$H(G) + H(P) - 2 I(G;P)\f$ with natural logarithms (nats); 0 for identical partitions.
  double variation_of_information = 0.;
  /// \f$\sum_i \frac{|G_i|}{N} \max_j \mathrm{IoU}(G_i, P_j)\f$.
  double segmentation_covering = 0.;
  /// \f$N\f$, the number of samples.
  std::size_t number_of_samples = 0;
  /// the number of ground-truth parts holding at least one sample.
  std::size_t number_of_ground_truth_parts = 0;
  /// the number of predicted parts holding at least one sample.
  std::size_t number_of_predicted_parts = 0;
};

/// \cond SKIP_IN_MANUAL
namespace internal {

// splitmix64 (Steele, Lea, Flood 2014): the same stream on every platform and standard library.
class Splitmix64
{
public:
  explicit Splitmix64(std::uint64_t seed) : m_state(seed) {}
  std::uint64_t next()
  {
    std::uint64_t z = (m_state += 0x9E3779B97F4A7C15ull);
    z = (z ^ (z >> 30)) * 0xBF58476D1CE4E5B9ull;
    z = (z ^ (z >> 27)) * 0x94D049BB133111EBull;
    return z ^ (z >> 31);
  }
  // uniform in [0, 1): the 53 high bits as the mantissa.
  double uniform() { return double(next() >> 11) * (1. / 9007199254740992.); }

private:
  std::uint64_t m_state;
};

// Dense ids 0..K-1 in order of first appearance; returns K.
template <typename Iterator>
std::size_t compact_labels(Iterator first, Iterator last, std::vector<std::size_t>& ids)
{
  typedef typename std::iterator_traits<Iterator>::value_type Label;
  std::unordered_map<Label, std::size_t> index;
  ids.clear();
  for(; first != last; ++first)
    ids.push_back(index.emplace(*first, index.size()).first->second);
  return index.size();
}

inline double x_log_x(std::size_t n) { return n == 0 ? 0. : double(n) * std::log(double(n)); }

} // namespace internal
/// \endcond

/*!
draws `N` points on the faces of `tm` with probability proportional to the face areas (independent
draws) and returns, for each of them in drawing order, the index of the face it lies on, counted in
the iteration order of `faces(tm)`. The draws come from a self-contained splitmix64 generator, so
the same mesh and seed give the same samples with every compiler and standard library.

If the total area of `tm` is zero (every face is degenerate), the faces are drawn uniformly
instead; if `tm` has no face, the result is empty.

\par Complexity
\f$O(F + N \log F)\f$ for \f$F\f$ faces: a prefix sum of the areas, then a binary search per draw.

\tparam TriangleMesh a model of `FaceListGraph`
\tparam NamedParameters a sequence of named parameters

\param tm the mesh
\param np an optional sequence of named parameters among the ones listed below

\cgalNamedParamsBegin
  \cgalParamNBegin{number_of_points_on_faces}
    \cgalParamDescription{the number `N` of samples}
    \cgalParamType{`std::size_t`}
    \cgalParamDefault{`10000`}
  \cgalParamNEnd
  \cgalParamNBegin{random_seed}
    \cgalParamDescription{the seed of the generator}
    \cgalParamType{an unsigned integer type}
    \cgalParamDefault{`0`}
  \cgalParamNEnd
  \cgalParamNBegin{vertex_point_map}
    \cgalParamDescription{a property map associating points to the vertices of `tm`}
    \cgalParamType{a class model of `ReadablePropertyMap` with
                   `boost::graph_traits<TriangleMesh>::%vertex_descriptor` as key type and
                   `%Point_3` as value type}
    \cgalParamDefault{`boost::get(CGAL::vertex_point, tm)`}
  \cgalParamNEnd
  \cgalParamNBegin{geom_traits}
    \cgalParamDescription{an instance of a geometric traits class}
    \cgalParamType{a class model of `Kernel`}
    \cgalParamDefault{a \cgal kernel deduced from the point type, using `CGAL::Kernel_traits`}
  \cgalParamNEnd
\cgalNamedParamsEnd

\pre `CGAL::is_triangle_mesh(tm)`

\returns the face index of each sample.
*/
template <typename TriangleMesh,
          typename NamedParameters = CGAL::parameters::Default_named_parameters>
std::vector<std::size_t>
sample_faces_by_area(const TriangleMesh& tm,
                     const NamedParameters& np = CGAL::parameters::default_values())
{
  using CGAL::parameters::choose_parameter;
  using CGAL::parameters::get_parameter;
  typedef typename boost::graph_traits<TriangleMesh>::face_descriptor face_descriptor;
  typedef typename GetGeomTraits<TriangleMesh, NamedParameters>::type GT;
  typedef typename GetVertexPointMap<TriangleMesh, NamedParameters>::const_type VPM;

  CGAL_precondition(CGAL::is_triangle_mesh(tm));
  const std::size_t n = choose_parameter(get_parameter(np, CGAL::internal_np::number_of_points_on_faces),
                                         std::size_t(10000));
  const std::uint64_t seed = static_cast<std::uint64_t>(
    choose_parameter(get_parameter(np, CGAL::internal_np::random_seed), 0u));
  const GT gt = choose_parameter<GT>(get_parameter(np, CGAL::internal_np::geom_traits));
  const VPM vpm = choose_parameter(get_parameter(np, CGAL::internal_np::vertex_point),
                                   get_const_property_map(CGAL::vertex_point, tm));
  const auto squared_area = gt.compute_squared_area_3_object();

  // Prefix sums of the areas, in face iteration order (sequential: the same on every run).
  std::vector<double> cumulative;
  for(face_descriptor f : faces(tm))
  {
    const auto h = halfedge(f, tm);
    const double a2 = CGAL::to_double(squared_area(get(vpm, source(h, tm)), get(vpm, target(h, tm)),
                                                   get(vpm, target(next(h, tm), tm))));
    const double a = (a2 > 0. && std::isfinite(a2)) ? std::sqrt(a2) : 0.;
    cumulative.push_back((cumulative.empty() ? 0. : cumulative.back()) + a);
  }
  std::vector<std::size_t> samples;
  const std::size_t nf = cumulative.size();
  if(nf == 0) return samples;
  samples.reserve(n);
  internal::Splitmix64 rng(seed);
  const double total = cumulative.back();
  if(!(total > 0.) || !std::isfinite(total))
  {
    for(std::size_t i = 0; i < n; ++i)
      samples.push_back((std::min)(nf - 1, std::size_t(rng.uniform() * double(nf))));
    return samples;
  }
  // u * total may round up to total: fall back to the last face of positive area.
  const std::size_t last_positive =
    std::size_t(std::lower_bound(cumulative.begin(), cumulative.end(), total) - cumulative.begin());
  for(std::size_t i = 0; i < n; ++i)
  {
    const double u = rng.uniform() * total;
    // The first face whose prefix sum exceeds u: faces of zero area are never chosen.
    std::size_t f = std::size_t(std::upper_bound(cumulative.begin(), cumulative.end(), u) - cumulative.begin());
    samples.push_back(f < nf ? f : last_positive);
  }
  return samples;
}

/*!
scores the predicted partition `prediction` of \f$N\f$ samples against the ground-truth partition
`ground_truth` of the same samples (the \f$k\f$-th label of each range belongs to the \f$k\f$-th
sample). Labels are compared for equality only, so renaming the parts of either partition changes
nothing. With \f$n_{ij}\f$ the number of samples in ground-truth part \f$G_i\f$ and predicted part
\f$P_j\f$, \f$a_i = |G_i|\f$ and \f$b_j = |P_j|\f$:
- \f$\mathrm{IoU}(G_i, P_j) = n_{ij} / (a_i + b_j - n_{ij})\f$; mIoU averages
  \f$\max_j \mathrm{IoU}(G_i,P_j)\f$ over the ground-truth parts, segmentation covering weights
  it by \f$a_i / N\f$;
- the Rand index is computed from the contingency table:
  \f$1 - \big(\sum_i \binom{a_i}{2} + \sum_j \binom{b_j}{2} - 2\sum_{ij}\binom{n_{ij}}{2}\big) / \binom{N}{2}\f$,
  and is 1 when \f$N < 2\f$;
- the variation of information is
  \f$\frac{1}{N}\big(\sum_i a_i\ln a_i + \sum_j b_j\ln b_j - 2\sum_{ij} n_{ij}\ln n_{ij}\big)\f$,
  in nats (divide by \f$\ln 2\f$ for bits).

The cost is linear in \f$N\f$ plus the number of ground-truth and predicted parts.
If \f$N = 0\f$, the four metrics are NaN.

\par Complexity
Linear in \f$N\f$ and in the numbers of parts (expected: the labels are hashed).

\tparam GroundTruthRange a range of labels (a type with `std::hash` and `operator==`, such as an
        integer type)
\tparam PredictionRange likewise, possibly of another label type

\throws std::invalid_argument if the two ranges have different sizes.
*/
template <typename GroundTruthRange, typename PredictionRange>
Segmentation_scores compare_segmentations(const GroundTruthRange& ground_truth,
                                          const PredictionRange& prediction)
{
  std::vector<std::size_t> g, p;
  const std::size_t kg = internal::compact_labels(std::begin(ground_truth), std::end(ground_truth), g);
  const std::size_t kp = internal::compact_labels(std::begin(prediction), std::end(prediction), p);
  if(g.size() != p.size())
    throw std::invalid_argument("compare_segmentations: the two labelings have different sizes");

  Segmentation_scores s;
  const std::size_t n = g.size();
  s.number_of_samples = n;
  s.number_of_ground_truth_parts = kg;
  s.number_of_predicted_parts = kp;
  if(n == 0)
  {
    s.mean_iou = s.rand_index = s.variation_of_information = s.segmentation_covering =
      std::numeric_limits<double>::quiet_NaN();
    return s;
  }

  std::vector<std::size_t> a(kg, 0), b(kp, 0);
  for(std::size_t k = 0; k < n; ++k) { ++a[g[k]]; ++b[p[k]]; }

  // Samples grouped by ground-truth part (counting sort), then each group's row of the table.
  std::vector<std::size_t> start(kg + 1, 0);
  for(std::size_t i = 0; i < kg; ++i) start[i + 1] = start[i] + a[i];
  std::vector<std::size_t> by_gt(n), fill(start.begin(), start.end() - 1);
  for(std::size_t k = 0; k < n; ++k) by_gt[fill[g[k]]++] = p[k];

  std::vector<std::size_t> row(kp, 0), touched;
  std::uint64_t same_both = 0; // sum over cells of C(n_ij, 2)
  double cells_xlogx = 0., sum_iou = 0., covering = 0.;
  for(std::size_t i = 0; i < kg; ++i)
  {
    touched.clear();
    for(std::size_t k = start[i]; k < start[i + 1]; ++k)
      if(row[by_gt[k]]++ == 0) touched.push_back(by_gt[k]);
    double best = 0.;
    for(std::size_t j : touched)
    {
      const std::size_t nij = row[j];
      same_both += std::uint64_t(nij) * (nij - 1) / 2;
      cells_xlogx += internal::x_log_x(nij);
      best = (std::max)(best, double(nij) / double(a[i] + b[j] - nij));
      row[j] = 0;
    }
    sum_iou += best;
    covering += double(a[i]) * best;
  }

  std::uint64_t same_gt = 0, same_pred = 0;
  double gt_xlogx = 0., pred_xlogx = 0.;
  for(std::size_t ai : a) { same_gt += std::uint64_t(ai) * (ai - 1) / 2; gt_xlogx += internal::x_log_x(ai); }
  for(std::size_t bj : b) { same_pred += std::uint64_t(bj) * (bj - 1) / 2; pred_xlogx += internal::x_log_x(bj); }

  s.mean_iou = sum_iou / double(kg);
  s.segmentation_covering = covering / double(n);
  const std::uint64_t pairs = std::uint64_t(n) * (n - 1) / 2;
  // disagreements = pairs together in exactly one partition
  s.rand_index = pairs == 0 ? 1.
                            : 1. - double(same_gt + same_pred - 2 * same_both) / double(pairs);
  s.variation_of_information = (std::max)(0., (gt_xlogx + pred_xlogx - 2. * cells_xlogx) / double(n));
  return s;
}

/*!
scores the predicted segmentation of the faces of `tm` against a ground-truth segmentation of the
same faces, following the paper's protocol (Appendix A): `N` points are drawn on the surface with
`sample_faces_by_area()`, each takes the ground-truth and the predicted label of its face, and the
two labelings are compared with `compare_segmentations()`. With several ground truths of one
shape, call this once per ground truth with the same seed (the samples are then the same) and
average the scores.

\par Complexity
\f$O(F + N \log F)\f$ for \f$F\f$ faces and \f$N\f$ = `number_of_points_on_faces`.

\tparam TriangleMesh a model of `FaceListGraph`
\tparam GroundTruthMap a model of `ReadablePropertyMap` with
        `boost::graph_traits<TriangleMesh>::%face_descriptor` as key type and a label type (with
        `std::hash` and `operator==`, such as an integer type) as value type
\tparam PredictionMap likewise
\tparam NamedParameters a sequence of named parameters

\param tm the mesh
\param ground_truth the ground-truth part of each face
\param prediction the predicted part of each face
\param np an optional sequence of named parameters among the ones listed below

\cgalNamedParamsBegin
  \cgalParamNBegin{number_of_points_on_faces}
    \cgalParamDescription{the number `N` of samples}
    \cgalParamType{`std::size_t`}
    \cgalParamDefault{`10000`}
  \cgalParamNEnd
  \cgalParamNBegin{random_seed}
    \cgalParamDescription{the seed of the sample generator}
    \cgalParamType{an unsigned integer type}
    \cgalParamDefault{`0`}
  \cgalParamNEnd
  \cgalParamNBegin{vertex_point_map}
    \cgalParamDescription{a property map associating points to the vertices of `tm`}
    \cgalParamType{a class model of `ReadablePropertyMap` with
                   `boost::graph_traits<TriangleMesh>::%vertex_descriptor` as key type and
                   `%Point_3` as value type}
    \cgalParamDefault{`boost::get(CGAL::vertex_point, tm)`}
  \cgalParamNEnd
  \cgalParamNBegin{geom_traits}
    \cgalParamDescription{an instance of a geometric traits class}
    \cgalParamType{a class model of `Kernel`}
    \cgalParamDefault{a \cgal kernel deduced from the point type, using `CGAL::Kernel_traits`}
  \cgalParamNEnd
\cgalNamedParamsEnd

\pre `CGAL::is_triangle_mesh(tm)`

\returns the scores; see `sample_faces_by_area()` for meshes of zero area or without faces.
*/
template <typename TriangleMesh, typename GroundTruthMap, typename PredictionMap,
          typename NamedParameters = CGAL::parameters::Default_named_parameters>
Segmentation_scores evaluate_segmentation(const TriangleMesh& tm,
                                          GroundTruthMap ground_truth,
                                          PredictionMap prediction,
                                          const NamedParameters& np = CGAL::parameters::default_values())
{
  typedef typename boost::graph_traits<TriangleMesh>::face_descriptor face_descriptor;
  typedef typename boost::property_traits<GroundTruthMap>::value_type Ground_truth_label;
  typedef typename boost::property_traits<PredictionMap>::value_type Predicted_label;

  const std::vector<face_descriptor> face_list(faces(tm).begin(), faces(tm).end());
  const std::vector<std::size_t> samples = sample_faces_by_area(tm, np);
  std::vector<Ground_truth_label> g;
  std::vector<Predicted_label> p;
  g.reserve(samples.size());
  p.reserve(samples.size());
  for(std::size_t f : samples)
  {
    g.push_back(get(ground_truth, face_list[f]));
    p.push_back(get(prediction, face_list[f]));
  }
  return compare_segmentations(g, p);
}

/// \cond SKIP_IN_MANUAL
namespace internal {

// Points along the cut edges of one labeling, each standing for the piece of edge around it.
template <typename GT>
struct Cut_samples
{
  std::vector<typename GT::Point_3> points;
  std::vector<double> lengths;                  // the length of edge each point stands for
  std::vector<std::size_t> segment_of;          // the cut edge of each point, in `segments`
  std::vector<typename GT::Segment_3> segments; // the cut edges
};

// The edges whose two faces carry different labels (border edges are not cuts), each cut in
// ceil(length / spacing) equal pieces (one if spacing is 0) sampled at their midpoints.
template <typename TriangleMesh, typename VPM, typename LabelMap, typename GT>
void sample_cuts(const TriangleMesh& tm, const VPM& vpm, const LabelMap& labels, double spacing,
                 const GT& gt, Cut_samples<GT>& out)
{
  typedef typename GT::Point_3 Point_3;
  const auto barycenter = gt.construct_barycenter_3_object();
  const auto squared_distance = gt.compute_squared_distance_3_object();
  const auto segment = gt.construct_segment_3_object();
  for(auto e : edges(tm))
  {
    const auto h = halfedge(e, tm), o = opposite(h, tm);
    if(is_border(h, tm) || is_border(o, tm) || get(labels, face(h, tm)) == get(labels, face(o, tm)))
      continue;
    const Point_3 a = get(vpm, source(h, tm)), b = get(vpm, target(h, tm));
    const double length = std::sqrt(CGAL::to_double(squared_distance(a, b)));
    const double pieces = spacing > 0. ? std::ceil(length / spacing) : 1.;
    const std::size_t n = pieces > 1. ? std::size_t(pieces) : 1;
    for(std::size_t i = 0; i < n; ++i)
    {
      const double t = (double(i) + 0.5) / double(n);
      out.points.push_back(barycenter(a, 1. - t, b));
      out.lengths.push_back(length / double(n));
      out.segment_of.push_back(out.segments.size());
    }
    out.segments.push_back(segment(a, b));
  }
}

// The mean over the points of `from`, weighted by length, of the distance to the cut edge that
// holds the nearest point of `to`: at least the distance to the cuts of `to`, at most that plus
// half the spacing.
template <typename GT>
double mean_distance_to_cuts(const Cut_samples<GT>& from, const Cut_samples<GT>& to, const GT& gt)
{
  typedef typename GT::Point_3 Point_3;
  typedef typename CGAL::Pointer_property_map<Point_3>::const_type Point_map;
  typedef CGAL::Search_traits_3<GT> Base_traits;
  typedef CGAL::Search_traits_adapter<std::size_t, Point_map, Base_traits> Traits;
  typedef CGAL::Distance_adapter<std::size_t, Point_map, CGAL::Euclidean_distance<Base_traits> > Distance;
  typedef CGAL::Orthogonal_k_neighbor_search<Traits, Distance> Search;
  typedef typename Search::Tree Tree;

  const Point_map point_map = CGAL::make_property_map(to.points);
  std::vector<std::size_t> ids(to.points.size());
  for(std::size_t i = 0; i < ids.size(); ++i) ids[i] = i;
  Tree tree(ids.begin(), ids.end(), typename Tree::Splitter(), Traits(point_map));
  tree.build();
  const Distance distance(point_map);
  const auto squared_distance = gt.compute_squared_distance_3_object();
  double weighted = 0., total = 0., plain = 0.;
  for(std::size_t i = 0; i < from.points.size(); ++i)
  {
    const Search search(tree, from.points[i], 1, 0., true, distance);
    const std::size_t j = search.begin()->first;
    // the smaller of the two: a point on both cuts is at distance 0 exactly, without rounding
    const double d = std::sqrt((std::min)(CGAL::to_double(search.begin()->second),
      CGAL::to_double(squared_distance(from.points[i], to.segments[to.segment_of[j]]))));
    weighted += from.lengths[i] * d;
    total += from.lengths[i];
    plain += d;
  }
  // every cut edge of zero length: the plain mean
  return total > 0. ? weighted / total : plain / double(from.points.size());
}

// The area-weighted mean distance from the surface to its area centroid. The integral over a face
// is the centroid rule on its regular split into sub-triangles whose edges are at most `h` long.
template <typename TriangleMesh, typename VPM>
double average_radius(const TriangleMesh& tm, const VPM& vpm, double h)
{
  std::vector<std::array<double, 9> > triangles;
  std::vector<double> areas;
  double area = 0., c[3] = {0., 0., 0.};
  for(auto f : faces(tm))
  {
    const auto hf = halfedge(f, tm);
    std::array<double, 9> t;
    int k = 0;
    for(auto v : {source(hf, tm), target(hf, tm), target(next(hf, tm), tm)})
    {
      const auto p = get(vpm, v);
      t[k++] = CGAL::to_double(p.x());
      t[k++] = CGAL::to_double(p.y());
      t[k++] = CGAL::to_double(p.z());
    }
    const double u[3] = {t[3] - t[0], t[4] - t[1], t[5] - t[2]}, w[3] = {t[6] - t[0], t[7] - t[1], t[8] - t[2]};
    const double n[3] = {u[1] * w[2] - u[2] * w[1], u[2] * w[0] - u[0] * w[2], u[0] * w[1] - u[1] * w[0]};
    const double a = 0.5 * std::sqrt(n[0] * n[0] + n[1] * n[1] + n[2] * n[2]);
    for(int i = 0; i < 3; ++i) c[i] += a * (t[i] + t[3 + i] + t[6 + i]) / 3.;
    area += a;
    triangles.push_back(t);
    areas.push_back(a);
  }
  if(!(area > 0.)) return 0.;
  for(int i = 0; i < 3; ++i) c[i] /= area;

  auto distance = [&c](const std::array<double, 9>& t, double s, double r) {
    double d2 = 0.;
    for(int i = 0; i < 3; ++i)
    {
      const double x = t[i] + s * (t[3 + i] - t[i]) + r * (t[6 + i] - t[i]) - c[i];
      d2 += x * x;
    }
    return std::sqrt(d2);
  };
  double sum = 0.;
  for(std::size_t f = 0; f < triangles.size(); ++f)
  {
    const std::array<double, 9>& t = triangles[f];
    double longest = 0.;
    for(int e = 0; e < 3; ++e)
    {
      const int a = 3 * e, b = 3 * ((e + 1) % 3);
      longest = (std::max)(longest, std::sqrt(CGAL::square(t[a] - t[b]) + CGAL::square(t[a + 1] - t[b + 1]) +
                                              CGAL::square(t[a + 2] - t[b + 2])));
    }
    const int m = h > 0. ? int((std::min)(1024., (std::max)(1., std::ceil(longest / h)))) : 1;
    double face_sum = 0.;
    for(int i = 0; i < m; ++i)
      for(int j = 0; i + j < m; ++j)
      {
        face_sum += distance(t, (i + 1. / 3.) / m, (j + 1. / 3.) / m); // upward sub-triangle
        if(i + j + 1 < m) face_sum += distance(t, (i + 2. / 3.) / m, (j + 2. / 3.) / m); // downward
      }
    sum += areas[f] * face_sum / (double(m) * double(m));
  }
  return sum / area;
}

} // namespace internal
/// \endcond

/*!
computes the Cut Discrepancy of the Princeton segmentation benchmark (Chen, Golovinskiy and
Funkhouser, "A Benchmark for 3D Mesh Segmentation", SIGGRAPH 2009) between two segmentations of
the faces of `tm`: 0 when their boundaries coincide, larger as they lie further apart.

The <em>cuts</em> of a segmentation are the edges whose two incident faces carry different labels;
border edges are never cuts, and neither are the edges between faces of the same label, so two
faces of one label in different components make no cut. Labels are compared for equality only.
With \f$C_1\f$ and \f$C_2\f$ the cuts of `ground_truth` and `prediction`,
\f[
\mathrm{CD} = \frac{\bar d(C_1, C_2) + \bar d(C_2, C_1)}{\bar R},
\qquad \bar d(C_a, C_b) = \text{mean over the points } p \text{ of } C_a \text{ of } \min_{q \in C_b} |p - q|,
\f]
where \f$\bar R\f$ is the average radius of the surface, the area-weighted mean distance from
the surface to its area centroid. The measure is symmetric in the two segmentations.

<b>Euclidean, not geodesic.</b> The Princeton benchmark measures the distance from a cut to the
other cuts along the surface (geodesic distance). This function uses the straight-line distance
in space, which is never larger and equals it when the shortest path is a straight segment on
the surface (cuts on one flat region); on a curved or folded surface the two differ, so the
values are not those of the Princeton tables.

<b>Discretization.</b> The mean \f$\bar d\f$ is taken over points placed along every cut edge at
the midpoints of \f$\lceil \ell / s \rceil\f$ equal pieces of the edge of length \f$\ell\f$
(at least its midpoint), each weighted by its piece's length, so that it is a mean per unit
length of cut. The distance of a point to \f$C_b\f$ is the smaller of its distances to the nearest
point of \f$C_b\f$ (a kd-tree query) and to the cut edge holding that point: at least the exact
distance, at most the exact distance plus \f$s/2\f$. \f$\bar R\f$ integrates by the centroid rule over a regular split of
each face into sub-triangles of edges at most 1/128 of the bounding-box diagonal (at most
\f$1024^2\f$ per face).

<b>Segmentations without cuts.</b> If neither segmentation has a cut (each gives one label to
every face of a connected component, for example both a single part), the result is 0. If exactly one of them
has no cut, the measure is undefined and the result is NaN: a caller averaging over several
ground truths skips it. The result is NaN too if the average radius is 0 (every face is
degenerate).

\par Complexity
\f$O(E + n \log n)\f$ for \f$E\f$ edges and \f$n\f$ points on the cuts (the cut length over
\f$s\f$), plus the integral of \f$\bar R\f$, \f$O(F + A / h^2)\f$ for \f$F\f$ faces of total
area \f$A\f$ and \f$h\f$ 1/128 of the diagonal.

\tparam TriangleMesh a model of `FaceListGraph`, `EdgeListGraph` and `VertexListGraph`
\tparam GroundTruthMap a model of `ReadablePropertyMap` with
        `boost::graph_traits<TriangleMesh>::%face_descriptor` as key type and a label type (with
        `operator==`, such as an integer type) as value type
\tparam PredictionMap likewise, possibly of another label type
\tparam NamedParameters a sequence of named parameters

\param tm the mesh
\param ground_truth the ground-truth part of each face
\param prediction the predicted part of each face
\param np an optional sequence of named parameters among the ones listed below

\cgalNamedParamsBegin
  \cgalParamNBegin{grid_spacing}
    \cgalParamDescription{the spacing \f$s\f$ of the points along the cuts; 0 places one point at
                          the midpoint of each cut edge}
    \cgalParamType{`double`, at least 0}
    \cgalParamDefault{1/1000 of the diagonal of the bounding box of the vertices}
  \cgalParamNEnd
  \cgalParamNBegin{vertex_point_map}
    \cgalParamDescription{a property map associating points to the vertices of `tm`}
    \cgalParamType{a class model of `ReadablePropertyMap` with
                   `boost::graph_traits<TriangleMesh>::%vertex_descriptor` as key type and
                   `%Point_3` as value type}
    \cgalParamDefault{`boost::get(CGAL::vertex_point, tm)`}
  \cgalParamNEnd
  \cgalParamNBegin{geom_traits}
    \cgalParamDescription{an instance of a geometric traits class}
    \cgalParamType{a class model of `Kernel`}
    \cgalParamDefault{a \cgal kernel deduced from the point type, using `CGAL::Kernel_traits`}
  \cgalParamNEnd
\cgalNamedParamsEnd

\pre `CGAL::is_triangle_mesh(tm)`
\pre the spacing is not negative.

\returns the cut discrepancy (a length over a length: no unit), 0 or NaN as described above.

\sa `evaluate_segmentation()`, which samples the surface and gives the region-based scores; the
cut discrepancy is a separate function because it needs the faces and their labels, not samples.
*/
template <typename TriangleMesh, typename GroundTruthMap, typename PredictionMap,
          typename NamedParameters = CGAL::parameters::Default_named_parameters>
double cut_discrepancy(const TriangleMesh& tm,
                       GroundTruthMap ground_truth,
                       PredictionMap prediction,
                       const NamedParameters& np = CGAL::parameters::default_values())
{
  using CGAL::parameters::choose_parameter;
  using CGAL::parameters::get_parameter;
  typedef typename GetGeomTraits<TriangleMesh, NamedParameters>::type GT;
  typedef typename GetVertexPointMap<TriangleMesh, NamedParameters>::const_type VPM;

  CGAL_precondition(CGAL::is_triangle_mesh(tm));
  const GT gt = choose_parameter<GT>(get_parameter(np, CGAL::internal_np::geom_traits));
  const VPM vpm = choose_parameter(get_parameter(np, CGAL::internal_np::vertex_point),
                                   get_const_property_map(CGAL::vertex_point, tm));
  CGAL::Bbox_3 box;
  bool has_vertex = false;
  for(auto v : vertices(tm))
  {
    box += get(vpm, v).bbox();
    has_vertex = true;
  }
  const double diagonal = !has_vertex ? 0. :
    std::sqrt(CGAL::square(box.xmax() - box.xmin()) + CGAL::square(box.ymax() - box.ymin()) +
              CGAL::square(box.zmax() - box.zmin()));
  const double spacing = choose_parameter(get_parameter(np, CGAL::internal_np::grid_spacing), diagonal / 1000.);
  CGAL_precondition(!(spacing < 0.));

  internal::Cut_samples<GT> cuts_g, cuts_p;
  internal::sample_cuts(tm, vpm, ground_truth, spacing, gt, cuts_g);
  internal::sample_cuts(tm, vpm, prediction, spacing, gt, cuts_p);
  if(cuts_g.points.empty() && cuts_p.points.empty()) return 0.;
  const double NaN = std::numeric_limits<double>::quiet_NaN();
  if(cuts_g.points.empty() || cuts_p.points.empty()) return NaN;
  const double radius = internal::average_radius(tm, vpm, diagonal / 128.);
  if(!(radius > 0.)) return NaN;
  return (internal::mean_distance_to_cuts(cuts_g, cuts_p, gt) +
          internal::mean_distance_to_cuts(cuts_p, cuts_g, gt)) / radius;
}

} // namespace Part_decomposition
} // namespace CGAL

#endif // CGAL_PART_DECOMPOSITION_BENCHMARK_SEGMENTATION_METRICS_H
