// Copyright (c) 2026 The Part_decomposition authors.
// All rights reserved.
//
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Author(s)     : The Part_decomposition authors

#ifndef CGAL_PART_DECOMPOSITION_INTERNAL_TRIANGLE_SOUP_AABB_TREE_H
#define CGAL_PART_DECOMPOSITION_INTERNAL_TRIANGLE_SOUP_AABB_TREE_H

#include <CGAL/Part_decomposition/internal/grid/triangle_distance.h>
#include <CGAL/Part_decomposition/internal/grid/winding_number.h>
#include <CGAL/Part_decomposition/internal/toolbox/toolbox.h>

#include <CGAL/AABB_tree.h>
#include <CGAL/Bbox_3.h>
#include <CGAL/Simple_cartesian.h>
#include <CGAL/version.h>
#include <CGAL/property_map.h>
#if CGAL_VERSION_NR >= CGAL_VERSION_NUMBER(6, 0, 0)
#include <CGAL/AABB_traits_3.h>
#include <CGAL/AABB_triangle_primitive_3.h>
#else
#include <CGAL/AABB_traits.h>
#include <CGAL/AABB_triangle_primitive.h>
#endif

#include <algorithm>
#include <array>
#include <cstddef>
#include <cstdint>
#include <limits>
#include <memory>
#include <utility>
#include <vector>

// Exact closest-triangle queries on a triangle soup with CGAL's AABB tree, whose primitives are
// runs of triangles. The tree is walked through its public `traversal_with_priority()` with our
// own traversal traits: nearest child first, nodes pruned by the best distance so far (which the
// caller may seed with an upper bound), and the exact double-precision point-triangle distance at
// the leaves. CGAL's own `closest_point()` gives the same distances but starts from a kd-tree
// hint, cannot take a bound and visits the children in a fixed order.

namespace CGAL {
namespace Part_decomposition {
namespace internal {

typedef CGAL::Simple_cartesian<double> Aabb_kernel;
// CGAL's tree of single triangles, the reference of the tests and benchmarks
typedef std::vector<Aabb_kernel::Triangle_3>::const_iterator Aabb_triangle_iterator;
#if CGAL_VERSION_NR >= CGAL_VERSION_NUMBER(6, 0, 0)
typedef CGAL::AABB_triangle_primitive_3<Aabb_kernel, Aabb_triangle_iterator> Aabb_triangle_primitive;
typedef CGAL::AABB_traits_3<Aabb_kernel, Aabb_triangle_primitive> Aabb_triangle_traits;
#else
typedef CGAL::AABB_triangle_primitive<Aabb_kernel, Aabb_triangle_iterator> Aabb_triangle_primitive;
typedef CGAL::AABB_traits<Aabb_kernel, Aabb_triangle_primitive> Aabb_triangle_traits;
#endif
typedef CGAL::AABB_tree<Aabb_triangle_traits> Aabb_triangle_tree;

// A primitive of the tree: a run of consecutive triangles of the Morton order, its box read from a
// property map. CGAL builds its tree in O(n log n) on the primitives, while the distance field asks
// for about as many distances as the grid has leaves near the surface: on a soup of many more
// triangles than that, runs of `Aabb_chunk::large_run` triangles make the build several times
// cheaper for a few more triangles tested per query (a run of neighbours in Morton order is
// compact); on a smaller soup each triangle is its own run, as queries dominate there.
struct Aabb_chunk
{
  static constexpr std::size_t large_run = 4, large_soup = std::size_t(1) << 18;
  std::size_t id;
  Aabb_kernel::Point_3 centre; // of its box, the point the build splits by
};

class Aabb_chunk_primitive
{
public:
  typedef std::size_t Id;
  typedef Aabb_kernel::Point_3 Point;
  typedef Aabb_kernel::Point_3 Datum; // never read: the boxes come from the box map

