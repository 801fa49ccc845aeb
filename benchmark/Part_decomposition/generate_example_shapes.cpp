// Builds the example meshes shipped in examples/Part_decomposition/data: unions of primitives
// (CGAL corefinement), remeshed isotropically, with the true part of each face (the primitive
// whose surface is nearest to its centroid) written as a .seg file (one label per line, in the
// face order of the .off file).
//
// Usage: generate_example_shapes [output_folder]   (default: examples/Part_decomposition/data)
#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Surface_mesh.h>

#include <CGAL/Polygon_mesh_processing/connected_components.h>
#include <CGAL/Polygon_mesh_processing/corefinement.h>
#include <CGAL/Polygon_mesh_processing/measure.h>
#include <CGAL/Polygon_mesh_processing/orientation.h>
#include <CGAL/Polygon_mesh_processing/polygon_soup_to_polygon_mesh.h>
#include <CGAL/Polygon_mesh_processing/self_intersections.h>
#include <CGAL/boost/graph/helpers.h>

#include <array>
#include <cmath>
#include <cstdlib>
#include <fstream>
#include <iomanip>
#include <iostream>
#include <map>
#include <memory>
#include <string>
#include <vector>

#include "generated_shapes.h"

namespace PMP = CGAL::Polygon_mesh_processing;
typedef CGAL::Exact_predicates_inexact_constructions_kernel K;
typedef K::Point_3 Point;
typedef K::Vector_3 Vector;
typedef CGAL::Surface_mesh<Point> Mesh;

