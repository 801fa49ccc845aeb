// Copyright (c) 2026 The Part_decomposition authors.
// All rights reserved.
//
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Author(s)     : The Part_decomposition authors

// The two steps shared by the generators of shapes with known parts (generate_example_shapes,
// generate_superquadric_unions): remeshing a union while keeping its creases, and the true part of
// each face.
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

#include <cstddef>
#include <memory>
#include <vector>

namespace pd_benchmark {

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
