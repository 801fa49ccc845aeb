// Copyright (c) 2026 The Part_decomposition authors.
// All rights reserved.
//
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Author(s)     : The Part_decomposition authors

// The steps shared by the generators of shapes with known parts (generate_example_shapes,
// generate_superquadric_unions): the surface of a lattice box, remeshing a union while keeping its
// creases, and the true part of each face.
#ifndef PD_BENCHMARK_GENERATED_SHAPES_H
#define PD_BENCHMARK_GENERATED_SHAPES_H

#include <CGAL/AABB_face_graph_triangle_primitive.h>
#include <CGAL/AABB_traits.h>
#include <CGAL/AABB_tree.h>
#include <CGAL/Kernel_traits.h>
#include <CGAL/Polygon_mesh_processing/detect_features.h>
#include <CGAL/Polygon_mesh_processing/remesh.h>
#include <CGAL/boost/graph/iterator.h>
#include <CGAL/centroid.h>

#include <array>
#include <cstddef>
#include <map>
#include <memory>
#include <vector>

namespace pd_benchmark {

// The surface of a box of n[0] x n[1] x n[2] lattice cells as a soup: each lattice node c of the
// surface (0 <= c[a] <= n[a]) made once, as position(c), and each square of a side split into two
// triangles along the same diagonal, oriented outward.
template <typename Point, typename Position>
void lattice_box_soup(const std::array<int, 3>& n, const Position& position, std::vector<Point>& points,
                      std::vector<std::array<std::size_t, 3> >& triangles)
{
  std::map<std::array<int, 3>, std::size_t> index;
  auto vertex = [&](const std::array<int, 3>& c) {
    auto it = index.find(c);
    if(it != index.end()) return it->second;
    points.push_back(position(c));
    return index[c] = points.size() - 1;
  };
  for(int a = 0; a < 3; ++a)
    for(int side = 0; side < 2; ++side)
    {
      const int u = (a + 1) % 3, v = (a + 2) % 3;
      for(int i = 0; i < n[u]; ++i)
        for(int j = 0; j < n[v]; ++j)
        {
          auto node = [&](int di, int dj) {
            std::array<int, 3> c;
            c[a] = side * n[a];
            c[u] = i + di;
            c[v] = j + dj;
            return vertex(c);
          };
          const std::size_t p00 = node(0, 0), p10 = node(1, 0), p11 = node(1, 1), p01 = node(0, 1);
          if(side)
          {
            triangles.push_back({{p00, p10, p11}});
            triangles.push_back({{p00, p11, p01}});
          }
          else
          {
            triangles.push_back({{p00, p11, p10}});
            triangles.push_back({{p00, p01, p11}});
          }
        }
    }
}

// Isotropic remeshing of a Surface_mesh at edge length `L`, keeping the creases (dihedral above 50
// degrees) and the vertices where more than two of them meet.
template <typename Mesh>
void remesh_keeping_creases(Mesh& m, double L)
{
  namespace PMP = CGAL::Polygon_mesh_processing;
  auto is_sharp = get(CGAL::edge_is_feature, m);
  PMP::detect_sharp_edges(m, 50., is_sharp);
  auto is_corner = m.template add_property_map<typename Mesh::Vertex_index, bool>("v:corner", false).first;
  for(auto v : vertices(m))
  {
    int n = 0;
    for(auto h : CGAL::halfedges_around_target(v, m)) n += get(is_sharp, edge(h, m)) ? 1 : 0;
    is_corner[v] = n > 2;
  }
  PMP::isotropic_remeshing(faces(m), L, m,
                           CGAL::parameters::number_of_iterations(5)
                             .edge_is_constrained_map(is_sharp)
                             .vertex_is_constrained_map(is_corner)
                             .relax_constraints(true));
  m.remove_property_map(is_corner);
  m.collect_garbage();
}

// The part whose meshed surface is nearest each face centroid of `m`, in the order of faces(m)
// (the first part on a tie).
template <typename Mesh>
std::vector<std::size_t> nearest_part_labels(const Mesh& m, const std::vector<Mesh>& parts)
{
  typedef typename CGAL::Kernel_traits<typename Mesh::Point>::Kernel K;
  typedef CGAL::AABB_face_graph_triangle_primitive<Mesh> Primitive;
  typedef CGAL::AABB_tree<CGAL::AABB_traits<K, Primitive> > Tree;
  std::vector<std::unique_ptr<Tree> > trees;
  for(const Mesh& p : parts)
  {
    trees.emplace_back(new Tree(faces(p).first, faces(p).second, p));
    trees.back()->accelerate_distance_queries();
  }
  std::vector<std::size_t> label;
  for(auto f : faces(m))
  {
    const auto h = halfedge(f, m);
    const auto c = CGAL::centroid(m.point(source(h, m)), m.point(target(h, m)), m.point(target(next(h, m), m)));
    std::size_t best = 0;
    double best_d = trees[0]->squared_distance(c);
    for(std::size_t i = 1; i < trees.size(); ++i)
    {
      const double d = trees[i]->squared_distance(c);
      if(d < best_d) best_d = d, best = i;
    }
    label.push_back(best);
  }
  return label;
}

} // namespace pd_benchmark

#endif // PD_BENCHMARK_GENERATED_SHAPES_H
