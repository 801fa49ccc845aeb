// figure_data: runs the Hi-TOPS pipeline stage by stage with `Part_decomposer` and writes what each
// stage computed, in files that render_mesh draws (doc/Part_decomposition/make_figures.sh).
//
// usage: figure_data MESH OUTDIR [--freeze-ratio A] [--resolutions 16,32,64] [--slice AXIS[:T]]
//
// OUTDIR receives, in the input coordinates of MESH:
//   prior_<r>.off       the Flow (blue) / Freeze (red) cut of every resolution r, one cube per voxel
//   prior_fused.off     the fused octree leaves, one cube per leaf (darker = coarser leaf)
//   tsdf_slice.ppm      a slice of the truncated signed distance field (blue inside, red outside)
//   zones_slice.ppm     the same slice of the fitting zones (exterior, Freeze zone, Flow zone)
//   primitives.off      the fitted superquadrics, in acceptance order (one component each)
//   claimed.off         the leaves of the adaptive grid claimed by each superquadric, one cube per
//                       leaf (same colours)
//   patches.seg         the patch of every face of MESH, in file order
//   parts.seg           the part of every face of MESH, in file order
//   part_primitives.off the superquadric of every part, in part order
//   summary.txt         counts of each stage
// The slice is across AXIS (x, y or z, default z) at the fraction T of the grid (default: the
// slice that cuts the most voxels of the shape). The distance field and the zones hold one value
// per leaf of an adaptive grid: a slice is one layer of the voxels of its finest resolution, each
// drawn with the value of the leaf that holds it.

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Surface_mesh.h>

#include <CGAL/Part_decomposition/IO/read_mesh.h>
#include <CGAL/Part_decomposition/Part_decomposer.h>
#include <CGAL/Part_decomposition/decompose.h>
#include <CGAL/Part_decomposition/fitting_zones.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <cstdlib>
#include <fstream>
#include <iostream>
#include <map>
#include <sstream>
#include <string>
#include <vector>

typedef CGAL::Exact_predicates_inexact_constructions_kernel K;
typedef CGAL::Surface_mesh<K::Point_3> Mesh;
namespace PD = CGAL::Part_decomposition;
typedef CGAL::Parallel_if_available_tag Concurrency;
typedef std::array<int, 3> Rgb;

// the colour of part k in the hitops tool
Rgb palette(std::size_t k)
{
  const double h = std::fmod(0.13 + 0.618033988749895 * double(k), 1.) * 6.;
  const double s = (k % 3 == 2) ? 0.55 : 0.8, v = (k % 2) ? 0.8 : 0.95;
  const int i = int(h);
  const double f = h - i, p = v * (1 - s), q = v * (1 - s * f), t = v * (1 - s * (1 - f));
  double r, g, b;
  switch(i % 6)
  {
    case 0: r = v; g = t; b = p; break;
    case 1: r = q; g = v; b = p; break;
    case 2: r = p; g = v; b = t; break;
    case 3: r = p; g = q; b = v; break;
    case 4: r = t; g = p; b = v; break;
    default: r = v; g = p; b = q; break;
  }
  return {{int(std::lround(255 * r)), int(std::lround(255 * g)), int(std::lround(255 * b))}};
}

const Rgb flow_color = {{70, 120, 215}}, freeze_color = {{225, 60, 45}};

Rgb shaded(const Rgb& c, double f)
{
  return {{int(std::lround(c[0] * f)), int(std::lround(c[1] * f)), int(std::lround(c[2] * f))}};
}

struct Cube
{
  std::array<double, 3> center; // input coordinates
  double size;                  // edge, input units
  Rgb color;
};

