// Times compute_tsdf(tm, prior) (the adaptive grid the prior asks for, finest leaves 128, tau = 8
// voxels of 64) on the given meshes: median of several runs with 1 and 2 threads, the process CPU
// time, the time of each internal step, and the leaves of the grid.
//
// usage: benchmark_tsdf [-runs N] [-method auto|votes|inside|winding|flood] [-grid R] [-uniform]
//                       [-open K] [-check] [-aabb] [-closed DIR] mesh [mesh ...]
//   -grid R    grid_resolution(R): the finest leaves (a power of two from 64 to 256)
//   -uniform   adaptive_grid(false): every leaf a voxel of 64^3, the paper's dense grid
//   -open K    removes K faces spread over the mesh first (an open mesh)
//   -closed DIR  for an open mesh with holes (../shared/data/open_meshes/make_open.py), the closed
//            original of the same file name in DIR: the leaves whose sign differs from the
//            original's (exact winding numbers at the same sign points of the same grid), and the
//            original's inside leaves
//   -check   compares 4000 leaves with CGAL: AABB-tree distance at the leaf centre, and
//            Side_of_triangle_mesh sign of the closed input (with -open: of the mesh before its faces
//            were removed) at the leaves the surface cannot cross (farther from it than half their
//            diagonal, and than one voxel with -open)
//   -aabb    also times the distances of the leaves in the band with the plain query of CGAL's
//            AABB tree (`squared_distance()`: kd-tree hint, no bound, fixed child order), for comparison
//
// The steps (2 threads) are those of compute_tsdf(): the AABB tree of the normalized triangles,
// the grid (internal::adaptive_grid_leaves(): the octree refined by the distances of the cell
// centres, which are the field's unsigned values) and the sign (internal::leaf_inside_flags(), the
// internal::leaf_inside_* function of the sign method); "other" is the rest of the call.
#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Surface_mesh.h>
#include <CGAL/AABB_face_graph_triangle_primitive.h>
#include <CGAL/AABB_traits.h>
#include <CGAL/AABB_tree.h>
#include <CGAL/Side_of_triangle_mesh.h>
#include <CGAL/boost/graph/Euler_operations.h>

#include <CGAL/Part_decomposition/IO/read_mesh.h>
#include <CGAL/Part_decomposition/flow_freeze_prior.h>
#include <CGAL/Part_decomposition/tsdf.h>

#ifdef CGAL_LINKED_WITH_TBB
#include <tbb/global_control.h>
#endif

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <ctime>
#include <fstream>
#include <functional>
#include <iostream>
#include <memory>
#include <string>
#include <vector>

typedef CGAL::Exact_predicates_inexact_constructions_kernel K;
typedef CGAL::Surface_mesh<K::Point_3> Mesh;
namespace PD = CGAL::Part_decomposition;
namespace PDI = CGAL::Part_decomposition::internal;
typedef CGAL::Parallel_if_available_tag Tag;

// Median wall-clock time of `runs` calls; `cpu` receives the median process CPU time (all threads),
// which stays meaningful when other programs share the machine.
static double median_ms(int runs, const std::function<void()>& f, double* cpu = nullptr)
{
  std::vector<double> t, c;
  for(int i = 0; i < runs; ++i)
  {
    const auto t0 = std::chrono::steady_clock::now();
    const std::clock_t c0 = std::clock();
    f();
    c.push_back(1000. * double(std::clock() - c0) / CLOCKS_PER_SEC);
    t.push_back(std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - t0).count());
  }
  std::sort(t.begin(), t.end());
  std::sort(c.begin(), c.end());
  if(cpu) *cpu = c[c.size() / 2];
  return t[t.size() / 2];
}

static const char* name(PD::Tsdf_sign_method m)
{
  switch(m)
  {
  case PD::Tsdf_sign_method::INSIDE_TEST: return "INSIDE_TEST";
  case PD::Tsdf_sign_method::WINDING_NUMBER: return "WINDING_NUMBER";
  case PD::Tsdf_sign_method::FLOOD_FILL: return "FLOOD_FILL";
  case PD::Tsdf_sign_method::RAY_VOTES: return "RAY_VOTES";
  default: return "AUTOMATIC";
  }
}