namespace {

const double pi = std::acos(-1.);

Mesh from_soup(const std::vector<Point>& points, const std::vector<std::array<std::size_t, 3> >& triangles)
{
  Mesh m;
  std::vector<std::vector<std::size_t> > polygons;
  for(const auto& t : triangles) polygons.push_back({t[0], t[1], t[2]});
  PMP::polygon_soup_to_polygon_mesh(points, polygons, m);
  if(!PMP::is_outward_oriented(m)) PMP::reverse_face_orientations(m);
  return m;
}

// A closed surface of revolution around the segment a -> b: `profile` lists (radius, t) from the
// bottom (t = 0 at a) to the top (t = 1 at b); a zero radius is a pole. `na` segments around.
Mesh revolve(const Point& a, const Point& b, const std::vector<std::pair<double, double> >& profile, int na)
{
  Vector d = b - a;
  const double len = std::sqrt(d.squared_length());
  d = d / len;
  // an orthonormal frame (u, v, d)
  const Vector helper = std::abs(d.x()) < 0.9 ? Vector(1, 0, 0) : Vector(0, 1, 0);
  Vector u = CGAL::cross_product(d, helper);
  u = u / std::sqrt(u.squared_length());
  const Vector v = CGAL::cross_product(d, u);

  std::vector<Point> points;
  std::vector<std::vector<std::size_t> > rings; // one vertex for a pole, na otherwise
  for(const auto& rt : profile)
  {
    const Point c = a + d * (rt.second * len);
    std::vector<std::size_t> ring;
    if(rt.first == 0.)
    {
      ring.push_back(points.size());
      points.push_back(c);
    }
    else
      for(int i = 0; i < na; ++i)
      {
        const double phi = 2 * pi * i / na;
        ring.push_back(points.size());
        points.push_back(c + u * (rt.first * std::cos(phi)) + v * (rt.first * std::sin(phi)));
      }
    rings.push_back(ring);
  }
  std::vector<std::array<std::size_t, 3> > triangles;
  for(std::size_t l = 0; l + 1 < rings.size(); ++l)
  {
    const auto& lo = rings[l];
    const auto& hi = rings[l + 1];
    for(int i = 0; i < na; ++i)
    {
      const int j = (i + 1) % na;
      if(lo.size() == 1)
        triangles.push_back({lo[0], hi[j], hi[i]});
      else if(hi.size() == 1)
        triangles.push_back({lo[i], lo[j], hi[0]});
      else
      {
        triangles.push_back({lo[i], lo[j], hi[j]});
        triangles.push_back({lo[i], hi[j], hi[i]});
      }
    }
  }
  return from_soup(points, triangles);
}

// An ellipsoid of semi-axes (rx, ry, rz) centred at c (axes along x, y, z).
Mesh ellipsoid(const Point& c, double rx, double ry, double rz, int na = 96, int nl = 48)
{
  std::vector<std::pair<double, double> > profile;
  for(int l = 0; l <= nl; ++l)
  {
    const double theta = pi * l / nl; // from the bottom pole
    profile.emplace_back(l == 0 || l == nl ? 0. : std::sin(theta), (1. - std::cos(theta)) / 2.);
  }
  Mesh m = revolve(Point(0, 0, -1), Point(0, 0, 1), profile, na);
  for(auto vd : vertices(m))
  {
    const Point& p = m.point(vd);
    m.point(vd) = Point(c.x() + rx * p.x(), c.y() + ry * p.y(), c.z() + rz * p.z());
  }
  return m;
}

// A capsule of radius r around the segment a -> b (hemispherical ends beyond a and b).
Mesh capsule(const Point& a, const Point& b, double r, int na = 48, int nh = 12, int nz = 8)
{
  const Vector d = b - a;
  const double len = std::sqrt(d.squared_length());
  const Vector e = d / len;
  const Point a2 = a - e * r, b2 = b + e * r;
  const double total = len + 2 * r;
  std::vector<std::pair<double, double> > profile;
  for(int l = 0; l <= nh; ++l)
  {
    const double theta = 0.5 * pi * l / nh;
    profile.emplace_back(l == 0 ? 0. : r * std::sin(theta), r * (1. - std::cos(theta)) / total);
  }
  for(int l = 1; l < nz; ++l) profile.emplace_back(r, (r + len * l / nz) / total);
  for(int l = nh; l >= 0; --l)
  {
    const double theta = 0.5 * pi * l / nh;
    profile.emplace_back(l == 0 ? 0. : r * std::sin(theta), 1. - r * (1. - std::cos(theta)) / total);
  }
  return revolve(a2, b2, profile, na);
}

// A cylinder of radius r with flat caps from a to b.
Mesh cylinder(const Point& a, const Point& b, double r, int na = 64, int nz = 8)
{
  std::vector<std::pair<double, double> > profile;
  profile.emplace_back(0., 0.);
  for(int l = 0; l <= nz; ++l) profile.emplace_back(r, double(l) / nz);
  profile.emplace_back(0., 1.);
  return revolve(a, b, profile, na);
}

// An axis-aligned box, each side split into n x n squares.
Mesh box(const Point& lo, const Point& hi, int n = 8)
{
  std::vector<Point> points;
  std::vector<std::array<std::size_t, 3> > triangles;
  pd_benchmark::lattice_box_soup({{n, n, n}}, [&](const std::array<int, 3>& c) {
    return Point(lo.x() + (hi.x() - lo.x()) * c[0] / n, lo.y() + (hi.y() - lo.y()) * c[1] / n,
                 lo.z() + (hi.z() - lo.z()) * c[2] / n);
  }, points, triangles);
  return from_soup(points, triangles);
}

struct Shape
{
  std::string name;
  std::vector<Mesh> parts;
  std::size_t target_faces;
};

bool build(const Shape& shape, const std::string& folder)
{
  // Union of the parts (copies: corefinement modifies its inputs).
  Mesh result = shape.parts.front();
  for(std::size_t i = 1; i < shape.parts.size(); ++i)
  {
    Mesh next = shape.parts[i];
    Mesh out;
    if(!PMP::corefine_and_compute_union(result, next, out))
    {
      std::cerr << shape.name << ": union with part " << i << " failed\n";
      return false;
    }
    result = out;
  }

  // Isotropic remeshing to about target_faces faces, keeping the sharp creases.
  const double area = PMP::area(result);
  const double target_length = std::sqrt(area / (std::sqrt(3.) / 4. * double(shape.target_faces)));
  pd_benchmark::remesh_keeping_creases(result, target_length);

  const bool closed = CGAL::is_closed(result);
  const bool self_intersecting = PMP::does_self_intersect(result);
  auto comp = result.add_property_map<Mesh::Face_index, std::size_t>("f:comp", 0).first;
  const std::size_t components = PMP::connected_components(result, comp);
  result.remove_property_map(comp);

  // True part of each face: the primitive whose surface is nearest to the centroid.
  const std::vector<std::size_t> label = pd_benchmark::nearest_part_labels(result, shape.parts);
  std::vector<std::size_t> count(shape.parts.size(), 0);
  for(std::size_t l : label) ++count[l];

  // Written by hand so that the face order of the file is the iteration order of `faces()`.
  const std::string off = folder + "/" + shape.name + ".off";
  std::ofstream out(off);
  out << "OFF\n" << num_vertices(result) << ' ' << num_faces(result) << " 0\n";
  out << std::setprecision(7);
  for(auto vd : vertices(result))
  {
    const Point& p = result.point(vd);
    out << p.x() << ' ' << p.y() << ' ' << p.z() << '\n';
  }
  for(auto f : faces(result))
  {
    out << '3';
    for(auto vd : vertices_around_face(halfedge(f, result), result)) out << ' ' << std::size_t(vd);
    out << '\n';
  }
  std::ofstream seg(folder + "/" + shape.name + ".seg");
  for(std::size_t l : label) seg << l << '\n';

  std::cout << shape.name << ": " << num_faces(result) << " faces, " << num_vertices(result)
            << " vertices, closed " << closed << ", self-intersecting " << self_intersecting
            << ", components " << components << ", faces per part:";
  for(std::size_t c : count) std::cout << ' ' << c;
  std::cout << '\n';
  return closed && !self_intersecting && components == 1;
}

} // namespace