// Writes cubes (slightly shrunk so that neighbouring voxels stay distinct) as an OFF file with
// one colour per face.
bool write_cubes(const std::string& file, const std::vector<Cube>& cubes, double shrink = 0.88)
{
  std::ofstream out(file);
  if(!out) return false;
  out.precision(9);
  out << "OFF\n" << 8 * cubes.size() << ' ' << 6 * cubes.size() << " 0\n";
  for(const Cube& c : cubes)
  {
    const double h = 0.5 * shrink * c.size;
    for(int k = 0; k < 8; ++k)
      out << c.center[0] + (k & 1 ? h : -h) << ' ' << c.center[1] + (k & 2 ? h : -h) << ' '
          << c.center[2] + (k & 4 ? h : -h) << '\n';
  }
  static const int quads[6][4] = {{0, 2, 3, 1}, {4, 5, 7, 6}, {0, 1, 5, 4}, {2, 6, 7, 3}, {0, 4, 6, 2}, {1, 3, 7, 5}};
  for(std::size_t i = 0; i < cubes.size(); ++i)
    for(const auto& q : quads)
      out << "4 " << 8 * i + q[0] << ' ' << 8 * i + q[1] << ' ' << 8 * i + q[2] << ' ' << 8 * i + q[3] << ' '
          << cubes[i].color[0] << ' ' << cubes[i].color[1] << ' ' << cubes[i].color[2] << '\n';
  return bool(out);
}

template <typename Superquadrics>
bool write_superquadrics(const std::string& file, const Superquadrics& sqs)
{
  Mesh all;
  for(const auto& q : sqs)
  {
    Mesh one;
    q.to_triangle_mesh(one, 24);
    all.join(one);
  }
  std::ofstream out(file);
  out.precision(9);
  return out && CGAL::IO::write_OFF(out, all);
}

bool write_labels(const std::string& file, const std::vector<std::size_t>& labels)
{
  std::ofstream out(file);
  for(std::size_t l : labels) out << l << '\n';
  return bool(out);
}

// The slice `index` across `axis` of an r^3 grid as a PPM image, 512 / r pixels (at least one) per
// voxel; the horizontal image axis is the next axis after `axis`, the vertical one the last (so that
// a slice across y of a z-up shape is a side view). `color(i,j,k)` gives each voxel's colour;
// `edge(a,b)` tells whether a dark line is drawn between two voxels.
template <typename Color, typename Edge>
bool write_slice(const std::string& file, int r, int axis, int index, const Color& color, const Edge& edge)
{
  const int scale = std::max(1, 512 / r);
  const int ha = axis == 2 ? 0 : (axis == 0 ? 1 : 0), va = axis == 2 ? 1 : 2;
  auto voxel = [&](int a, int b) {
    std::array<int, 3> ijk;
    ijk[std::size_t(axis)] = index;
    ijk[std::size_t(ha)] = a;
    ijk[std::size_t(va)] = b;
    return ijk;
  };
  std::ofstream out(file, std::ios::binary);
  if(!out) return false;
  out << "P6\n" << r * scale << ' ' << r * scale << "\n255\n";
  for(int y = r * scale - 1; y >= 0; --y)
    for(int x = 0; x < r * scale; ++x)
    {
      const int a = x / scale, b = y / scale;
      const std::array<int, 3> v = voxel(a, b);
      Rgb c = color(v);
      const bool line = (a + 1 < r && x % scale == scale - 1 && edge(v, voxel(a + 1, b))) ||
                        (b + 1 < r && y % scale == scale - 1 && edge(v, voxel(a, b + 1))) ||
                        (a > 0 && x % scale == 0 && edge(v, voxel(a - 1, b))) ||
                        (b > 0 && y % scale == 0 && edge(v, voxel(a, b - 1)));
      if(line) c = {{20, 20, 20}};
      const unsigned char rgb[3] = {(unsigned char)c[0], (unsigned char)c[1], (unsigned char)c[2]};
      out.write(reinterpret_cast<const char*>(rgb), 3);
    }
  return bool(out);
}

struct Figure_options
{
  std::string input, dir;
  double alpha = PD::defaults::freeze_ratio;
  std::vector<int> resolutions = PD::defaults::voxel_resolutions;
  int axis = 2;
  double slice_fraction = -1.; // < 0: the slice with the most non-exterior voxels
};

