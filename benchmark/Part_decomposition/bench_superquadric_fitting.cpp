// Times SDFSQFit (fit_superquadrics) on meshes and scores the parts it induces.
//
// Usage: bench_superquadric_fitting [--threads N] [--runs R] [--mode mps|oneshot] [--roi X]
//        [--no-exterior-band] [--no-connected] [--max-evals N] [--rejections K]
//        [--verbose] mesh...
// Per mesh: the leaves of the adaptive grid of the distance field, the median fitting time over R
// runs (prior and TSDF excluded), the number of primitives, seeds, rejections, solves and residual
// evaluations; then, if NAME_k.seg files lie next to the mesh, the mean mIoU / RI / VoI / SC over
// them of the segmentation obtained with over_segment() + assign_parts() (the paper's protocol,
// 10000 area-weighted samples).

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Surface_mesh.h>

#include <CGAL/Part_decomposition/IO/read_mesh.h>
#include <CGAL/Part_decomposition/flow_freeze_prior.h>
#include <CGAL/Part_decomposition/over_segmentation.h>
#include <CGAL/Part_decomposition/primitive_assignment.h>
#include <CGAL/Part_decomposition/superquadric_fitting.h>
#include <CGAL/Part_decomposition/tsdf.h>

#include "segmentation_metrics.h"

#ifdef CGAL_LINKED_WITH_TBB
#include <tbb/global_control.h>
#endif

#include <algorithm>
#include <array>
#include <chrono>
#include <cstdlib>
#include <fstream>
#include <iomanip>
#include <iostream>
#include <memory>
#include <string>
#include <vector>

typedef CGAL::Exact_predicates_inexact_constructions_kernel K;
typedef CGAL::Surface_mesh<K::Point_3> Mesh;
namespace PD = CGAL::Part_decomposition;
typedef CGAL::Parallel_if_available_tag Tag;

namespace {

double now_s() { return std::chrono::duration<double>(std::chrono::steady_clock::now().time_since_epoch()).count(); }

double median(std::vector<double> v)
{
  std::sort(v.begin(), v.end());
  return v[v.size() / 2];
}

std::vector<int> read_seg(const std::string& file)
{
  std::vector<int> labels;
  std::ifstream in(file);
  int l;
  while(in >> l) labels.push_back(l);
  return labels;
}

} // namespace

struct Options
{
  int threads = 0, runs = 3;
  bool verbose = false;
  PD::Method_variant switches; // interior_weight_mode, use_exterior_band_samples, use_reachable_regions
  double roi = PD::defaults::roi_radius;
  int evaluations = PD::defaults::maximum_solver_evaluations;
  std::size_t rejections = PD::defaults::maximum_rejections_in_a_row;
  std::vector<std::string> files;
};

Options parse_options(int argc, char** argv)
{
  Options o;
  for(int i = 1; i < argc; ++i)
  {
    const std::string a = argv[i];
    if(a == "--threads" && i + 1 < argc) o.threads = std::atoi(argv[++i]);
    else if(a == "--runs" && i + 1 < argc) o.runs = std::max(1, std::atoi(argv[++i]));
    else if(a == "--mode" && i + 1 < argc)
      o.switches.interior_weight_mode = std::string(argv[++i]) == "mps" ? PD::Interior_weight_mode::MPS_REESTIMATED : PD::Interior_weight_mode::ONE_SHOT;
    else if(a == "--roi" && i + 1 < argc) o.roi = std::atof(argv[++i]);
    else if(a == "--no-exterior-band") o.switches.use_exterior_band_samples = false;
    else if(a == "--no-connected") o.switches.use_reachable_regions = false;
    else if(a == "--max-evals" && i + 1 < argc) o.evaluations = std::atoi(argv[++i]);
    else if(a == "--rejections" && i + 1 < argc) o.rejections = std::size_t(std::atol(argv[++i]));
    else if(a == "--verbose") o.verbose = true;
    else o.files.push_back(a);
  }
  return o;
}

// fit_superquadrics() run `o.runs` times; `seconds` receives the median time.
PD::Superquadric_fitting_result<K> timed_fit(const PD::Hierarchical_prior& prior,
                                             const PD::Truncated_signed_distance_field& tsdf, const Options& o,
                                             double& seconds)
{
  std::vector<double> times;
  PD::Superquadric_fitting_result<K> res;
  for(int run = 0; run < o.runs; ++run)
  {
    const double t0 = now_s();
    // the zones are part of the fitting stage
    res = PD::fit_superquadrics<Tag, K>(
      prior, tsdf,
      PD::parameters::combine(CGAL::parameters::verbose(o.verbose && run == 0), PD::parameters::roi_radius(o.roi),
                              PD::parameters::method_variant(o.switches),
                              PD::parameters::maximum_solver_evaluations(o.evaluations),
                              PD::parameters::maximum_rejections_in_a_row(o.rejections)));
    times.push_back(now_s() - t0);
  }
  seconds = median(times);
  return res;
}

