// Over-segmentation and SQ-to-mesh assignment on a set of meshes: patch counts, timings (median
// of 7 runs) and the purity of the patches against a ground truth, if one is found.
//
// Usage: bench_assignment [--min-size F] [--max-size F] [--quantile Q] [--smoothing N] [--threads]
//                         mesh.off...
// The ground truth of NAME.off is NAME_0.seg (Princeton benchmark) or NAME.seg. Purity is the
// accuracy of the best labelling that is constant on each patch: an upper bound for the
// assignment. The assignment is timed on synthetic claims on the adaptive grid of the mesh's
// distance field (compute_tsdf() with its prior, as decompose() computes it): the leaves the field
// puts inside, claimed by 8 primitives, one per octant around the centre.
#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Surface_mesh.h>

#include <CGAL/Part_decomposition/IO/read_mesh.h>
#include <CGAL/Part_decomposition/flow_freeze_prior.h>
#include <CGAL/Part_decomposition/over_segmentation.h>
#include <CGAL/Part_decomposition/primitive_assignment.h>
#include <CGAL/Part_decomposition/tsdf.h>

#include <algorithm>
#include <chrono>
#include <ctime>
#include <cstdlib>
#include <fstream>
#include <iostream>
#include <map>
#include <string>
#include <vector>

namespace PD = CGAL::Part_decomposition;
typedef CGAL::Exact_predicates_inexact_constructions_kernel K;
typedef CGAL::Surface_mesh<K::Point_3> Mesh;

namespace {

// Median wall-clock and process CPU milliseconds of 7 runs (CPU time is the steadier figure on a
// shared machine; with threads it adds up all threads).
struct Timing
{
  double wall = 0., cpu = 0.;
};

template <typename F>
Timing median_ms(const F& f)
{
  std::vector<double> wall, cpu;
  for(int run = 0; run < 7; ++run)
  {
    const auto t0 = std::chrono::steady_clock::now();
    const std::clock_t c0 = std::clock();
    f();
    cpu.push_back(1000. * double(std::clock() - c0) / CLOCKS_PER_SEC);
    wall.push_back(std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - t0).count());
  }
  std::sort(wall.begin(), wall.end());
  std::sort(cpu.begin(), cpu.end());
  return Timing{wall[wall.size() / 2], cpu[cpu.size() / 2]};
}

// Per leaf of the field's grid: the octant of its centre (0 to 7) if the field puts it inside, -1.
std::vector<std::int32_t> synthetic_claims(const PD::Truncated_signed_distance_field& tsdf)
{
  std::vector<std::int32_t> claimed(tsdf.grid.number_of_leaves(), -1);
  for(std::size_t l = 0; l < claimed.size(); ++l)
  {
    if(!(tsdf.values[l] < 0.)) continue;
    const auto u = tsdf.grid.center(l);
    claimed[l] = (u[0] > 0 ? 1 : 0) + (u[1] > 0 ? 2 : 0) + (u[2] > 0 ? 4 : 0);
  }
  return claimed;
}

double purity(const std::string& file, const std::vector<std::size_t>& label, std::size_t count)
{
  std::ifstream in(file.substr(0, file.size() - 4) + "_0.seg");
  if(!in) in.open(file.substr(0, file.size() - 4) + ".seg");
  std::vector<int> truth;
  int v;
  while(in >> v) truth.push_back(v);
  if(truth.size() != label.size()) return -1.;
  std::vector<std::map<int, std::size_t> > hist(count);
  for(std::size_t i = 0; i < label.size(); ++i) ++hist[label[i]][truth[i]];
  std::size_t good = 0;
  for(const auto& h : hist)
  {
    std::size_t best = 0;
    for(const auto& e : h) best = (std::max)(best, e.second);
    good += best;
  }
  return double(good) / double(label.size());
}