// Distances of the leaves in the band with the plain distance query of CGAL's AABB tree (same tree
// type as compute_tsdf(), one thread), clipped to tau; returns its time, tree build included.
static double aabb_band_ms(const std::vector<PDI::Triangle_points>& tris, const PD::Truncated_signed_distance_field& tsdf,
                           std::vector<double>& out)
{
  typedef PDI::Aabb_kernel SC;
  const auto t0 = std::chrono::steady_clock::now();
  std::vector<SC::Triangle_3> triangles;
  for(const auto& t : tris)
    triangles.emplace_back(SC::Point_3(t[0][0], t[0][1], t[0][2]), SC::Point_3(t[1][0], t[1][1], t[1][2]),
                           SC::Point_3(t[2][0], t[2][1], t[2][2]));
  PDI::Aabb_triangle_tree tree(triangles.begin(), triangles.end());
  tree.accelerate_distance_queries();
  out.assign(tsdf.values.size(), tsdf.truncation);
  for(std::size_t l = 0; l < out.size(); ++l)
    if(std::abs(tsdf.values[l]) < tsdf.truncation)
    {
      const auto c = tsdf.grid.center(l);
      out[l] = std::min(tsdf.truncation, std::sqrt(tree.squared_distance(SC::Point_3(c[0], c[1], c[2]))));
    }
  return std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - t0).count();
}

struct Options
{
  int runs = 5, open_faces = 0, grid_resolution = PD::defaults::grid_resolution;
  bool check = false, aabb = false, uniform = false;
  std::string closed_dir;
  PD::Tsdf_sign_method method = PD::Tsdf_sign_method::AUTOMATIC;
  std::vector<std::string> files;
};

static Options parse_options(int argc, char** argv)
{
  Options o;
  for(int i = 1; i < argc; ++i)
  {
    const std::string a = argv[i];
    if(a == "-runs" && i + 1 < argc) o.runs = std::max(1, std::atoi(argv[++i]));
    else if(a == "-open" && i + 1 < argc) o.open_faces = std::max(0, std::atoi(argv[++i]));
    else if(a == "-grid" && i + 1 < argc) o.grid_resolution = std::atoi(argv[++i]);
    else if(a == "-uniform") o.uniform = true;
    else if(a == "-check") o.check = true;
    else if(a == "-aabb") o.aabb = true;
    else if(a == "-closed" && i + 1 < argc) o.closed_dir = argv[++i];
    else if(a == "-method" && i + 1 < argc)
    {
      const std::string m = argv[++i];
      o.method = m == "inside" ? PD::Tsdf_sign_method::INSIDE_TEST
               : m == "winding" ? PD::Tsdf_sign_method::WINDING_NUMBER
               : m == "flood" ? PD::Tsdf_sign_method::FLOOD_FILL
               : m == "votes" ? PD::Tsdf_sign_method::RAY_VOTES
                              : PD::Tsdf_sign_method::AUTOMATIC;
    }
    else o.files.push_back(a);
  }
  return o;
}

// Removes `count` faces spread over `mesh` (an open mesh).
static void remove_spread_faces(Mesh& mesh, int count)
{
  const std::size_t n = num_faces(mesh), step = std::max<std::size_t>(1, n / std::size_t(count));
  std::vector<Mesh::Face_index> removed;
  std::size_t i = 0;
  for(auto f : faces(mesh))
    if(i++ % step == 0 && removed.size() < std::size_t(count)) removed.push_back(f);
  for(auto f : removed) CGAL::Euler::remove_face(halfedge(f, mesh), mesh);
  mesh.collect_garbage();
}