bool parse(int argc, char** argv, Figure_options& o)
{
  if(argc < 3)
  {
    std::cerr << "usage: figure_data MESH OUTDIR [--freeze-ratio A] [--resolutions 16,32,64] [--slice AXIS[:T]]\n";
    return false;
  }
  o.input = argv[1];
  o.dir = argv[2];
  for(int i = 3; i + 1 < argc; i += 2)
  {
    const std::string a = argv[i], v = argv[i + 1];
    if(a == "--freeze-ratio") o.alpha = std::stod(v);
    else if(a == "--resolutions")
    {
      o.resolutions.clear();
      std::istringstream s(v);
      std::string t;
      while(std::getline(s, t, ',')) o.resolutions.push_back(std::stoi(t));
    }
    else if(a == "--slice")
    {
      o.axis = v[0] == 'x' ? 0 : v[0] == 'y' ? 1 : 2;
      if(v.size() > 2) o.slice_fraction = std::stod(v.substr(2));
    }
    else
    {
      std::cerr << "unknown option " << a << "\n";
      return false;
    }
  }
  return true;
}

// The cut of each resolution, one cube per non-empty voxel.
bool write_level_cubes(const std::string& dir, const PD::Hierarchical_prior& prior)
{
  const PD::Normalization& normalization = prior.normalization;
  const double unit = 1. / normalization.scale(); // one normalized unit in input units
  bool ok = true;
  for(const PD::Topology_score_field& field : prior.fields)
  {
    std::vector<Cube> cubes;
    const int r = field.resolution;
    for(std::size_t v = 0; v < field.classes.size(); ++v)
    {
      if(field.classes[v] == PD::Voxel_class::EMPTY) continue;
      cubes.push_back({normalization.from_unit(field.classes.center(v)), unit / r,
                       field.classes[v] == PD::Voxel_class::FREEZE ? freeze_color : flow_color});
    }
    ok = ok && write_cubes(dir + "/prior_" + std::to_string(r) + ".off", cubes);
  }
  return ok;
}

// The fused leaves: the leaf of resolution R(v) that holds each finest voxel, once.
bool write_fused_leaves(const std::string& dir, const PD::Hierarchical_prior& prior)
{
  const PD::Normalization& normalization = prior.normalization;
  const double unit = 1. / normalization.scale();
  const int rf = prior.classes.resolution();
  const std::size_t L = prior.resolutions.size();
  std::map<std::array<int, 4>, Cube> leaves;
  for(std::size_t v = 0; v < prior.classes.size(); ++v)
  {
    if(prior.classes[v] == PD::Voxel_class::EMPTY) continue;
    const int rl = prior.leaf_resolution[v], f = rf / rl;
    const std::array<int, 3> c = prior.classes.coordinates(v);
    const std::array<int, 4> key = {{rl, c[0] / f, c[1] / f, c[2] / f}};
    if(leaves.count(key)) continue;
    std::size_t level = 0;
    while(level + 1 < L && prior.resolutions[level] != rl) ++level;
    const double shade = L > 1 ? 0.6 + 0.4 * double(level) / double(L - 1) : 1.; // coarse = darker
    const std::array<double, 3> center = {{-0.5 + (key[1] + 0.5) / rl, -0.5 + (key[2] + 0.5) / rl,
                                           -0.5 + (key[3] + 0.5) / rl}};
    leaves[key] = {normalization.from_unit(center), unit / rl,
                   shaded(prior.classes[v] == PD::Voxel_class::FREEZE ? freeze_color : flow_color, shade)};
  }
  std::vector<Cube> cubes;
  for(const auto& kv : leaves) cubes.push_back(kv.second);
  return write_cubes(dir + "/prior_fused.off", cubes, 0.94);
}

// The leaf of `grid` that holds the finest voxel v (that locate() finds at its centre).
std::size_t leaf_at(const PD::Adaptive_grid& grid, const std::array<int, 3>& v)
{
  return grid.leaf_of_voxel(std::uint32_t(v[0]), std::uint32_t(v[1]), std::uint32_t(v[2]));
}