template <typename Tag>
void run(const std::string& file, double min_size, double max_size, double q, int smoothing,
         std::vector<double>& counts, std::vector<double>& purities)
{
  Mesh m;
  PD::IO::read_triangle_mesh(file, m);
  const auto fim = get(CGAL::face_index, m);
  const auto np = PD::parameters::combine(PD::parameters::minimum_patch_size(min_size),
                                          PD::parameters::patch_split_size(max_size),
                                          PD::parameters::dihedral_percentile(q),
                                          PD::parameters::smoothing_iterations(smoothing));
  std::vector<std::size_t> label;
  PD::internal::Over_segmentation_statistics st;
  std::size_t count = 0;
  const Timing ms_over = median_ms([&] { count = PD::internal::over_segment_labels<Tag>(m, fim, label, np, &st); });

  const PD::Hierarchical_prior prior = PD::compute_flow_freeze_prior<Tag>(m);
  const PD::Truncated_signed_distance_field tsdf = PD::compute_tsdf<Tag>(m, prior);
  const std::vector<std::int32_t> claimed = synthetic_claims(tsdf);
  auto patch = m.add_property_map<Mesh::Face_index, std::size_t>("f:patch", 0).first;
  auto part = m.add_property_map<Mesh::Face_index, std::size_t>("f:part", 0).first;
  for(auto f : faces(m)) patch[f] = label[std::size_t(f)];
  std::size_t parts = 0;
  const Timing ms_assign = median_ms([&] { parts = PD::assign_parts<Tag>(m, patch, claimed, tsdf, part).size(); });
  std::size_t claimed_count = 0;
  for(std::int32_t l : claimed) claimed_count += l >= 0;

  const double p = purity(file, label, count);
  const std::string name = file.substr(file.find_last_of('/') + 1);
  std::cout << name << ' ' << num_faces(m) << ' ' << st.threshold << ' ' << st.number_of_cut_edges << ' '
            << st.number_of_components << ' ' << st.number_of_split_patches << ' '
            << st.number_of_merged_patches << ' ' << st.number_of_smoothed_faces << ' ' << count << ' ' << p
            << ' ' << ms_over.wall << ' ' << ms_over.cpu << ' ' << claimed.size() << ' ' << claimed_count << ' '
            << parts << ' ' << ms_assign.wall << ' ' << ms_assign.cpu << '\n';
  counts.push_back(double(count));
  if(p >= 0.) purities.push_back(p);
}

} // namespace

int main(int argc, char** argv)
{
  double min_size = 0.001, max_size = 0.003, q = 90.;
  int smoothing = 1;
  bool parallel = false;
  std::vector<std::string> files;
  for(int i = 1; i < argc; ++i)
  {
    const std::string a = argv[i];
    if(a == "--min-size" && i + 1 < argc) min_size = std::atof(argv[++i]);
    else if(a == "--max-size" && i + 1 < argc) max_size = std::atof(argv[++i]);
    else if(a == "--quantile" && i + 1 < argc) q = std::atof(argv[++i]);
    else if(a == "--smoothing" && i + 1 < argc) smoothing = std::atoi(argv[++i]);
    else if(a == "--threads") parallel = true;
    else files.push_back(a);
  }
  std::cout << "mesh faces threshold_deg cut_edges components after_split after_cleanup smoothed A purity"
               " over_segment_wall_ms over_segment_cpu_ms leaves claimed_leaves parts assign_wall_ms assign_cpu_ms\n";
  std::vector<double> counts, purities;
  for(const std::string& file : files)
  {
#ifdef CGAL_LINKED_WITH_TBB
    if(parallel)
      run<CGAL::Parallel_tag>(file, min_size, max_size, q, smoothing, counts, purities);
    else
#endif
      run<CGAL::Sequential_tag>(file, min_size, max_size, q, smoothing, counts, purities);
  }
  if(!counts.empty())
  {
    std::sort(counts.begin(), counts.end());
    std::cout << "A: min " << counts.front() << " median " << counts[counts.size() / 2] << " max "
              << counts.back() << '\n';
  }
  if(!purities.empty())
  {
    double sum = 0.;
    for(double p : purities) sum += p;
    std::sort(purities.begin(), purities.end());
    std::cout << "purity: mean " << sum / double(purities.size()) << " min " << purities.front() << '\n';
  }
  return EXIT_SUCCESS;
}