// Prints the 1- and 2-thread times of compute_tsdf(mesh, prior), of its steps (2 threads), the
// leaves and, with -aabb, the time of the band distances by CGAL's plain AABB-tree query; returns
// the field.
static PD::Truncated_signed_distance_field time_tsdf(const Mesh& mesh, const Options& o, const std::string& shown)
{
  PD::Method_variant switches;
  switches.adaptive_grid = !o.uniform;
  const auto np = PD::parameters::combine(PD::parameters::tsdf_sign_method(o.method),
                                          PD::parameters::grid_resolution(o.grid_resolution),
                                          PD::parameters::method_variant(switches));
  const PD::Hierarchical_prior prior = PD::compute_flow_freeze_prior<Tag>(mesh);
  PD::Truncated_signed_distance_field tsdf;
  double t1 = 0., t2 = 0., cpu = 0.;
  {
#ifdef CGAL_LINKED_WITH_TBB
    tbb::global_control gc(tbb::global_control::max_allowed_parallelism, 1);
#endif
    t1 = median_ms(o.runs, [&] { tsdf = PD::compute_tsdf<Tag>(mesh, prior, np); });
  }
#ifdef CGAL_LINKED_WITH_TBB
  tbb::global_control gc(tbb::global_control::max_allowed_parallelism, 2);
#endif
  t2 = median_ms(o.runs, [&] { tsdf = PD::compute_tsdf<Tag>(mesh, prior, np); }, &cpu);

  // The steps, with the refinement rule compute_tsdf() makes of its parameters.
  const PDI::Tsdf_parameters p = PDI::read_tsdf_parameters(np);
  PDI::Grid_refinement_rule rule;
  rule.base_depth = PD::Adaptive_grid::depth_of(p.resolution);
  rule.finest_depth = PD::Adaptive_grid::depth_of(p.adaptive ? p.grid_resolution : p.resolution);
  rule.uniform = !p.adaptive;
  rule.band = tsdf.truncation;
  if(p.adaptive) rule.surface = PDI::prior_surface_depths(prior, p.resolution);
  const auto tris = PDI::normalized_triangles(mesh, get(CGAL::vertex_point, mesh), tsdf.normalization);
  const bool closed = PDI::faces_form_closed_surface(mesh);
  std::unique_ptr<PDI::Triangle_soup_aabb_tree> tree;
  const double t_tree = median_ms(o.runs, [&] { tree.reset(new PDI::Triangle_soup_aabb_tree(tris, CGAL::Parallel_if_available_tag())); });
  PD::Adaptive_grid grid;
  std::vector<double> distance;
  std::vector<std::uint8_t> crossed;
  const double t_grid = median_ms(o.runs, [&] {
    std::vector<PDI::Grid_leaf> leaves = PDI::adaptive_grid_leaves<Tag>(*tree, rule);
    grid = PDI::grid_of_leaves(leaves, 1 << rule.finest_depth, distance, crossed);
  });
  tree.reset();
  const double t_sign =
    median_ms(o.runs, [&] { PDI::leaf_inside_flags<Tag>(tris, closed, tsdf.sign_method, grid, crossed); });
  if(grid != tsdf.grid) std::cerr << shown << ": the grid of the steps is not that of compute_tsdf()\n";

  std::size_t band = 0;
  for(double v : tsdf.values)
    if(std::abs(v) < tsdf.truncation) ++band;
  const PD::Adaptive_grid& g = tsdf.grid;
  std::printf("%-20s %6zu %-14s %4s %8.1f %8.1f %8.1f | %6.1f %6.1f %6.1f %6.1f | %8zu %7zu %8zu", shown.c_str(),
              std::size_t(num_faces(mesh)), name(tsdf.sign_method), closed ? "yes" : "no", t1, t2, cpu, t_tree,
              t_grid, t_sign, t2 - t_tree - t_grid - t_sign, g.number_of_leaves(),
              g.number_of_leaves_of_depth(PD::Adaptive_grid::depth_of(g.finest_resolution())), band);
  if(o.aabb)
  {
    std::vector<double> reference;
    const double ms = aabb_band_ms(tris, tsdf, reference);
    double worst = 0.;
    for(std::size_t l = 0; l < reference.size(); ++l)
      worst = std::max(worst, std::abs(reference[l] - std::abs(tsdf.values[l])));
    std::printf(" | %8.1f (max diff %.1e vox)", ms, worst / tsdf.voxel_size);
  }
  return tsdf;
}

// Prints the number of leaves whose sign differs from that of the closed original `file` (its exact
// winding numbers at the sign points of the same grid, in the frame of `tsdf`), and of its inside
// leaves, with their volumes.
static void compare_with_closed(const std::string& file, const PD::Truncated_signed_distance_field& tsdf)
{
  Mesh closed;
  PD::IO::read_triangle_mesh(file, closed);
  const auto tris = PDI::normalized_triangles(closed, get(CGAL::vertex_point, closed), tsdf.normalization);
  const std::vector<std::uint8_t> reference = PDI::leaf_inside_from_rows<Tag>(tris, tsdf.grid, false);
  std::size_t inside = 0, wrong = 0;
  double inside_volume = 0., wrong_volume = 0.;
  for(std::size_t l = 0; l < reference.size(); ++l)
  {
    const double v = tsdf.grid.volume(l);
    if(reference[l]) ++inside, inside_volume += v;
    if(bool(reference[l]) != std::signbit(tsdf.values[l])) ++wrong, wrong_volume += v;
  }
  std::printf(" | closed original: %zu leaves inside, %zu of the open mesh's signs differ (%.2f%% of the inside volume)",
              inside, wrong, inside_volume > 0. ? 100. * wrong_volume / inside_volume : 0.);
}