// The slice of finest voxels along `axis` with the most voxels outside the exterior.
int fullest_slice(const PD::Fitting_zones& zones, const PD::Adaptive_grid& grid, int axis)
{
  const int r = grid.finest_resolution();
  int index = r / 2;
  std::size_t best = 0;
  for(int s = 0; s < r; ++s)
  {
    std::size_t n = 0;
    for(int a = 0; a < r; ++a)
      for(int b = 0; b < r; ++b)
      {
        std::array<int, 3> v;
        v[std::size_t(axis)] = s;
        v[std::size_t(axis == 0 ? 1 : 0)] = a;
        v[std::size_t(axis == 2 ? 1 : 2)] = b;
        n += !zones.exterior[leaf_at(grid, v)];
      }
    if(n > best) best = n, index = s;
  }
  return index;
}

// The slice of the distance field and of the zones of the finest fitting resolution, in finest
// voxels of the grid; returns the slice index.
int write_slices(const Figure_options& o, const PD::Truncated_signed_distance_field& tsdf,
                 const PD::Fitting_zones& zones, bool& ok)
{
  const PD::Adaptive_grid& grid = tsdf.grid;
  const int r = grid.finest_resolution();
  const std::vector<std::uint8_t>& flow = zones.flow_zone.rbegin()->second; // the finest r_fit
  const int index = o.slice_fraction >= 0. ? std::min(r - 1, int(o.slice_fraction * r)) : fullest_slice(zones, grid, o.axis);
  const double tau = tsdf.truncation;
  auto inside = [&](const std::array<int, 3>& v) { return tsdf.values[leaf_at(grid, v)] < 0.; };
  auto boundary = [&](const std::array<int, 3>& a, const std::array<int, 3>& b) { return inside(a) != inside(b); };
  auto tsdf_color = [&](const std::array<int, 3>& v) -> Rgb {
    const double d = tsdf.values[leaf_at(grid, v)], t = std::min(1., std::abs(d) / tau);
    if(t >= 1.) return d < 0 ? Rgb{{48, 82, 160}} : Rgb{{236, 236, 236}};
    const double s = 0.25 + 0.75 * t; // white at the surface, saturated at the truncation
    return d < 0 ? Rgb{{int(255 * (1 - 0.8 * s)), int(255 * (1 - 0.6 * s)), 255}}
                 : Rgb{{255, int(255 * (1 - 0.7 * s)), int(255 * (1 - 0.75 * s))}};
  };
  ok = ok && write_slice(o.dir + "/tsdf_slice.ppm", r, o.axis, index, tsdf_color, boundary);
  auto zone_color = [&](const std::array<int, 3>& v) -> Rgb {
    const std::size_t l = leaf_at(grid, v);
    if(zones.classes[l] == PD::Voxel_class::FREEZE) return freeze_color;
    if(!zones.exterior[l])
      return zones.classes[l] == PD::Voxel_class::FLOW ? flow_color        // Flow carrier leaves
                                                       : Rgb{{160, 190, 240}}; // interior of the hull
    return flow[l] ? Rgb{{215, 228, 250}}  // Flow-zone tolerance outside the hull
                   : Rgb{{255, 255, 255}}; // exterior
  };
  ok = ok && write_slice(o.dir + "/zones_slice.ppm", r, o.axis, index, zone_color, boundary);
  return index;
}