  Aabb_chunk_primitive() = default;
  explicit Aabb_chunk_primitive(std::vector<Aabb_chunk>::const_iterator it) : m_id(it->id), m_centre(it->centre) {}
  Id id() const { return m_id; }
  const Point& datum() const { return m_centre; }
  const Point& reference_point() const { return m_centre; }

private:
  Id m_id = 0;
  Point m_centre;
};

typedef CGAL::Pointer_property_map<CGAL::Bbox_3>::const_type Aabb_chunk_box_map;
#if CGAL_VERSION_NR >= CGAL_VERSION_NUMBER(6, 0, 0)
typedef CGAL::AABB_traits_3<Aabb_kernel, Aabb_chunk_primitive, Aabb_chunk_box_map> Aabb_chunk_traits;
#else
typedef CGAL::AABB_traits<Aabb_kernel, Aabb_chunk_primitive, Aabb_chunk_box_map> Aabb_chunk_traits;
#endif
typedef CGAL::AABB_tree<Aabb_chunk_traits> Aabb_chunk_tree;

// Traversal traits of a closest-triangle query (the query is a `Vec3`): the priority of a node is
// minus its squared distance to the query, a node is entered only if that distance is at most the
// best one so far, and among triangles at the same distance the smallest soup index is kept: every
// triangle at the least distance is seen, so the answer does not depend on the shape of the tree.
class Closest_triangle_traversal
{
public:
  typedef double Priority;

  // `triangles`: the stored triangles, in runs of `run`; `soup_index`: the soup index of each.
  Closest_triangle_traversal(const std::vector<Aabb_kernel::Triangle_3>& triangles, std::size_t run,
                             const std::uint32_t* soup_index, double bound2, std::uint32_t bound_triangle)
    : m_triangles(triangles), m_run(run), m_soup_index(soup_index), m_best2(bound2), m_best(bound_triangle)
  {}

  bool go_further() const { return true; }

  template <typename Primitive>
  void intersection(const Vec3& p, const Primitive& primitive)
  {
    const std::size_t first = primitive.id() * m_run;
    const std::size_t last = (std::min)(first + m_run, m_triangles.size());
    for(std::size_t r = first; r < last; ++r)
    {
      const Aabb_kernel::Triangle_3& t = m_triangles[r];
      const double d = squared_distance_to_triangle(p, vec(t[0]), vec(t[1]), vec(t[2]));
      if(d < m_best2 || (d == m_best2 && m_soup_index[r] < m_best))
      {
        m_best2 = d;
        m_best = m_soup_index[r];
      }
    }
  }

  template <typename Node>
  bool do_intersect(const Vec3& p, const Node& node) const
  {
    return box_distance(p, node.bbox()) <= m_best2;
  }

  template <typename Node>
  std::pair<bool, Priority> do_intersect_with_priority(const Vec3& p, const Node& node) const
  {
    const double d = box_distance(p, node.bbox());
    return std::make_pair(d <= m_best2, -d);
  }

  double squared_distance() const { return m_best2; }
  std::uint32_t triangle() const { return m_best; }

  // the squared distance from p to the box b
  static double box_distance(const Vec3& p, const CGAL::Bbox_3& b)
  {
    double s = 0.;
    for(int a = 0; a < 3; ++a)
    {
      const double e = (std::max)((std::max)(b.min(a) - p[a], p[a] - b.max(a)), 0.);
      s += e * e;
    }
    return s;
  }

private:
  static Vec3 vec(const Aabb_kernel::Point_3& p) { return {{p.x(), p.y(), p.z()}}; }