int main(int argc, char** argv)
{
  const std::string folder = argc > 1 ? argv[1] : "examples/Part_decomposition/data";
  std::vector<Shape> shapes;

  // table: top (part 0) and four round legs (parts 1-4) that enter the top from below
  {
    Shape s{"table", {}, 7000};
    s.parts.push_back(box(Point(-0.6, -0.4, 0.70), Point(0.6, 0.4, 0.78)));
    for(int sx : {-1, 1})
      for(int sy : {-1, 1})
        s.parts.push_back(cylinder(Point(sx * 0.49, sy * 0.29, 0.), Point(sx * 0.49, sy * 0.29, 0.74), 0.05));
    shapes.push_back(s);
  }
  // animal: body (0), head (1), four legs (2-5), tail (6)
  {
    Shape s{"animal", {}, 7000};
    s.parts.push_back(ellipsoid(Point(0., 0., 0.62), 0.52, 0.22, 0.20));
    s.parts.push_back(ellipsoid(Point(0.52, 0., 0.78), 0.17, 0.11, 0.12));
    for(int sx : {1, -1})
      for(int sy : {-1, 1})
        s.parts.push_back(capsule(Point(sx * 0.33, sy * 0.08, 0.58), Point(sx * 0.35, sy * 0.09, 0.06), 0.055));
    s.parts.push_back(capsule(Point(-0.46, 0., 0.68), Point(-0.78, 0., 0.86), 0.03));
    shapes.push_back(s);
  }
  // dumbbell: left ball (0), bar (1), right ball (2)
  {
    Shape s{"dumbbell", {}, 4000};
    s.parts.push_back(ellipsoid(Point(-0.7, 0., 0.), 0.3, 0.3, 0.3));
    s.parts.push_back(capsule(Point(-0.7, 0., 0.), Point(0.7, 0., 0.), 0.1));
    s.parts.push_back(ellipsoid(Point(0.7, 0., 0.), 0.3, 0.3, 0.3));
    shapes.push_back(s);
  }

  bool ok = true;
  for(const Shape& s : shapes) ok = build(s, folder) && ok;
  return ok ? EXIT_SUCCESS : EXIT_FAILURE;
}