bool write_claims_and_summary(const Figure_options& o, const Mesh& mesh, const PD::Hierarchical_prior& prior,
                              const PD::Truncated_signed_distance_field& tsdf,
                              const PD::Superquadric_fitting_result<K>& fit, int slice, std::size_t number_of_patches,
                              std::size_t number_of_parts)
{
  const PD::Adaptive_grid& grid = tsdf.grid;
  const double unit = 1. / prior.normalization.scale();
  std::vector<Cube> claimed;
  for(std::size_t l = 0; l < fit.labels.size(); ++l)
    if(fit.labels[l] >= 0)
      claimed.push_back({prior.normalization.from_unit(grid.center(l)), unit * grid.size(l),
                         palette(std::size_t(fit.labels[l]))});
  bool ok = write_cubes(o.dir + "/claimed.off", claimed);
  std::ofstream summary(o.dir + "/summary.txt");
  summary << o.input << ": " << num_faces(mesh) << " faces\n"
          << "slice " << "xyz"[o.axis] << " = " << slice << " of " << grid.finest_resolution() << "\n";
  for(std::size_t l = 0; l < prior.fields.size(); ++l)
    summary << "r = " << prior.resolutions[l] << ": " << prior.fields[l].number_of_active_voxels << " active voxels, "
            << prior.fields[l].number_of_freeze_voxels << " Freeze; fused leaves " << prior.number_of_flow_leaves[l]
            << " Flow, " << prior.number_of_freeze_leaves[l] << " Freeze\n";
  summary << "grid: " << grid.number_of_leaves() << " leaves, by resolution:";
  for(int d = 0; (1 << d) <= grid.finest_resolution(); ++d)
    if(grid.number_of_leaves_of_depth(d) > 0) summary << ' ' << (1 << d) << ": " << grid.number_of_leaves_of_depth(d);
  summary << "\n"
          << fit.primitives.size() << " superquadrics, " << number_of_patches << " patches, " << number_of_parts
          << " parts\n";
  return ok && bool(summary);
}

int main(int argc, char** argv)
{
  Figure_options o;
  if(!parse(argc, argv, o)) return EXIT_FAILURE;
  Mesh mesh;
  PD::IO::Mesh_file_info info;
  try
  {
    info = PD::IO::read_triangle_mesh(o.input, mesh);
  }
  catch(const PD::Invalid_input& e)
  {
    std::cerr << "cannot read " << o.input << ": " << e.what() << "\n";
    return EXIT_FAILURE;
  }

  const auto np = PD::parameters::combine(PD::parameters::freeze_ratio(o.alpha),
                                          PD::parameters::voxel_resolutions(o.resolutions));
  PD::Part_decomposer<Mesh> decomposer(mesh);
  const PD::Hierarchical_prior& prior = decomposer.compute_prior<Concurrency>(np);
  const PD::Truncated_signed_distance_field& tsdf = decomposer.compute_distance_field<Concurrency>(np);
  // the zones the fitter uses, at the fitting resolutions of the prior
  const PD::Fitting_zones& zones = decomposer.compute_fitting_zones<Concurrency>(np);
  const PD::Superquadric_fitting_result<K>& fit = decomposer.fit_primitives<Concurrency>(np);
  const std::size_t number_of_patches = decomposer.over_segment<Concurrency>(np);
  std::vector<std::size_t> part(num_faces(mesh), 0);
  const std::size_t number_of_parts = decomposer.compose_parts<Concurrency>(CGAL::make_property_map(part), np);

  bool ok = write_level_cubes(o.dir, prior) && write_fused_leaves(o.dir, prior);
  const int slice = write_slices(o, tsdf, zones, ok);
  ok = ok && write_claims_and_summary(o, mesh, prior, tsdf, fit, slice, number_of_patches, number_of_parts);
  ok = ok && write_superquadrics(o.dir + "/primitives.off", fit.input_primitives);
  ok = ok && write_superquadrics(o.dir + "/part_primitives.off", decomposer.part_primitives());
  ok = ok && write_labels(o.dir + "/patches.seg", PD::IO::labels_in_file_order(info, decomposer.patches()));
  ok = ok && write_labels(o.dir + "/parts.seg", PD::IO::labels_in_file_order(info, part));
  if(!ok)
  {
    std::cerr << "cannot write the outputs in " << o.dir << "\n";
    return EXIT_FAILURE;
  }
  std::cout << o.input << ": " << fit.primitives.size() << " superquadrics, " << number_of_patches << " patches, "
            << number_of_parts << " parts; outputs in " << o.dir << std::endl;
  return EXIT_SUCCESS;
}