  const std::vector<Aabb_kernel::Triangle_3>& m_triangles;
  std::size_t m_run;
  const std::uint32_t* m_soup_index;
  double m_best2;
  std::uint32_t m_best;
};

// The triangles of a soup in CGAL AABB trees, built at construction (not lazily, so that
// concurrent queries never wait for a build). The tree's primitives are runs of a copy of the
// triangles stored in Morton order of their centroids: a run is compact, and a node's triangles
// lie close in memory (5 to 10% faster queries on the development meshes than in the file's face
// order).
// Triangle indices in and out are those of the soup.
class Triangle_soup_aabb_tree
{
public:
  // `ConcurrencyTag`: the threads of the build (the tree is the same either way).
  template <typename ConcurrencyTag = CGAL::Sequential_tag>
  explicit Triangle_soup_aabb_tree(const std::vector<Triangle_points>& soup, ConcurrencyTag = ConcurrencyTag())
  {
    const std::size_t n = soup.size();
    const auto centroid = [&](std::size_t i, int a) { return (soup[i][0][a] + soup[i][1][a] + soup[i][2][a]) / 3.; };
    // the box of the centroids: a min and a max per block, the same whatever the blocks
    constexpr std::size_t block = 1 << 16;
    std::vector<std::array<Vec3, 2> > box((n + block - 1) / block);
    for_each_block<ConcurrencyTag>(n, block, [&](std::size_t b, std::size_t e) {
      Vec3 lo, hi;
      lo.fill(std::numeric_limits<double>::infinity());
      hi.fill(-std::numeric_limits<double>::infinity());
      for(std::size_t i = b; i < e; ++i)
        for(int a = 0; a < 3; ++a)
        {
          lo[a] = (std::min)(lo[a], centroid(i, a));
          hi[a] = (std::max)(hi[a], centroid(i, a));
        }
      box[b / block] = {{lo, hi}};
    });
    Vec3 lo, hi;
    lo.fill(std::numeric_limits<double>::infinity());
    hi.fill(-std::numeric_limits<double>::infinity());
    for(const std::array<Vec3, 2>& b : box)
      for(int a = 0; a < 3; ++a)
      {
        lo[a] = (std::min)(lo[a], b[0][a]);
        hi[a] = (std::max)(hi[a], b[1][a]);
      }
    // 21 bits per axis of the centroid's cell, interleaved; ties keep the soup order.
    const double cells = double(1u << 21);
    std::vector<std::pair<std::uint64_t, std::uint32_t> > key(n);
    for_each_range<ConcurrencyTag>(n, [&](std::size_t b, std::size_t e) {
      for(std::size_t i = b; i < e; ++i)
      {
        std::uint32_t q[3];
        for(int a = 0; a < 3; ++a)
        {
          const double t = hi[a] > lo[a] ? (centroid(i, a) - lo[a]) / (hi[a] - lo[a]) * cells : 0.;
          q[a] = std::uint32_t((std::min)((std::max)(t, 0.), cells - 1.));
        }
        std::uint64_t code = 0;
        for(int bit = 20; bit >= 0; --bit)
          for(int a = 0; a < 3; ++a) code = (code << 1) | ((q[a] >> bit) & 1u);
        key[i] = std::make_pair(code, std::uint32_t(i));
      }
    }, 4096);
    sort_values<ConcurrencyTag>(key.begin(), key.end());

    m_triangles.resize(n);
    m_soup_index.resize(n);
    m_position.resize(n);
    for_each_range<ConcurrencyTag>(n, [&](std::size_t b, std::size_t e) {
      auto point = [](const Vec3& p) { return Aabb_kernel::Point_3(p[0], p[1], p[2]); };
      for(std::size_t r = b; r < e; ++r)
      {
        const Triangle_points& t = soup[key[r].second];
        m_position[key[r].second] = std::uint32_t(r);
        m_triangles[r] = Aabb_kernel::Triangle_3(point(t[0]), point(t[1]), point(t[2]));
        m_soup_index[r] = key[r].second;
      }
    }, 4096);
    std::vector<std::pair<std::uint64_t, std::uint32_t> >().swap(key);
    make_chunks<ConcurrencyTag>();
    // CGAL builds a tree on one thread: a large soup is split into the two halves of its Morton
    // order (two boxes apart in space), one tree each, built side by side and both searched
    const std::size_t half = m_triangles.size() >= split_size ? m_chunks.size() / 2 : m_chunks.size();
    run_side_by_side<ConcurrencyTag>([&] { build_tree(m_trees[0], 0, half); },
                                     [&] { build_tree(m_trees[1], half, m_chunks.size()); });
  }
  // The tree refers to m_triangles.
  Triangle_soup_aabb_tree(const Triangle_soup_aabb_tree&) = delete;
  Triangle_soup_aabb_tree& operator=(const Triangle_soup_aabb_tree&) = delete;

