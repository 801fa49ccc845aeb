// Generated analytic shapes shared by the tests. Every shape is closed and outward oriented
// unless stated otherwise.
#ifndef PART_DECOMPOSITION_TEST_SHAPES_H
#define PART_DECOMPOSITION_TEST_SHAPES_H

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Surface_mesh.h>
#include <CGAL/Polygon_mesh_processing/polygon_soup_to_polygon_mesh.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <map>
#include <vector>

namespace test_shapes {

typedef CGAL::Exact_predicates_inexact_constructions_kernel K;
typedef K::Point_3 Point;
typedef K::Vector_3 Vector;
typedef CGAL::Surface_mesh<Point> Mesh;

// A triangle soup whose equal points are merged, turned into a Surface_mesh.
struct Soup
{
  std::vector<Point> points;
  std::vector<std::vector<std::size_t> > triangles;
  std::map<std::array<double, 3>, std::size_t> index;

  std::size_t point(const Point& p)
  {
    const std::array<double, 3> c = {{p.x(), p.y(), p.z()}};
    auto r = index.emplace(c, points.size());
    if(r.second) points.push_back(p);
    return r.first->second;
  }
  void triangle(const Point& a, const Point& b, const Point& c)
  {
    triangles.push_back({point(a), point(b), point(c)});
  }
  Mesh mesh() const
  {
    Mesh m;
    CGAL::Polygon_mesh_processing::polygon_soup_to_polygon_mesh(points, triangles, m);
    return m;
  }
};

// Sphere of radius R: an icosahedron subdivided `level` times, projected on the sphere.
inline Mesh make_sphere(const Point& c, double R, int level)
{
  const double t = (1. + std::sqrt(5.)) / 2.;
  std::vector<std::array<double, 3> > v = {{-1, t, 0}, {1, t, 0}, {-1, -t, 0}, {1, -t, 0},
                                           {0, -1, t}, {0, 1, t}, {0, -1, -t}, {0, 1, -t},
                                           {t, 0, -1}, {t, 0, 1}, {-t, 0, -1}, {-t, 0, 1}};
  std::vector<std::array<int, 3> > f = {{0, 11, 5}, {0, 5, 1}, {0, 1, 7}, {0, 7, 10}, {0, 10, 11},
                                        {1, 5, 9}, {5, 11, 4}, {11, 10, 2}, {10, 7, 6}, {7, 1, 8},
                                        {3, 9, 4}, {3, 4, 2}, {3, 2, 6}, {3, 6, 8}, {3, 8, 9},
                                        {4, 9, 5}, {2, 4, 11}, {6, 2, 10}, {8, 6, 7}, {9, 8, 1}};
  auto unit = [](std::array<double, 3> a) {
    const double n = std::sqrt(a[0] * a[0] + a[1] * a[1] + a[2] * a[2]);
    return std::array<double, 3>{{a[0] / n, a[1] / n, a[2] / n}};
  };
  for(auto& p : v) p = unit(p);
  for(int l = 0; l < level; ++l)
  {
    std::map<std::pair<int, int>, int> mid;
    auto midpoint = [&](int a, int b) {
      auto key = std::make_pair(std::min(a, b), std::max(a, b));
      auto it = mid.find(key);
      if(it != mid.end()) return it->second;
      v.push_back(unit({{(v[a][0] + v[b][0]) / 2, (v[a][1] + v[b][1]) / 2, (v[a][2] + v[b][2]) / 2}}));
      return mid[key] = int(v.size()) - 1;
    };
    std::vector<std::array<int, 3> > g;
    for(const auto& tri : f)
    {
      const int a = midpoint(tri[0], tri[1]), b = midpoint(tri[1], tri[2]), cc = midpoint(tri[2], tri[0]);
      g.push_back({tri[0], a, cc});
      g.push_back({tri[1], b, a});
      g.push_back({tri[2], cc, b});
      g.push_back({a, b, cc});
    }
    f.swap(g);
  }
  Soup s;
  auto P = [&](int i) { return Point(c.x() + R * v[i][0], c.y() + R * v[i][1], c.z() + R * v[i][2]); };
  for(const auto& tri : f) s.triangle(P(tri[0]), P(tri[1]), P(tri[2]));
  return s.mesh();
}

// Axis-aligned box [lo, hi], each face split into n x n squares of two triangles.
inline Mesh make_box(const Point& lo, const Point& hi, int n)
{
  Soup s;
  const double L[3] = {lo.x(), lo.y(), lo.z()}, H[3] = {hi.x(), hi.y(), hi.z()};
  for(int axis = 0; axis < 3; ++axis)
    for(int side = 0; side < 2; ++side)
    {
      const int u = (axis + 1) % 3, w = (axis + 2) % 3;
      auto P = [&](int i, int j) {
        double c[3];
        c[axis] = side ? H[axis] : L[axis];
        // the last vertex is the corner itself: L + (H - L) * n / n may miss it by a rounding,
        // and the sides would then not share their edges
        c[u] = i == n ? H[u] : L[u] + (H[u] - L[u]) * i / n;
        c[w] = j == n ? H[w] : L[w] + (H[w] - L[w]) * j / n;
        return Point(c[0], c[1], c[2]);
      };
      for(int i = 0; i < n; ++i)
        for(int j = 0; j < n; ++j)
        {
          // (u, w, axis) is right-handed: counter-clockwise in (u, w) faces +axis.
          if(side)
          {
            s.triangle(P(i, j), P(i + 1, j), P(i + 1, j + 1));
            s.triangle(P(i, j), P(i + 1, j + 1), P(i, j + 1));
          }
          else
          {
            s.triangle(P(i, j), P(i + 1, j + 1), P(i + 1, j));
            s.triangle(P(i, j), P(i, j + 1), P(i + 1, j + 1));
          }
        }
    }
  return s.mesh();
}

// Closed cylinder of radius R around the z axis through c, from c.z()-h/2 to c.z()+h/2;
// `na` segments around, `nz` along, caps as triangle fans.
inline Mesh make_cylinder(const Point& c, double R, double h, int na, int nz)
{
  Soup s;
  const double pi = std::acos(-1.);
  auto P = [&](int i, int k) {
    const double a = 2 * pi * (i % na) / na;
    return Point(c.x() + R * std::cos(a), c.y() + R * std::sin(a), c.z() - h / 2 + h * k / nz);
  };
  for(int i = 0; i < na; ++i)
    for(int k = 0; k < nz; ++k)
    {
      s.triangle(P(i, k), P(i + 1, k), P(i + 1, k + 1));
      s.triangle(P(i, k), P(i + 1, k + 1), P(i, k + 1));
    }
  const Point bottom(c.x(), c.y(), c.z() - h / 2), top(c.x(), c.y(), c.z() + h / 2);
  for(int i = 0; i < na; ++i)
  {
    s.triangle(bottom, P(i + 1, 0), P(i, 0));
    s.triangle(top, P(i, nz), P(i + 1, nz));
  }
  return s.mesh();
}

// The closed surface of a union of unit cubes, each given by its lowest corner: two outward
// triangles per square between a cube and an empty cell. No two cubes may meet along an edge or a
// corner only (the surface would not be manifold).
inline Mesh make_union_of_cubes(const std::vector<std::array<int, 3> >& cubes)
{
  Soup s;
  auto filled = [&](const std::array<int, 3>& c) { return std::find(cubes.begin(), cubes.end(), c) != cubes.end(); };
  auto point = [](const std::array<int, 3>& p) { return Point(p[0], p[1], p[2]); };
  for(const std::array<int, 3>& c : cubes)
    for(int axis = 0; axis < 3; ++axis)
      for(int side = 0; side < 2; ++side)
      {
        std::array<int, 3> n = c;
        n[axis] += side == 1 ? 1 : -1;
        if(filled(n)) continue;
        // the square at c + side e_axis spanned by e_u and e_w, with e_u x e_w = e_axis
        const int u = (axis + 1) % 3, w = (axis + 2) % 3;
        std::array<int, 3> a = c;
        a[axis] += side;
        std::array<int, 3> b = a, d = a, e = a;
        ++b[u];
        ++d[u];
        ++d[w];
        ++e[w];
        if(side == 1) { s.triangle(point(a), point(b), point(d)); s.triangle(point(a), point(d), point(e)); }
        else { s.triangle(point(a), point(d), point(b)); s.triangle(point(a), point(e), point(d)); }
      }
  return s.mesh();
}

// Appends `b` to `a` (disjoint union); returns the number of faces `a` had before.
inline std::size_t append(Mesh& a, const Mesh& b)
{
  const std::size_t before = num_faces(a);
  a.join(b);
  return before;
}

// Closed L-shaped prism made of two plates of thickness t, extruded along z over [0, w]:
// plate A = [0, la] x [0, t] (along x), plate B = [0, t] x [0, lb] (along y); they share the
// corner square [0, t]^2. The surface is the boundary of a rectilinear grid of cells (t across
// the plates, about h elsewhere), each boundary square split into two triangles.
// If `plate` is given, it receives the true plate of each face in the order of faces(mesh):
// 1 (B) if the face centroid has y > t, else 0 (A): the corner region and the walls on the
// plane y = t go to plate A. Needs t < la and t < lb.
inline Mesh make_l_bracket(double la, double lb, double t, double w, double h, std::vector<int>* plate = nullptr)
{
  // cell walls from `from` to `to`, about h apart
  auto breaks = [h](double from, double to) {
    std::vector<double> b;
    const int n = std::max(1, int(std::lround((to - from) / h)));
    for(int i = 0; i <= n; ++i) b.push_back(from + (to - from) * i / n);
    return b;
  };
  // x and y: one cell across the thickness, then cells of about h; z: cells of about h.
  std::vector<double> g[3] = {{0., t}, {0., t}, breaks(0., w)};
  for(int a = 0; a < 2; ++a)
  {
    const std::vector<double> rest = breaks(t, a == 0 ? la : lb);
    g[a].insert(g[a].end(), rest.begin() + 1, rest.end());
  }
  const int n[3] = {int(g[0].size()) - 1, int(g[1].size()) - 1, int(g[2].size()) - 1};
  // cell (i, j, k) is solid if it lies in plate A (j == 0) or in plate B (i == 0)
  auto solid = [&](const std::array<int, 3>& c) {
    for(int a = 0; a < 3; ++a)
      if(c[a] < 0 || c[a] >= n[a]) return false;
    return c[0] == 0 || c[1] == 0;
  };
  Soup s;
  for(int a = 0; a < 3; ++a)
  {
    const int u = (a + 1) % 3, v = (a + 2) % 3;
    std::array<int, 3> c;
    for(c[a] = -1; c[a] < n[a]; ++c[a])
      for(c[u] = 0; c[u] < n[u]; ++c[u])
        for(c[v] = 0; c[v] < n[v]; ++c[v])
        {
          std::array<int, 3> d = c;
          ++d[a];
          const bool low = solid(c), high = solid(d);
          if(low == high) continue;
          // the square between the two cells, facing out of the solid one
          auto P = [&](int du, int dv) {
            double x[3];
            x[a] = g[a][d[a]];
            x[u] = g[u][c[u] + du];
            x[v] = g[v][c[v] + dv];
            return Point(x[0], x[1], x[2]);
          };
          if(low)
          {
            s.triangle(P(0, 0), P(1, 0), P(1, 1));
            s.triangle(P(0, 0), P(1, 1), P(0, 1));
          }
          else
          {
            s.triangle(P(0, 0), P(1, 1), P(1, 0));
            s.triangle(P(0, 0), P(0, 1), P(1, 1));
          }
        }
  }
  Mesh m = s.mesh();
  if(plate != nullptr)
  {
    plate->clear();
    for(auto f : faces(m))
    {
      // a vertex above y = t: the same as the centroid, without its rounding on the plane y = t
      bool above = false;
      for(auto vd : vertices_around_face(halfedge(f, m), m)) above = above || m.point(vd).y() > t;
      plate->push_back(above ? 1 : 0);
    }
  }
  return m;
}

// An open square sheet [-1,1]^2 of 2 n^2 triangles, z = amplitude sin(3x) sin(3y): flat for
// amplitude 0, corrugated (not convex, bounding no volume) otherwise.
inline Mesh make_wavy_sheet(int n, double amplitude)
{
  Soup sheet;
  auto P = [&](int i, int j) {
    const double x = -1. + 2. * i / n, y = -1. + 2. * j / n;
    return Point(x, y, amplitude * std::sin(3. * x) * std::sin(3. * y));
  };
  for(int i = 0; i < n; ++i)
    for(int j = 0; j < n; ++j)
    {
      sheet.triangle(P(i, j), P(i + 1, j), P(i + 1, j + 1));
      sheet.triangle(P(i, j), P(i + 1, j + 1), P(i, j + 1));
    }
  return sheet.mesh();
}

// The triangles of `m` as a soup: its points and three point indices per face, in the order of
// faces(m).
inline void mesh_soup(const Mesh& m, std::vector<std::array<double, 3> >& points,
                      std::vector<std::array<std::size_t, 3> >& triangles)
{
  for(auto v : vertices(m)) points.push_back({{m.point(v).x(), m.point(v).y(), m.point(v).z()}});
  for(auto f : faces(m))
  {
    std::array<std::size_t, 3> t;
    int k = 0;
    for(auto v : vertices_around_face(halfedge(f, m), m)) t[k++] = std::size_t(v);
    triangles.push_back(t);
  }
}

// The faces of `m` (indices in the order of faces(m)) left after cutting `holes` holes, as
// ../shared/data/open_meshes/make_open.py does: each hole grows breadth-first over edge-adjacent
// faces from a face at a fixed stride until it covers `area_fraction` of the area of the mesh.
inline std::vector<std::size_t> faces_outside_holes(const Mesh& m, int holes, double area_fraction)
{
  const std::size_t n = num_faces(m);
  std::vector<double> area(n);
  double total = 0.;
  for(auto f : faces(m))
  {
    auto h = halfedge(f, m);
    area[std::size_t(f)] = std::sqrt(CGAL::squared_area(m.point(source(h, m)), m.point(target(h, m)),
                                                        m.point(target(next(h, m), m))));
    total += area[std::size_t(f)];
  }
  std::vector<char> removed(n, 0);
  for(int hole = 0; hole < holes; ++hole)
  {
    std::size_t seed = (std::size_t(hole) * n) / std::size_t(holes) + n / (2 * std::size_t(holes));
    while(removed[seed]) seed = (seed + 1) % n;
    std::vector<std::size_t> queue(1, seed);
    std::vector<char> queued(n, 0);
    queued[seed] = 1;
    double covered = 0.;
    for(std::size_t head = 0; head < queue.size() && covered < area_fraction * total; ++head)
    {
      const Mesh::Face_index f(static_cast<Mesh::size_type>(queue[head]));
      removed[queue[head]] = 1;
      covered += area[queue[head]];
      for(auto h : halfedges_around_face(halfedge(f, m), m))
      {
        const auto g = face(opposite(h, m), m);
        if(g != Mesh::null_face() && !queued[std::size_t(g)] && !removed[std::size_t(g)])
        {
          queued[std::size_t(g)] = 1;
          queue.push_back(std::size_t(g));
        }
      }
    }
  }
  std::vector<std::size_t> kept;
  for(std::size_t i = 0; i < n; ++i)
    if(!removed[i]) kept.push_back(i);
  return kept;
}

// The number of labels if they are numbered 0, 1, ... in the order of their first face (each
// label is at most one more than every label before it), else std::size_t(-1).
inline std::size_t count_if_numbered_by_first_face(const std::vector<std::size_t>& labels)
{
  std::size_t next = 0;
  for(std::size_t l : labels)
  {
    if(l > next) return std::size_t(-1);
    if(l == next) ++next;
  }
  return next;
}

} // namespace test_shapes

#endif // PART_DECOMPOSITION_TEST_SHAPES_H
