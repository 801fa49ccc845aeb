// Times the Flow/Freeze prior (cues, one-pass multi-resolution score, fusion) on meshes.
//
// Usage: bench_prior [--threads N] [--runs R] mesh...
// Prints, per mesh, the median over R runs of each step and of compute_flow_freeze_prior() (wall
// time; its minimum over the runs; the process CPU time of the latter).

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Surface_mesh.h>

#include <CGAL/Part_decomposition/IO/read_mesh.h>
#include <CGAL/Part_decomposition/flow_freeze_prior.h>

#ifdef CGAL_LINKED_WITH_TBB
#include <tbb/global_control.h>
#endif

#include <algorithm>
#include <chrono>
#include <ctime>
#include <cstdlib>
#include <iomanip>
#include <iostream>
#include <memory>
#include <string>
#include <vector>

typedef CGAL::Exact_predicates_inexact_constructions_kernel K;
typedef CGAL::Surface_mesh<K::Point_3> Mesh;
namespace PD = CGAL::Part_decomposition;
namespace PDI = CGAL::Part_decomposition::internal;
typedef CGAL::Parallel_if_available_tag Tag;

namespace {

double now_ms()
{
  return std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now().time_since_epoch()).count();
}

// Process CPU time (all threads): on a loaded machine it shows what the wall time would be alone.
double cpu_ms() { return 1000. * double(std::clock()) / CLOCKS_PER_SEC; }

double median(std::vector<double> v)
{
  std::sort(v.begin(), v.end());
  return v[v.size() / 2];
}

} // namespace

int main(int argc, char** argv)
{
  int threads = 0, runs = 5;
  std::vector<std::string> files;
  for(int i = 1; i < argc; ++i)
  {
    const std::string a = argv[i];
    if(a == "--threads" && i + 1 < argc) threads = std::atoi(argv[++i]);
    else if(a == "--runs" && i + 1 < argc) runs = std::max(1, std::atoi(argv[++i]));
    else files.push_back(a);
  }
  if(files.empty())
  {
    std::cerr << "usage: bench_prior [--threads N] [--runs R] mesh..." << std::endl;
    return EXIT_FAILURE;
  }
#ifdef CGAL_LINKED_WITH_TBB
  std::unique_ptr<tbb::global_control> control;
  if(threads > 0)
    control.reset(new tbb::global_control(tbb::global_control::max_allowed_parallelism, std::size_t(threads)));
#endif
  std::cout << "threads: " << (threads > 0 ? std::to_string(threads) : std::string("default")) << ", runs: " << runs
            << " (median ms)\n";
  std::cout << std::left << std::setw(18) << "mesh" << std::right << std::setw(7) << "faces" << std::setw(8)
            << "arrays" << std::setw(8) << "curv" << std::setw(8) << "phi" << std::setw(8) << "score"
            << std::setw(8) << "fusion" << std::setw(9) << "TOTAL" << std::setw(9) << "min" << std::setw(9) << "CPU"
            << "  freeze16/32/64  leaves(flow/freeze)\n";
  for(const std::string& file : files)
  {
    Mesh mesh;
    try { PD::IO::read_triangle_mesh(file, mesh); }
    catch(const std::exception& e)
    {
      std::cerr << file << ": " << e.what() << std::endl;
      continue;
    }
    const auto np = CGAL::parameters::default_values();
    std::vector<double> t_arrays, t_curv, t_phi, t_score, t_fusion, t_total, t_cpu;
    PD::Hierarchical_prior prior;
    for(int run = 0; run < runs; ++run)
    {
      double t0 = now_ms();
      const PDI::Triangle_arrays arrays = PDI::make_triangle_arrays(mesh, np);
      const PD::Normalization nz = PD::compute_normalization(mesh);
      double t1 = now_ms();
      const PDI::Vertex_corners vc = PDI::make_vertex_corners(arrays);
      const std::vector<double> kappa = PDI::vertex_mean_curvatures<Tag>(arrays, vc);
      const std::vector<double> c = PDI::face_curvature_cue(arrays, vc, kappa, 99.5);
      double t2 = now_ms();
      const std::vector<double> phi = PDI::face_normal_deviation<Tag>(arrays, 8);
      double t3 = now_ms();
      std::vector<PD::Topology_score_field> fields = PDI::topology_score_fields<Tag>(
        arrays, c, phi, std::vector<int>{16, 32, 64}, nz, PD::barycentric_sample_grid(36), {{1., 1., 1., 1.}}, 0.15);
      double t4 = now_ms();
      std::vector<PD::Voxel_grid<PD::Voxel_class> > levels;
      for(const auto& f : fields) levels.push_back(f.classes);
      const PD::Hierarchical_prior fused = PD::fuse_flow_freeze(levels);
      double t5 = now_ms();
      const double c5 = cpu_ms();
      prior = PD::compute_flow_freeze_prior<Tag>(mesh);
      double t6 = now_ms();
      t_cpu.push_back(cpu_ms() - c5);
      t_arrays.push_back(t1 - t0);
      t_curv.push_back(t2 - t1);
      t_phi.push_back(t3 - t2);
      t_score.push_back(t4 - t3);
      t_fusion.push_back(t5 - t4);
      t_total.push_back(t6 - t5);
      if(fused.classes != prior.classes)
      {
        std::cerr << "steps and compute_flow_freeze_prior() disagree" << std::endl;
        return EXIT_FAILURE;
      }
    }
    // Same bits as the sequential run, whatever the number of threads.
    const PD::Hierarchical_prior sequential = PD::compute_flow_freeze_prior<CGAL::Sequential_tag>(mesh);
    bool same = sequential.classes == prior.classes && sequential.leaf_resolution == prior.leaf_resolution;
    for(std::size_t l = 0; l < prior.fields.size(); ++l)
      same = same && sequential.fields[l].score == prior.fields[l].score &&
             sequential.fields[l].threshold == prior.fields[l].threshold;
    // Fusion never lets a Flow leaf cover a finest-level Freeze voxel.
    const auto& finest = prior.fields.back().classes;
    for(std::size_t v = 0; v < finest.size(); ++v)
      same = same && (finest[v] != PD::Voxel_class::FREEZE || prior.classes[v] == PD::Voxel_class::FREEZE);
    if(!same)
    {
      std::cerr << file << ": the parallel prior differs from the sequential one, or a finest Freeze voxel was lost" << std::endl;
      return EXIT_FAILURE;
    }
    std::string name = file.substr(file.find_last_of('/') + 1);
    std::cout << std::left << std::setw(18) << name << std::right << std::fixed << std::setprecision(1)
              << std::setw(7) << num_faces(mesh) << std::setw(8) << median(t_arrays) << std::setw(8)
              << median(t_curv) << std::setw(8) << median(t_phi) << std::setw(8) << median(t_score)
              << std::setw(8) << median(t_fusion) << std::setw(9) << median(t_total) << std::setw(9)
              << *std::min_element(t_total.begin(), t_total.end()) << std::setw(9) << median(t_cpu) << "  ";
    for(const auto& f : prior.fields)
      std::cout << f.number_of_freeze_voxels << "/" << f.number_of_active_voxels << " ";
    std::cout << " ";
    for(std::size_t l = 0; l < prior.resolutions.size(); ++l)
      std::cout << prior.number_of_flow_leaves[l] << "/" << prior.number_of_freeze_leaves[l] << " ";
    std::cout << std::endl;
  }
  return EXIT_SUCCESS;
}