  /// the soup index of a triangle closest to `p` and its squared distance.
  /// `bound2`, `bound_triangle`: a squared distance reached by that triangle (+infinity if none);
  /// when no triangle is closer than the bound, the bound is returned.
  std::pair<std::uint32_t, double> closest(const Vec3& p, double bound2 = std::numeric_limits<double>::infinity(),
                                           std::uint32_t bound_triangle = 0) const
  {
    Closest_triangle_traversal traversal(m_triangles, m_run, m_soup_index.data(), bound2, bound_triangle);
    // the nearer tree first, so that its answer prunes the other
    const Aabb_chunk_tree &a = *m_trees[0], &b = *m_trees[1];
    const bool second_first =
      !b.empty() && Closest_triangle_traversal::box_distance(p, b.bbox()) < Closest_triangle_traversal::box_distance(p, a.bbox());
    for(const Aabb_chunk_tree* tree : {second_first ? &b : &a, second_first ? &a : &b})
      if(!tree->empty()) tree->traversal_with_priority(p, traversal);
    return std::make_pair(traversal.triangle(), traversal.squared_distance());
  }

  /// the corners of the triangle of soup index `t`, as in the soup: the soup itself can be freed.
  Triangle_points triangle(std::uint32_t t) const
  {
    const Aabb_kernel::Triangle_3& tri = m_triangles[m_position[t]];
    Triangle_points out;
    for(int k = 0; k < 3; ++k) out[k] = {{tri[k].x(), tri[k].y(), tri[k].z()}};
    return out;
  }

private:
  // the number of triangles from which the soup is held in two trees
  static constexpr std::size_t split_size = std::size_t(1) << 16;

  template <typename ConcurrencyTag>
  void make_chunks()
  {
    const std::size_t n = m_triangles.size();
    m_run = n >= Aabb_chunk::large_soup ? Aabb_chunk::large_run : 1;
    const std::size_t size = m_run;
    m_chunks.resize((n + size - 1) / size);
    m_boxes.resize(m_chunks.size());
    for_each_range<ConcurrencyTag>(m_chunks.size(), [&](std::size_t b, std::size_t e) {
      for(std::size_t c = b; c < e; ++c)
      {
        CGAL::Bbox_3 box = m_triangles[c * size].bbox();
        for(std::size_t r = c * size + 1; r < (std::min)(n, (c + 1) * size); ++r) box += m_triangles[r].bbox();
        m_boxes[c] = box;
        m_chunks[c] = Aabb_chunk{c, Aabb_kernel::Point_3((box.xmin() + box.xmax()) / 2., (box.ymin() + box.ymax()) / 2.,
                                                         (box.zmin() + box.zmax()) / 2.)};
      }
    }, 1024);
  }

  void build_tree(std::unique_ptr<Aabb_chunk_tree>& tree, std::size_t begin, std::size_t end) const
  {
    tree.reset(new Aabb_chunk_tree(Aabb_chunk_traits(CGAL::make_property_map(m_boxes))));
    tree->insert(m_chunks.begin() + std::ptrdiff_t(begin), m_chunks.begin() + std::ptrdiff_t(end));
    tree->build();
  }

  std::vector<Aabb_kernel::Triangle_3> m_triangles;
  std::vector<std::uint32_t> m_soup_index;
  std::vector<std::uint32_t> m_position; // soup index -> index in m_triangles
  std::size_t m_run = 1; // triangles per chunk
  std::vector<Aabb_chunk> m_chunks;
  std::vector<CGAL::Bbox_3> m_boxes; // per chunk, read by the trees
  // made once m_boxes is filled (their traits hold its address); the second holds no chunk below
  // split_size triangles
  std::array<std::unique_ptr<Aabb_chunk_tree>, 2> m_trees;
};

} // namespace internal
} // namespace Part_decomposition
} // namespace CGAL

#endif // CGAL_PART_DECOMPOSITION_INTERNAL_TRIANGLE_SOUP_AABB_TREE_H