// The mean scores (mIoU, RI, VoI, SC) of the induced segmentation against every BASE_k.seg whose
// size matches; the number of them in `n_gt`.
std::array<double, 4> mean_scores(Mesh& mesh, const PD::IO::Mesh_file_info& info,
                                  const PD::Superquadric_fitting_result<K>& res,
                                  const PD::Truncated_signed_distance_field& tsdf, const std::string& base, int& n_gt)
{
  auto patch = get(CGAL::dynamic_face_property_t<std::size_t>(), mesh);
  PD::over_segment<Tag>(mesh, patch);
  auto part = get(CGAL::dynamic_face_property_t<std::size_t>(), mesh);
  PD::assign_parts<Tag>(mesh, patch, res.labels, tsdf, part); // labels per leaf of the field's grid
  std::array<double, 4> s = {{0, 0, 0, 0}};
  n_gt = 0;
  for(int k = 0; k < 32; ++k)
  {
    const std::vector<int> gt_file = read_seg(base + "_" + std::to_string(k) + ".seg");
    if(gt_file.empty()) continue;
    if(gt_file.size() != info.number_of_input_faces) continue;
    auto gt = get(CGAL::dynamic_face_property_t<int>(), mesh);
    std::size_t i = 0;
    for(auto f : faces(mesh)) put(gt, f, gt_file[info.face_to_input[i++]]);
    const PD::Segmentation_scores sc = PD::evaluate_segmentation(mesh, gt, part);
    s[0] += sc.mean_iou;
    s[1] += sc.rand_index;
    s[2] += sc.variation_of_information;
    s[3] += sc.segmentation_covering;
    ++n_gt;
  }
  if(n_gt > 0)
    for(double& v : s) v /= n_gt;
  return s;
}

int main(int argc, char** argv)
{
  const Options o = parse_options(argc, argv);
#ifdef CGAL_LINKED_WITH_TBB
  std::unique_ptr<tbb::global_control> control;
  if(o.threads > 0)
    control.reset(new tbb::global_control(tbb::global_control::max_allowed_parallelism, std::size_t(o.threads)));
#endif
  std::cout << std::fixed << std::setprecision(3);
  std::cout << "mesh\tfaces\tleaves\tfit_ms\tprims\tseeds\tbody\trej_flow\trej_vol\tsolves\tevals\tsamples\tcov16\tcov32\tcov64"
               "\tmIoU\tRI\tVoI\tSC\n";
  double sum[4] = {0, 0, 0, 0};
  std::size_t scored = 0;
  std::vector<double> all_times;
  for(const std::string& file : o.files)
  {
    Mesh mesh;
    PD::IO::Mesh_file_info info;
    try
    {
      info = PD::IO::read_triangle_mesh(file, mesh);
    }
    catch(const std::exception& e)
    {
      std::cerr << file << ": " << e.what() << "\n";
      continue;
    }
    const PD::Hierarchical_prior prior = PD::compute_flow_freeze_prior<Tag>(mesh);
    // the grid the prior asks for, as decompose() computes it
    const PD::Truncated_signed_distance_field tsdf = PD::compute_tsdf<Tag>(mesh, prior);
    double t = 0.;
    const PD::Superquadric_fitting_result<K> res = timed_fit(prior, tsdf, o, t);
    all_times.push_back(t);

    const std::string base = file.substr(0, file.find_last_of('.'));
    int n_gt = 0;
    const std::array<double, 4> s = mean_scores(mesh, info, res, tsdf, base, n_gt);
    const std::string name = base.substr(base.find_last_of('/') + 1);
    std::cout << name << "\t" << num_faces(mesh) << "\t" << tsdf.grid.number_of_leaves() << "\t" << 1000. * t << "\t" << res.primitives.size() << "\t"
              << res.number_of_seeds << "\t" << res.number_of_body_seeds << "\t" << res.rejected_by_flow_zone << "\t"
              << res.rejected_by_volume << "\t" << res.number_of_solves << "\t" << res.number_of_evaluations << "\t"
              << res.number_of_samples;
    for(double c : res.stage_coverage) std::cout << "\t" << c;
    if(n_gt > 0)
    {
      for(double v : s) std::cout << "\t" << v;
      for(int q = 0; q < 4; ++q) sum[q] += s[std::size_t(q)];
      ++scored;
    }
    std::cout << std::endl;
  }
  if(scored > 0)
    std::cout << "MEAN over " << scored << " shapes: mIoU " << sum[0] / scored << " RI " << sum[1] / scored << " VoI "
              << sum[2] / scored << " SC " << sum[3] / scored << "; median fit " << 1000. * median(all_times)
              << " ms\n";
  return EXIT_SUCCESS;
}
