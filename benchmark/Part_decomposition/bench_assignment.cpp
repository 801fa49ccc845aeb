// Patch counts and timings of the over-segmentation on a set of meshes.
// Usage: bench_over_segmentation [--min-size F] [--max-size F] [--quantile Q] [--smoothing N] [--threads] mesh.off...
#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Surface_mesh.h>

#include <CGAL/Part_decomposition/IO/read_mesh.h>
#include <CGAL/Part_decomposition/over_segmentation.h>

#include <algorithm>
#include <chrono>
#include <fstream>
#include <map>
#include <cstdlib>
#include <iostream>
#include <string>
#include <vector>

namespace PD = CGAL::Part_decomposition;
typedef CGAL::Exact_predicates_inexact_constructions_kernel K;
typedef CGAL::Surface_mesh<K::Point_3> Mesh;

template <typename Tag>
double run(const Mesh& m, std::vector<std::size_t>& label, double min_size, double max_size, double q, int smoothing,
           PD::internal::Over_segmentation_statistics& st, std::size_t& count)
{
  const auto fim = get(CGAL::face_index, m);
  const auto np = PD::parameters::combine(PD::parameters::minimum_patch_size(min_size),
                                          PD::parameters::maximum_patch_size(max_size),
                                          PD::parameters::dihedral_quantile(q),
                                          PD::parameters::smoothing_iterations(smoothing));
  std::vector<double> times;
  for(int run = 0; run < 5; ++run)
  {
    const auto t0 = std::chrono::steady_clock::now();
    count = PD::internal::over_segment_labels<Tag>(m, fim, label, np, &st);
    times.push_back(std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - t0).count());
  }
  std::sort(times.begin(), times.end());
  return times[times.size() / 2];
}

int main(int argc, char** argv)
{
  double min_size = 0.001, max_size = 0.0025, q = 90.;
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
  std::cout << "mesh faces threshold_deg cut_edges components after_split after_cleanup smoothed A median_ms\n";
  std::vector<double> counts, purity;
  for(const std::string& file : files)
  {
    Mesh m;
    PD::IO::read_triangle_mesh(file, m);
    std::vector<std::size_t> label;
    PD::internal::Over_segmentation_statistics st;
    std::size_t count = 0;
    double ms = 0.;
#ifdef CGAL_LINKED_WITH_TBB
    if(parallel) ms = run<CGAL::Parallel_tag>(m, label, min_size, max_size, q, smoothing, st, count);
    else
#endif
      ms = run<CGAL::Sequential_tag>(m, label, min_size, max_size, q, smoothing, st, count);
    const std::string name = file.substr(file.find_last_of('/') + 1);
    std::cout << name << ' ' << num_faces(m) << ' ' << st.threshold << ' ' << st.number_of_cut_edges << ' '
              << st.number_of_components << ' ' << st.number_of_split_patches << ' ' << st.number_of_merged_patches << ' '
              << st.number_of_smoothed_faces << ' ' << count << ' ' << ms << '\n';
    counts.push_back(double(count));
    // Purity against the first human segmentation, if any: the accuracy of the best labelling
    // that is constant on each patch (an upper bound for the assignment).
    const std::string seg = file.substr(0, file.size() - 4) + "_0.seg";
    std::ifstream in(seg);
    if(in)
    {
      std::vector<int> truth;
      int v;
      while(in >> v) truth.push_back(v);
      if(truth.size() == label.size())
      {
        std::vector<std::map<int, std::size_t> > hist(count);
        for(std::size_t i = 0; i < label.size(); ++i) ++hist[label[i]][truth[i]];
        std::size_t good = 0;
        for(const auto& h : hist)
        {
          std::size_t best = 0;
          for(const auto& e : h) best = (std::max)(best, e.second);
          good += best;
        }
        purity.push_back(double(good) / double(label.size()));
      }
    }
  }
  if(!counts.empty())
  {
    std::sort(counts.begin(), counts.end());
    std::cout << "A: min " << counts.front() << " median " << counts[counts.size() / 2] << " max "
              << counts.back() << '\n';
  if(!purity.empty())
  {
    double sum = 0.;
    for(double p : purity) sum += p;
    std::sort(purity.begin(), purity.end());
    std::cout << "purity vs _0.seg: mean " << sum / double(purity.size()) << " min " << purity.front() << '\n';
  }
  }
  return EXIT_SUCCESS;
}