// Prints the largest distance error and the number of wrong signs of 4000 leaves, against CGAL's
// AABB tree on `mesh` and Side_of_triangle_mesh on `input` (the mesh before faces were removed).
static void check_against_cgal(const Mesh& mesh, const Mesh& input, const PD::Truncated_signed_distance_field& tsdf,
                               int open_faces)
{
  typedef CGAL::AABB_tree<CGAL::AABB_traits<K, CGAL::AABB_face_graph_triangle_primitive<Mesh> > > Tree;
  Tree tree(faces(mesh).first, faces(mesh).second, mesh);
  tree.accelerate_distance_queries();
  std::unique_ptr<CGAL::Side_of_triangle_mesh<Mesh, K> > side;
  const bool input_closed = CGAL::is_closed(input);
  if(input_closed) side.reset(new CGAL::Side_of_triangle_mesh<Mesh, K>(input));
  double worst = 0.;
  std::size_t wrong = 0;
  for(std::size_t s = 0; s < 4000; ++s)
  {
    const std::size_t l = (s * 2654435761u) % tsdf.values.size();
    const std::array<double, 3> x = tsdf.normalization.from_unit(tsdf.grid.center(l));
    const K::Point_3 p(x[0], x[1], x[2]);
    const double d =
      std::min(tsdf.truncation, std::sqrt(CGAL::to_double(tree.squared_distance(p))) * tsdf.normalization.scale());
    worst = std::max(worst, std::abs(d - std::abs(tsdf.values[l])));
    // the sign is decided at the leaf's sign point: the centre is on its side if the surface
    // cannot cross the leaf
    const double reach = 0.5 * std::sqrt(3.) * tsdf.grid.size(l) + (open_faces > 0 ? tsdf.voxel_size : 1e-9);
    if(side && d > reach)
      if(((*side)(p) == CGAL::ON_BOUNDED_SIDE) != (tsdf.values[l] < 0.)) ++wrong;
  }
  std::printf(" | %.1e, %zu%s", worst / tsdf.voxel_size, wrong, input_closed ? "" : " (no sign reference)");
}

int main(int argc, char** argv)
{
  const Options o = parse_options(argc, argv);
  if(o.files.empty())
  {
    std::cerr << "usage: " << argv[0]
              << " [-runs N] [-method auto|votes|inside|winding|flood] [-grid R] [-uniform] [-open K] [-check]"
                 " [-aabb] [-closed DIR] mesh [mesh ...]\n";
    return EXIT_FAILURE;
  }
#ifndef CGAL_LINKED_WITH_TBB
  std::cout << "(TBB not available: the 2-thread column is sequential)\n";
#endif
  {
    std::ifstream load("/proc/loadavg");
    std::string l1;
    if(load >> l1) std::cout << "load average at start: " << l1 << "\n";
  }
  std::printf("%-20s %6s %-14s %4s %8s %8s %8s | 2 thr: %4s %6s %6s %6s | %8s %7s %8s%s%s\n", "mesh", "faces",
              "sign", "clsd", "1thr ms", "2thr ms", "cpu ms", "tree", "grid", "sign", "other", "leaves", "finest",
              "band", o.aabb ? " | AABB band ms" : "", o.check ? " | check: max |d err| vox, wrong signs" : "");
  for(const std::string& file : o.files)
  {
    Mesh mesh;
    try
    {
      PD::IO::read_triangle_mesh(file, mesh);
    }
    catch(const std::exception& e)
    {
      std::cerr << file << ": " << e.what() << "\n";
      continue;
    }
    const Mesh input = mesh;
    if(o.open_faces > 0) remove_spread_faces(mesh, o.open_faces);
    const std::string shown = file.substr(file.find_last_of('/') == std::string::npos ? 0 : file.find_last_of('/') + 1);
    try
    {
      const PD::Truncated_signed_distance_field tsdf = time_tsdf(mesh, o, shown);
      if(o.check) check_against_cgal(mesh, input, tsdf, o.open_faces);
      if(!o.closed_dir.empty()) compare_with_closed(o.closed_dir + "/" + shown, tsdf);
    }
    catch(const std::exception& e) // a parameter out of its range
    {
      std::cerr << shown << ": " << e.what() << "\n";
      return EXIT_FAILURE;
    }
    std::printf("\n");
  }
  return EXIT_SUCCESS;
}
