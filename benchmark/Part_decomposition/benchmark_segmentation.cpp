// Copyright (c) 2026 The Part_decomposition authors.
// All rights reserved.
//
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Author(s)     : The Part_decomposition authors

// Scores this package and CGAL's SDF segmentation against human segmentations, shape by shape,
// in one run (see README.md next to this file).
//
//   benchmark_segmentation DATASET_DIR [--out DIR] [--methods sdf,ours,ours1] [--shapes a,b]
//                          [--threads N] [--ablations] [--variants v1,v2] [--samples N] [--seed S]
//   benchmark_segmentation DATASET_DIR --scale SHAPE [--scale-faces 100000,300000,1000000]
//                          [--out DIR] [--threads N]

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Surface_mesh.h>
#include <CGAL/property_map.h>
#include <CGAL/subdivision_method_3.h>
#include <CGAL/IO/PLY.h>
#include <CGAL/IO/STL.h>
#include <CGAL/version.h>

#include <CGAL/Part_decomposition/IO/read_mesh.h>
#include <CGAL/Part_decomposition/decompose.h>
#include <CGAL/Part_decomposition/parameters.h>
#include <CGAL/Part_decomposition/part_composition.h>

#include "decomposition_settings.h"
#include "parts_tsv.h"
#include "sdf_peer.h"
#include "segmentation_metrics.h"

#ifdef CGAL_LINKED_WITH_TBB
#include <tbb/global_control.h>
#include <tbb/task_arena.h>
#include <tbb/version.h>
#endif

#include <sys/utsname.h>
#ifdef __GLIBC__
#include <malloc.h>
#endif

#include <algorithm>
#include <array>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <iomanip>
#include <iostream>
#include <limits>
#include <map>
#include <sstream>
#include <string>
#include <thread>
#include <vector>

namespace PD = CGAL::Part_decomposition;
namespace fs = std::filesystem;

typedef CGAL::Exact_predicates_inexact_constructions_kernel K;
typedef CGAL::Surface_mesh<K::Point_3> Mesh;
typedef Mesh::Face_index Face;

namespace {

const double NaN = std::numeric_limits<double>::quiet_NaN();

// ------------------------------------------------------------------------------------------
// Command line

struct Options
{
  std::string dataset;
  std::string out = "benchmark_out";
  std::vector<std::string> methods = {"sdf", "ours"};
  std::vector<std::string> shapes;
  std::vector<std::string> variants; // ablation variants; empty with --ablations = all
  bool ablations = false;
  bool levels = false; // --levels: mIoU of every level of the hierarchy (with ours_k)
  int threads = 0; // 0: all hardware threads
  std::size_t samples = 10000;
  unsigned seed = 0;
  std::string scale_shape; // --scale: the scale run on this shape instead of the dataset run
  std::vector<double> scale_faces = {1e5, 3e5, 1e6};
  std::string command_line;
};

bool contains(const std::vector<std::string>& v, const std::string& x)
{
  return std::find(v.begin(), v.end(), x) != v.end();
}

// In run order: "ours" before "ours1", whose labels it checks. "_k": told the shape's part count.
const std::vector<std::string>& all_methods()
{
  static const std::vector<std::string> m = {"sdf", "sdf_k", "ours", "ours_k", "ours1"};
  return m;
}

void usage()
{
  std::cerr << "usage: benchmark_segmentation DATASET_DIR [--out DIR] [--methods sdf,sdf_k,ours,ours_k,ours1] [--levels] [--shapes a,b]\n"
               "                              [--threads N] [--ablations] [--variants v1,v2]\n"
               "                              [--samples N] [--seed S]\n"
               "       benchmark_segmentation DATASET_DIR --scale SHAPE [--scale-faces 100000,300000,1000000]\n"
               "                              [--out DIR] [--threads N]\n"
               "DATASET_DIR holds manifest.tsv (columns shape, category, ...), NAME.off|obj|ply|stl and\n"
               "NAME_k.seg (one label per face, file order). --variants implies --ablations.\n"
               "Methods: sdf (CGAL's SDF segmentation), ours (Hi-TOPS with --threads threads), ours1 (Hi-TOPS\n"
               "on one thread, reading included, labels compared with ours); sdf_k and ours_k are told the\n"
               "shape's part count k (the lower median of its human segmentations' counts). --levels adds\n"
               "ours_k and scores every level of its hierarchy (levels.md, levels.tsv).\n";
}

bool parse(int argc, char** argv, Options& o)
{
  for(int i = 0; i < argc; ++i) o.command_line += (i ? " " : "") + std::string(argv[i]);
  for(int i = 1; i < argc; ++i)
  {
    const std::string a = argv[i];
    auto value = [&](std::string& v) {
      if(i + 1 >= argc) return false;
      v = argv[++i];
      return true;
    };
    std::string v;
    if(a == "--out") { if(!value(o.out)) return false; }
    else if(a == "--methods") { if(!value(v)) return false; o.methods = pd_benchmark::split(v, ','); }
    else if(a == "--scale") { if(!value(o.scale_shape)) return false; }
    else if(a == "--scale-faces")
    {
      if(!value(v)) return false;
      o.scale_faces.clear();
      for(const std::string& x : pd_benchmark::split(v, ',')) o.scale_faces.push_back(std::atof(x.c_str()));
      for(double x : o.scale_faces)
        if(!(x >= 1.)) return false;
    }
    else if(a == "--shapes") { if(!value(v)) return false; o.shapes = pd_benchmark::split(v, ','); }
    else if(a == "--variants") { if(!value(v)) return false; o.variants = pd_benchmark::split(v, ','); o.ablations = true; }
    else if(a == "--threads") { if(!value(v)) return false; o.threads = std::atoi(v.c_str()); }
    else if(a == "--samples") { if(!value(v)) return false; o.samples = std::strtoull(v.c_str(), nullptr, 10); }
    else if(a == "--seed") { if(!value(v)) return false; o.seed = unsigned(std::strtoul(v.c_str(), nullptr, 10)); }
    else if(a == "--ablations") o.ablations = true;
    else if(a == "--levels") o.levels = true;
    else if(a == "-h" || a == "--help") return false;
    else if(!a.empty() && a[0] == '-') { std::cerr << "unknown option " << a << "\n"; return false; }
    else if(o.dataset.empty()) o.dataset = a;
    else return false;
  }
  for(const std::string& m : o.methods)
    if(!contains(all_methods(), m)) { std::cerr << "unknown method " << m << "\n"; return false; }
  if(o.levels && !contains(o.methods, "ours_k")) o.methods.push_back("ours_k");
  return !o.dataset.empty() && o.samples > 0;
}

// ------------------------------------------------------------------------------------------
// Dataset

struct Shape_entry
{
  std::string name, category;
  long manifest_faces = -1;
  fs::path mesh;
  std::vector<fs::path> ground_truths; // NAME_k.seg in k order (or NAME.seg)
  fs::path parts;                      // NAME.parts.tsv, the true primitives, if any
};

std::vector<Shape_entry> read_dataset(const Options& o, std::string& error)
{
  std::vector<Shape_entry> shapes;
  const fs::path dir(o.dataset);
  std::ifstream in(dir / "manifest.tsv");
  if(!in) { error = "cannot open " + (dir / "manifest.tsv").string(); return shapes; }
  std::string line;
  std::getline(in, line);
  const std::vector<std::string> header = pd_benchmark::split(line, '\t');
  auto column = [&](const std::string& name) {
    return int(std::find(header.begin(), header.end(), name) - header.begin());
  };
  const int c_shape = column("shape"), c_category = column("category"), c_faces = column("faces");
  if(c_shape >= int(header.size())) { error = "manifest.tsv has no 'shape' column"; return shapes; }

  // NAME_k.seg, or NAME.seg alone
  std::map<std::string, std::map<long, fs::path> > seg;
  for(const fs::directory_entry& e : fs::directory_iterator(dir))
  {
    if(e.path().extension() != ".seg") continue;
    const std::string stem = e.path().stem().string();
    seg[stem][-1] = e.path();
    const std::size_t u = stem.rfind('_');
    if(u == std::string::npos || u + 1 == stem.size()) continue;
    const std::string k = stem.substr(u + 1);
    if(std::all_of(k.begin(), k.end(), [](char c) { return c >= '0' && c <= '9'; }))
      seg[stem.substr(0, u)][std::atol(k.c_str())] = e.path();
  }

  while(std::getline(in, line))
  {
    if(!line.empty() && line.back() == '\r') line.pop_back();
    if(line.empty()) continue;
    std::vector<std::string> f;
    std::string item;
    std::istringstream ls(line);
    while(std::getline(ls, item, '\t')) f.push_back(item);
    if(c_shape >= int(f.size())) continue;
    Shape_entry s;
    s.name = f[c_shape];
    if(!o.shapes.empty() && !contains(o.shapes, s.name)) continue;
    s.category = c_category < int(f.size()) ? f[c_category] : "-";
    if(c_faces < int(f.size())) s.manifest_faces = std::atol(f[c_faces].c_str());
    for(const char* ext : {".off", ".obj", ".ply", ".stl"})
      if(fs::exists(dir / (s.name + ext))) { s.mesh = dir / (s.name + ext); break; }
    if(fs::exists(dir / (s.name + ".parts.tsv"))) s.parts = dir / (s.name + ".parts.tsv");
    auto it = seg.find(s.name);
    if(it != seg.end())
    {
      for(const auto& kp : it->second)
        if(kp.first >= 0) s.ground_truths.push_back(kp.second);
      if(s.ground_truths.empty()) s.ground_truths.push_back(it->second.begin()->second);
    }
    shapes.push_back(s);
  }
  return shapes;
}

bool read_labels(const fs::path& p, std::vector<long>& labels)
{
  labels.clear();
  std::ifstream in(p);
  if(!in) return false;
  long v;
  while(in >> v) labels.push_back(v);
  return in.eof();
}

// ------------------------------------------------------------------------------------------
// Measurements

double seconds_since(std::chrono::steady_clock::time_point t0)
{
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
}

// VmHWM (peak resident set) or VmRSS of this process, in MB.
double status_mb(const std::string& key)
{
  std::ifstream in("/proc/self/status");
  std::string line;
  while(std::getline(in, line))
    if(line.compare(0, key.size(), key) == 0)
      return std::atof(line.c_str() + key.size()) / 1024.;
  return NaN;
}

// Writing "5" to clear_refs resets VmHWM to the current RSS (Linux >= 4.0).
bool reset_peak_memory()
{
  std::ofstream f("/proc/self/clear_refs");
  if(!f) return false;
  f << "5";
  f.flush();
  return bool(f);
}


// ------------------------------------------------------------------------------------------
// Ablation variants (paper Tables 3 and 4); every one passes all its settings explicitly.

struct Variant : Part_decomposition_tools::Decomposition_settings
{
  std::string id;
};

// The paper's settings where this implementation departs from it: the curvature of every vertex,
// r_fit = min(r, 32), no exterior-band samples, the plain ROI ball, no exclusion balls, scipy's
// default budget of 100 evaluations per parameter, no early end of a stage, coverage 0.95, no
// patch-size cap (a split size of the whole mesh), no thin-sheet merge.
constexpr int paper_fitting_resolution_cap = 32;
constexpr int paper_solver_evaluations = 100 * 11;
constexpr double paper_coverage = 0.95;

void make_paper_literal(Variant& v)
{
  v.fitting_resolution_cap = paper_fitting_resolution_cap;
  v.method_variant.use_exterior_band_samples = v.method_variant.use_reachable_regions = v.method_variant.use_seed_exclusion = v.method_variant.merge_thin_sheets = false;
  v.method_variant.use_concave_curvature = false;
  v.cue_weights = {1., 1., 1., 1.};
  v.maximum_solver_evaluations = paper_solver_evaluations;
  v.maximum_rejections_in_a_row = 0;
  v.coverage_target = paper_coverage;
  v.patch_split_size = 1.;
}

std::vector<Variant> all_variants()
{
  std::vector<Variant> v;
  auto add = [&](const std::string& id) { v.push_back(Variant()); v.back().id = id; return &v.back(); };
  add("full");
  add("no_body")->method_variant.use_body_seeds = false;
  add("no_freeze")->method_variant.use_freeze_zone = false;
  add("alpha05")->freeze_ratio = 0.05;
  add("alpha25")->freeze_ratio = 0.25;
  add("alpha10")->freeze_ratio = 0.10;
  add("alpha20")->freeze_ratio = 0.20;
  add("curvature_mean_only")->cue_weights = {1., 0., 0., 0.};
  add("no_curvature_gradient")->cue_weights = {1., 1., 0., 0.};
  add("no_curvature_deviation")->cue_weights = {1., 0., 1., 0.};
  add("percentile_99")->curvature_percentile = 99.;
  add("percentile_99_9")->curvature_percentile = 99.9;
  add("surface_volume_2")->minimum_surface_volume = 2.;
  add("flow_tolerance_1")->flow_zone_tolerance = 1.;
  add("flow_tolerance_3")->flow_zone_tolerance = 3.;
  add("body_seed_1")->body_seed_threshold = 1.;
  add("body_seed_2")->body_seed_threshold = 2.;
  add("no_curvature")->cue_weights = {0., 0., 0., 1.};
  add("paper_normal")->cue_weights = {1., 1., 1., 1.}; // the normal deviation, convex edges too
  add("no_density")->method_variant.use_density = false;
  add("paper_curvature")->method_variant.use_concave_curvature = false; // |H|/2 at every vertex, convex ones too
  add("no_tsdf")->method_variant.use_tsdf_guidance = false;
  // the inside of every volume stage: the paper's exterior flood fill, the hierarchical winding number
  add("sign_flood")->tsdf_sign_method = PD::Tsdf_sign_method::FLOOD_FILL;
  add("sign_winding")->tsdf_sign_method = PD::Tsdf_sign_method::WINDING_NUMBER;
  for(int r : {16, 32, 64})
  {
    const std::string s = std::to_string(r);
    add("r" + s)->voxel_resolutions = {r};
    Variant* a = add("r" + s + "_no_freeze");
    a->voxel_resolutions = {r};
    a->method_variant.use_freeze_zone = false;
    Variant* b = add("r" + s + "_no_tsdf");
    b->voxel_resolutions = {r};
    b->method_variant.use_tsdf_guidance = false;
    Variant* c = add("r" + s + "_paper_fit_resolution");
    c->voxel_resolutions = {r};
    c->fitting_resolution_cap = paper_fitting_resolution_cap;
  }
  // one departure from the paper undone at a time, then all of them
  add("paper_fit_resolution")->fitting_resolution_cap = paper_fitting_resolution_cap;
  add("no_exterior_band")->method_variant.use_exterior_band_samples = false;
  add("no_reachable_regions")->method_variant.use_reachable_regions = false;
  add("no_seed_exclusion")->method_variant.use_seed_exclusion = false;
  add("paper_evaluations")->maximum_solver_evaluations = paper_solver_evaluations;
  add("no_rejection_stop")->maximum_rejections_in_a_row = 0;
  add("paper_coverage")->coverage_target = paper_coverage;
  add("no_patch_split")->patch_split_size = 1.;
  add("no_sheet_merge")->method_variant.merge_thin_sheets = false;
  make_paper_literal(*add("paper_literal"));
  // the evidence of pieces and creases, and its two thresholds
  add("no_pieces")->method_variant.use_pieces = false;
  for(double a : {45., 75.}) add("crease" + std::to_string(int(a)))->crease_angle = a;
  for(double a : {0.002, 0.01}) add("min_part_area_" + std::to_string(int(a * 1000)))->minimum_part_area = a;
  // the residual patches, off by default, at three tolerances
  for(double t : {1., 2., 4.})
  {
    Variant* r = add("residual_" + std::to_string(int(t)));
    r->method_variant.keep_residual_patches = true;
    r->residual_tolerance = t;
  }
  // the final labelling: the patch vote (0) and the weight of the boundary cost
  for(double s : {0., 0.3, 1., 3., 10.})
    add("smooth_" + std::to_string(int(s * 10)))->boundary_smoothness = s;
  // finer fitting: the last stage at 64, or the whole hierarchy one level finer
  add("fit64")->fitting_resolution_cap = 64;
  add("r128")->voxel_resolutions = {32, 64, 128};
  // which of the finer distance field and the finer fitting grid separates thin parts
  Variant* fine_field = add("r128_fit32");
  fine_field->voxel_resolutions = {32, 64, 128};
  fine_field->fitting_resolution_cap = 32;
  add("r32_64")->voxel_resolutions = {32, 64}; // the first fitting stage at 32, the field at 64
  // the paper's coarse stages with one finer level on top
  Variant* four_levels = add("r16_128_fit32");
  four_levels->voxel_resolutions = {16, 32, 64, 128};
  four_levels->fitting_resolution_cap = 32;
  // r128_fit32 with the thresholds of the finest grid kept at their lengths at 64
  Variant* lengths = add("r128_abs");
  lengths->voxel_resolutions = {32, 64, 128};
  lengths->fitting_resolution_cap = 32;
  lengths->tsdf_truncation *= 2.;
  lengths->vote_temperature *= 2.;
  lengths->boundary_smoothness *= 2.;
  lengths->residual_tolerance *= 2.;
  // the grid: the paper's dense grid of the finest voxel resolution, no leaf finer than it, leaves to 256
  add("uniform")->method_variant.adaptive_grid = false;
  add("grid64")->grid_resolution = 64;
  add("grid256")->grid_resolution = 256;
  for(double t : {4., 6.}) add("trunc" + std::to_string(int(t)))->tsdf_truncation = t;
  // the parts of the assignment, without the hierarchy's merges below maximum_merge_cost
  add("no_cost_merge")->maximum_merge_cost = 0.;
  // the threshold of the hierarchy's merges, in thousandths of the bounding box volume
  for(int t : {1, 2, 5, 8, 12}) add("merge_cost_" + std::to_string(t))->maximum_merge_cost = t / 1000.;
  // primitives that one superquadric explains: kept apart, or merged from three IoU levels
  add("no_primitive_merge")->method_variant.merge_primitives = false;
  for(double t : {0.5, 0.7, 0.8}) add("merge_iou_" + std::to_string(int(t * 100)))->minimum_merge_iou = t;
  for(double t : {0.7, 0.8, 0.9})
  {
    Variant* v = add("r128_merge_iou_" + std::to_string(int(t * 100)));
    v->voxel_resolutions = {32, 64, 128};
    v->minimum_merge_iou = t;
  }
  Variant* r128_apart = add("r128_no_primitive_merge");
  r128_apart->voxel_resolutions = {32, 64, 128};
  r128_apart->method_variant.merge_primitives = false;
  Variant* before = add("vote_no_primitive_merge"); // the final labelling of issue 16
  before->boundary_smoothness = 0.;
  before->method_variant.merge_primitives = false;
  Variant* vote_no_split = add("smooth_0_no_patch_split");
  vote_no_split->boundary_smoothness = 0.;
  vote_no_split->patch_split_size = 1.;
  return v;
}

// ------------------------------------------------------------------------------------------
// One row of results.tsv

struct Row
{
  std::string shape, category, method;
  std::size_t faces = 0, n_gt = 0, parts = 0;
  bool ok = false;
  std::string error, note;
  double miou = NaN, ri = NaN, voi = NaN, sc = NaN, gt_parts = NaN;
  double t_read = NaN, t_prior = NaN, t_tsdf = NaN, t_fitting = NaN, t_overseg = NaN, t_assign = NaN;
  double t_sdf = NaN, t_sdf_segmentation = NaN, t_method = NaN;
  double peak_mb = NaN, rss_before_mb = NaN;
  std::string same_labels; // ours1: "yes" or "no" against ours on the same shape
  std::size_t k = 0;       // the oracle count: lower median of the human part counts
  std::size_t leaves = 0;  // ours_k: the leaves of the hierarchy
  double t_hierarchy = NaN;
  double cd = NaN;          // cut discrepancy, mean over the ground truths where it is defined
  // true primitives found (NAME.parts.tsv); -1: not applicable (no parts file, no primitives)
  long found = -1, true_primitives = -1, thin_found = -1, thin_total = -1;
  // of those, found by the true labels with each true part's faces boxed: what the surface shows
  long findable = -1, thin_findable = -1;
  double end_to_end() const { return t_read + t_method; }
};

std::string clean(std::string s)
{
  for(char& c : s)
    if(c == '\t' || c == '\n' || c == '\r') c = ' ';
  return s;
}

std::string num(double x, int digits = 4)
{
  if(std::isnan(x)) return "nan";
  std::ostringstream o;
  o << std::fixed << std::setprecision(digits) << x;
  return o.str();
}

// a count, or n/a when it does not apply (negative)
std::string count(long n) { return n < 0 ? "n/a" : std::to_string(n); }

void write_tsv_header(std::ostream& out)
{
  out << "dataset\tshape\tcategory\tfaces\tmethod\tstatus\tmIoU\tRI\tVoI\tSC\tparts\tgt_parts\tn_gt"
         "\tt_read\tt_prior\tt_tsdf\tt_fitting\tt_overseg\tt_assign\tt_sdf_values\tt_sdf_segmentation"
         "\tt_method\tt_end_to_end\tpeak_mb\trss_before_mb\tsame_labels\terror\tnote\tk\tleaves\tt_hierarchy"
         "\tCD\tfound\ttrue_primitives\tthin_found\tthin_total\tfindable\tthin_findable\n";
}

void write_tsv_row(std::ostream& out, const std::string& dataset, const Row& r)
{
  out << dataset << '\t' << r.shape << '\t' << r.category << '\t' << r.faces << '\t' << r.method << '\t'
      << (r.ok ? "ok" : "error") << '\t' << num(r.miou) << '\t' << num(r.ri) << '\t' << num(r.voi) << '\t'
      << num(r.sc) << '\t' << r.parts << '\t' << num(r.gt_parts, 2) << '\t' << r.n_gt << '\t'
      << num(r.t_read) << '\t' << num(r.t_prior) << '\t' << num(r.t_tsdf) << '\t' << num(r.t_fitting) << '\t'
      << num(r.t_overseg) << '\t' << num(r.t_assign) << '\t' << num(r.t_sdf) << '\t'
      << num(r.t_sdf_segmentation) << '\t' << num(r.t_method) << '\t' << num(r.end_to_end()) << '\t'
      << num(r.peak_mb, 1) << '\t' << num(r.rss_before_mb, 1) << '\t' << r.same_labels << '\t'
      << clean(r.error) << '\t' << clean(r.note) << '\t' << r.k << '\t' << r.leaves << '\t' << num(r.t_hierarchy)
      << '\t' << num(r.cd) << '\t' << count(r.found) << '\t' << count(r.true_primitives) << '\t'
      << count(r.thin_found) << '\t' << count(r.thin_total) << '\t' << count(r.findable) << '\t'
      << count(r.thin_findable) << '\n';
  out.flush();
}

// Scores face labels against every ground truth (sample labels precomputed) and averages.
void score(const std::vector<std::size_t>& face_labels, const std::vector<std::size_t>& samples,
           const std::vector<std::vector<long> >& gt_samples, Row& r)
{
  if(gt_samples.empty()) return;
  std::vector<std::size_t> predicted;
  predicted.reserve(samples.size());
  for(std::size_t f : samples) predicted.push_back(face_labels[f]);
  double m = 0., ri = 0., voi = 0., sc = 0.;
  for(const std::vector<long>& g : gt_samples)
  {
    const PD::Segmentation_scores s = PD::compare_segmentations(g, predicted);
    m += s.mean_iou;
    ri += s.rand_index;
    voi += s.variation_of_information;
    sc += s.segmentation_covering;
  }
  const double k = double(gt_samples.size());
  r.miou = m / k;
  r.ri = ri / k;
  r.voi = voi / k;
  r.sc = sc / k;
}


// The cut discrepancy of the face labels against each ground truth (face labels in mesh order),
// averaged over the ground truths where it is defined: NaN where only one side has cuts.
double mean_cut_discrepancy(const Mesh& mesh, const std::vector<std::size_t>& face_labels,
                            const std::vector<std::vector<long> >& gt_faces)
{
  std::vector<double> cd;
  for(const std::vector<long>& g : gt_faces)
    cd.push_back(PD::cut_discrepancy(mesh, CGAL::make_property_map(g), CGAL::make_property_map(face_labels)));
  double sum = 0.;
  std::size_t n = 0;
  for(double x : cd)
    if(!std::isnan(x)) { sum += x; ++n; }
  return n ? sum / double(n) : NaN;
}

// The true primitives found by the predicted parts: true primitive i is found if some part k has
// its superquadric's centre within i's smallest semi-axis of i's centre and more than half of
// its area labelled i in the ground truth `gt` (face labels in mesh order, labels = ids).
void score_primitives(const std::vector<pd_benchmark::True_primitive>& truth,
                      const std::vector<PD::Superquadric<K> >& predicted, const std::vector<std::size_t>& labels,
                      const std::vector<long>& gt, const std::vector<double>& face_area, Row& r)
{
  // the ground-truth label holding more than half of each part's area, or -1
  std::vector<double> area(predicted.size(), 0.);
  std::vector<std::map<long, double> > by_label(predicted.size());
  for(std::size_t f = 0; f < labels.size(); ++f)
    if(labels[f] < predicted.size())
    {
      area[labels[f]] += face_area[f];
      by_label[labels[f]][gt[f]] += face_area[f];
    }
  std::vector<long> majority(predicted.size(), -1);
  for(std::size_t k = 0; k < predicted.size(); ++k)
    for(const auto& la : by_label[k])
      if(la.second > 0.5 * area[k]) majority[k] = la.first;

  r.found = r.thin_found = r.thin_total = 0;
  r.true_primitives = long(truth.size());
  for(const pd_benchmark::True_primitive& t : truth)
  {
    const K::Point_3 c(t.center[0], t.center[1], t.center[2]);
    bool found = false;
    for(std::size_t k = 0; k < predicted.size() && !found; ++k)
      found = majority[k] == long(t.id) &&
              CGAL::squared_distance(predicted[k].center(), c) <= CGAL::square(t.smallest_semi_axis());
    r.found += found;
    r.thin_total += t.thin;
    r.thin_found += found && t.thin;
  }
}

// The predicted superquadrics in the format of NAME.parts.tsv (id = part id), to look at what
// score_primitives() matched.
void write_primitives(const fs::path& file, const std::vector<PD::Superquadric<K> >& primitives)
{
  std::vector<pd_benchmark::True_primitive> out;
  for(const PD::Superquadric<K>& q : primitives)
  {
    pd_benchmark::True_primitive p;
    p.id = out.size();
    p.center = {{q.center().x(), q.center().y(), q.center().z()}};
    p.semi_axes = q.scales();
    p.epsilon1 = q.epsilon1();
    p.epsilon2 = q.epsilon2();
    p.rotation = q.rotation();
    p.thin = pd_benchmark::is_thin(p.semi_axes);
    out.push_back(p);
  }
  fs::create_directories(file.parent_path());
  std::ofstream f(file);
  pd_benchmark::write_parts_tsv(f, out);
}

// Our method; `primitives` receives the superquadric of each part, in part order.
template <typename NP>
std::size_t run_ours(const Mesh& mesh, std::vector<std::size_t>& labels, const NP& np,
                     std::vector<PD::Superquadric<K> >* primitives = nullptr)
{
  labels.assign(num_faces(mesh), std::size_t(-1));
  std::vector<PD::Superquadric<K> > out;
  const std::size_t k = PD::decompose<CGAL::Parallel_if_available_tag>(
    mesh, CGAL::make_property_map(labels), // Surface_mesh face indices are 0..F-1 (no garbage)
    PD::parameters::combine(np, PD::parameters::primitive_output_iterator(std::back_inserter(out))));
  for(std::size_t l : labels)
    if(l >= k) throw std::runtime_error("decompose left a face without a part id in [0, K)");
  if(primitives != nullptr) *primitives = std::move(out);
  return k;
}

// The stage times of decompose() in a row.
void copy_stage_timings(const PD::Stage_timings& st, Row& r)
{
  r.t_prior = st.prior;
  r.t_tsdf = st.tsdf;
  r.t_fitting = st.fitting;
  r.t_overseg = st.over_segmentation;
  r.t_assign = st.assignment;
}

// Appends `s` to a row's note, "; "-separated.
void append_note(std::string& note, const std::string& s) { note += (note.empty() ? "" : "; ") + s; }

// The true primitives of a shape (NAME.parts.tsv, whose ids are the labels of its single ground
// truth) and the area of each face; empty without a parts file or a ground truth.
struct Shape_truth
{
  std::vector<pd_benchmark::True_primitive> primitives;
  std::vector<double> face_area; // in mesh face order
  long findable = -1, thin_findable = -1;
};

// The true primitives that the surface shows: found (score_primitives()) by the true labels, each
// true part carrying the principal-axis box of its own faces, the superquadric `decompose()` gives a
// part without a fitted one. A part whose centre lies inside its neighbours (a fin or a leg
// sunk into a body) is missed even so: no segmentation of the surface can find it.
void count_findable(const Mesh& mesh, const std::vector<long>& gt, Shape_truth& t)
{
  std::map<long, std::size_t> index; // true label -> box
  std::vector<std::vector<std::array<double, 3> > > corners;
  std::vector<std::size_t> labels;
  for(Face f : faces(mesh))
  {
    const long g = gt[std::size_t(f)];
    const auto it = index.emplace(g, corners.size()).first;
    if(it->second == corners.size()) corners.emplace_back();
    labels.push_back(it->second);
    for(auto v : vertices_around_face(halfedge(f, mesh), mesh))
      corners[it->second].push_back({{mesh.point(v).x(), mesh.point(v).y(), mesh.point(v).z()}});
  }
  std::vector<PD::Superquadric<K> > boxes;
  for(const auto& c : corners) boxes.push_back(PD::internal::bounding_superquadric<K>(c));
  Row r;
  score_primitives(t.primitives, boxes, labels, gt, t.face_area, r);
  t.findable = r.found;
  t.thin_findable = r.thin_found;
}

Shape_truth read_truth(const Shape_entry& e, const Mesh& mesh, const std::vector<std::vector<long> >& gt_faces,
                       std::string& note)
{
  Shape_truth t;
  if(e.parts.empty() || gt_faces.empty()) return t;
  std::string error;
  if(!pd_benchmark::read_parts_tsv(e.parts.string(), t.primitives, error))
  {
    append_note(note, error);
    t.primitives.clear();
    return t;
  }
  if(gt_faces.size() > 1) append_note(note, "primitives scored on the first ground truth");
  for(Face f : faces(mesh))
  {
    const auto h = halfedge(f, mesh);
    t.face_area.push_back(std::sqrt(CGAL::squared_area(mesh.point(source(h, mesh)), mesh.point(target(h, mesh)),
                                                       mesh.point(target(next(h, mesh), mesh)))));
  }
  count_findable(mesh, gt_faces.front(), t);
  return t;
}

// ------------------------------------------------------------------------------------------
// Summaries

double median(std::vector<double> v)
{
  v.erase(std::remove_if(v.begin(), v.end(), [](double x) { return std::isnan(x); }), v.end());
  if(v.empty()) return NaN;
  std::sort(v.begin(), v.end());
  const std::size_t n = v.size();
  return n % 2 ? v[n / 2] : 0.5 * (v[n / 2 - 1] + v[n / 2]);
}

double mean(const std::vector<double>& v)
{
  double s = 0.;
  std::size_t n = 0;
  for(double x : v)
    if(!std::isnan(x)) { s += x; ++n; }
  return n ? s / double(n) : NaN;
}

template <typename F>
std::vector<double> field(const std::vector<const Row*>& rows, F f)
{
  std::vector<double> v;
  for(const Row* r : rows) v.push_back(f(*r));
  return v;
}

struct Aggregate
{
  std::size_t n_ok = 0, n_all = 0;
  double miou = NaN, ri = NaN, voi = NaN, sc = NaN, parts = NaN, gt_parts = NaN;
  double t_median = NaN, t_mean = NaN, peak_median = NaN, end_to_end_median = NaN;
  double cd = NaN; // mean over the shapes where it is defined
  std::size_t cd_shapes = 0;
  // true primitives found, summed over the shapes with primitives; found < 0: not applicable
  long found = -1, true_primitives = 0, thin_found = -1, thin_total = 0;
  long findable = 0, thin_findable = 0;
};

// "mean (shapes where defined)"
std::string cd_cell(double cd, std::size_t shapes) { return num(cd, 3) + " (" + std::to_string(shapes) + ")"; }

// "percent (found/total)", or n/a
std::string percent(long found, long total)
{
  if(found < 0 || total <= 0) return "n/a";
  return num(100. * double(found) / double(total), 1) + " (" + std::to_string(found) + "/" + std::to_string(total) + ")";
}

Aggregate aggregate(const std::vector<Row>& rows, const std::string& method, const std::string& category = "")
{
  std::vector<const Row*> ok;
  Aggregate a;
  for(const Row& r : rows)
  {
    if(r.method != method || (!category.empty() && r.category != category)) continue;
    ++a.n_all;
    if(r.ok) ok.push_back(&r);
  }
  a.n_ok = ok.size();
  a.miou = mean(field(ok, [](const Row& r) { return r.miou; }));
  a.ri = mean(field(ok, [](const Row& r) { return r.ri; }));
  a.voi = mean(field(ok, [](const Row& r) { return r.voi; }));
  a.sc = mean(field(ok, [](const Row& r) { return r.sc; }));
  a.parts = mean(field(ok, [](const Row& r) { return double(r.parts); }));
  a.gt_parts = mean(field(ok, [](const Row& r) { return r.gt_parts; }));
  a.t_median = median(field(ok, [](const Row& r) { return r.t_method; }));
  a.t_mean = mean(field(ok, [](const Row& r) { return r.t_method; }));
  a.peak_median = median(field(ok, [](const Row& r) { return r.peak_mb; }));
  a.end_to_end_median = median(field(ok, [](const Row& r) { return r.end_to_end(); }));
  a.cd = mean(field(ok, [](const Row& r) { return r.cd; }));
  for(const Row* r : ok) a.cd_shapes += std::isnan(r->cd) ? 0 : 1;
  for(const Row* r : ok)
    if(r->found >= 0)
    {
      a.found = (std::max)(a.found, 0L) + r->found;
      a.thin_found = (std::max)(a.thin_found, 0L) + r->thin_found;
      a.true_primitives += r->true_primitives;
      a.thin_total += r->thin_total;
      a.findable += r->findable;
      a.thin_findable += r->thin_findable;
    }
  return a;
}

std::string method_label(const std::string& m)
{
  if(m == "sdf") return "CGAL SDF (defaults)";
  if(m == "ours") return "Hi-TOPS (ours)";
  if(m == "ours1") return "Hi-TOPS (ours), 1 thread";
  if(m == "sdf_k") return "CGAL SDF, k clusters (told the count)";
  if(m == "ours_k") return "Hi-TOPS (ours), k parts (told the count)";
  return m;
}

std::string read_first(const std::string& file, const std::string& key)
{
  std::ifstream in(file);
  std::string line;
  while(std::getline(in, line))
    if(line.compare(0, key.size(), key) == 0)
    {
      std::size_t c = line.find(':');
      std::string v = c == std::string::npos ? line : line.substr(c + 1);
      v.erase(0, v.find_first_not_of(" \t"));
      return v;
    }
  return "?";
}

std::string load_average()
{
  std::ifstream in("/proc/loadavg");
  double a = NaN, b = NaN, c = NaN;
  in >> a >> b >> c;
  return num(a, 2) + " " + num(b, 2) + " " + num(c, 2);
}

std::string machine_description(int threads)
{
  std::ostringstream o;
  struct utsname u;
  const bool has_uname = uname(&u) == 0;
  o << "- CPU: " << read_first("/proc/cpuinfo", "model name") << ", "
    << std::thread::hardware_concurrency() << " hardware threads; " << threads << " thread(s) used\n"
    << "- Memory: " << num(std::atof(read_first("/proc/meminfo", "MemTotal").c_str()) / 1048576., 1) << " GiB\n"
    << "- Load average (1, 5, 15 min) when this file was written: " << load_average()
    << " (other processes share the cores: seconds are only comparable within one run)\n"
    << "- OS: " << (has_uname ? std::string(u.sysname) + " " + u.release + " " + u.machine : "?") << "\n"
    << "- Compiler: "
#if defined(__clang__)
    << "clang "
#elif defined(__GNUC__)
    << "GCC "
#endif
    << __VERSION__ << ", CGAL " << CGAL_VERSION_STR
#ifdef CGAL_LINKED_WITH_TBB
    << ", oneTBB " << TBB_VERSION_MAJOR << "." << TBB_VERSION_MINOR
#else
    << ", no TBB"
#endif
#ifdef NDEBUG
    << ", NDEBUG (Release)"
#else
    << ", assertions on (not Release)"
#endif
    << "\n";
  return o.str();
}

// The methods present in `rows`, in run order, and the found columns when the data set has true
// primitives.
struct Summary_columns
{
  std::vector<std::string> methods;
  bool with_primitives = false;

  explicit Summary_columns(const std::vector<Row>& rows)
  {
    for(const std::string& m : all_methods())
      for(const Row& r : rows)
        if(r.method == m) { methods.push_back(m); break; }
    for(const Row& r : rows) with_primitives = with_primitives || r.true_primitives > 0;
  }
  std::string found_head() const { return with_primitives ? " found % ↑ | thin found % ↑ |" : ""; }
  std::string found_rule() const { return with_primitives ? "---|---|" : ""; }
  std::string found_cells(const Aggregate& a) const
  {
    return with_primitives ? " " + percent(a.found, a.true_primitives) + " | " + percent(a.thin_found, a.thin_total) + " |"
                           : std::string();
  }
  // method, shapes ok, mIoU, RI, VoI, CD, SC and the found columns
  std::string quality_cells(const std::string& m, const Aggregate& a) const
  {
    return " " + method_label(m) + " | " + std::to_string(a.n_ok) + "/" + std::to_string(a.n_all) + " | " +
           num(a.miou, 3) + " | " + num(a.ri, 3) + " | " + num(a.voi, 3) + " | " + cd_cell(a.cd, a.cd_shapes) + " | " +
           num(a.sc, 3) + " |" + found_cells(a);
  }
};

void write_protocol(std::ostream& out, const Options& o, const std::string& dataset, int threads)
{
  out << "# Segmentation benchmark: " << dataset << "\n\n"
      << "Command: `" << o.command_line << "`\n\n" << machine_description(threads) << "\n"
      << "Protocol (paper, Appendix A): " << o.samples << " points per shape drawn on the surface with "
      << "probability proportional to area (seed " << o.seed << "), each labelled by its face; "
      << "class-agnostic mIoU (many-to-one best match per ground-truth part), Rand index, variation "
      << "of information (natural log, nats) and segmentation covering, averaged over every human "
      << "segmentation of a shape, then over shapes. \"s\" columns exclude reading the mesh, "
      << "\"end-to-end s\" adds it (file to labels; the same reader for every method); peak memory is "
      << "the process's VmHWM during the method. CD: the cut discrepancy (Chen et al. 2009, "
      << "`cut_discrepancy()`: mean distance from the cuts of one segmentation to those of the other, both "
      << "ways, over the mean radius; Euclidean, not the Princeton benchmark's geodesic distance), averaged "
      << "over the ground truths where it is defined (both or neither have cuts), then over the shapes where "
      << "it is (their number in parentheses): a single predicted part against a ground truth of several parts "
      << "leaves it undefined.\n\n";
}

// What the true labels themselves reach, each true part boxed (count_findable()).
std::string findable_sentence(const Summary_columns& c, const std::vector<Row>& rows)
{
  for(const std::string& m : c.methods)
  {
    const Aggregate a = aggregate(rows, m);
    if(a.found < 0) continue;
    auto share = [](long k, long n) {
      return num(100. * double(k) / double((std::max)(n, 1L)), 1) + "% (" + std::to_string(k) + " of " + std::to_string(n) + ")";
    };
    return "The true labels, each true part with the principal-axis box of its faces, find " +
           share(a.findable, a.true_primitives) + ", thin " + share(a.thin_findable, a.thin_total) +
           ": the others have their centre sunk in a neighbouring part, where the surface does not show it.";
  }
  return "";
}

void write_quality_tables(std::ostream& out, const Summary_columns& c, const std::vector<Row>& rows,
                          const std::vector<std::string>& categories)
{
  if(c.with_primitives)
    out << "Primitives (NAME.parts.tsv): a true primitive is found if some predicted part has its "
        << "superquadric's centre within the primitive's smallest semi-axis of its centre and more than half "
        << "of its area labelled with it in NAME.seg; thin: smallest semi-axis at most 1/8 of the largest. "
        << "Percentages pool the primitives of the shapes; n/a for methods without primitives (SDF). "
        << findable_sentence(c, rows) << "\n\n";
  out << "## Overall\n\n"
      << "| Method | shapes ok | mIoU ↑ | RI ↑ | VoI ↓ | CD ↓ | SC ↑ |" << c.found_head() << " parts | GT parts | median s | mean s "
         "| median end-to-end s | median peak MB |\n"
      << "|---|---|---|---|---|---|---|" << c.found_rule() << "---|---|---|---|---|---|\n";
  for(const std::string& m : c.methods)
  {
    const Aggregate a = aggregate(rows, m);
    out << "|" << c.quality_cells(m, a) << " " << num(a.parts, 1) << " | " << num(a.gt_parts, 1) << " | "
        << num(a.t_median, 3) << " | " << num(a.t_mean, 3) << " | " << num(a.end_to_end_median, 3) << " | "
        << num(a.peak_median, 0) << " |\n";
  }
  out << "\n## Per category\n\n"
      << "| Category | Method | shapes ok | mIoU ↑ | RI ↑ | VoI ↓ | CD ↓ | SC ↑ |" << c.found_head() << " parts | GT parts | median s |\n"
      << "|---|---|---|---|---|---|---|---|" << c.found_rule() << "---|---|---|\n";
  for(const std::string& category : categories)
    for(const std::string& m : c.methods)
    {
      const Aggregate a = aggregate(rows, m, category);
      if(a.n_all == 0) continue;
      out << "| " << category << " |" << c.quality_cells(m, a) << " " << num(a.parts, 1) << " | " << num(a.gt_parts, 1)
          << " | " << num(a.t_median, 3) << " |\n";
    }
}

// Halves for tuning and checking: the shapes in name order, alternately in half A and half B.
void write_halves(std::ostream& out, const Summary_columns& c, const std::vector<Row>& rows)
{
  std::vector<std::string> names;
  for(const Row& r : rows) names.push_back(r.shape);
  std::sort(names.begin(), names.end());
  names.erase(std::unique(names.begin(), names.end()), names.end());
  std::vector<Row> halves(rows);
  for(Row& r : halves)
    r.category = (std::lower_bound(names.begin(), names.end(), r.shape) - names.begin()) % 2 ? "B" : "A";
  out << "\n## Halves (shapes in name order, alternately A and B)\n\n"
      << "| Half | Method | shapes ok | mIoU ↑ | RI ↑ | VoI ↓ | CD ↓ | SC ↑ |" << c.found_head() << " parts | median parts | median s |\n"
      << "|---|---|---|---|---|---|---|---|" << c.found_rule() << "---|---|---|\n";
  for(const std::string h : {"A", "B"})
    for(const std::string& m : c.methods)
    {
      const Aggregate a = aggregate(halves, m, h);
      std::vector<double> parts;
      for(const Row& r : halves)
        if(r.ok && r.method == m && r.category == h) parts.push_back(double(r.parts));
      out << "| " << h << " |" << c.quality_cells(m, a) << " " << num(a.parts, 1) << " | " << num(median(parts), 1)
          << " | " << num(a.t_median, 3) << " |\n";
    }
}

double geometric_mean(const std::vector<double>& v)
{
  double log_sum = 0.;
  for(double x : v) log_sum += std::log(x);
  return std::exp(log_sum / double(v.size()));
}

// The successful rows of one method, by shape.
std::map<std::string, const Row*> rows_by_shape(const std::vector<Row>& rows, const std::string& method)
{
  std::map<std::string, const Row*> by_shape;
  for(const Row& r : rows)
    if(r.ok && r.method == method) by_shape[r.shape] = &r;
  return by_shape;
}

// Pair by pair: the ratio of each shape's times, then their median.
void write_time_ratios(std::ostream& out, const std::vector<Row>& rows)
{
  const std::map<std::string, const Row*> sdf = rows_by_shape(rows, "sdf");
  std::vector<double> ratios, e2e_ratios;
  std::size_t at_most_half = 0;
  std::ostringstream table;
  for(const Row& r : rows)
  {
    if(r.method != "ours" || !r.ok || !sdf.count(r.shape)) continue;
    const Row& s = *sdf.at(r.shape);
    const double ratio = r.t_method / s.t_method, e2e = r.end_to_end() / s.end_to_end();
    ratios.push_back(ratio);
    e2e_ratios.push_back(e2e);
    if(e2e <= 0.5) ++at_most_half;
    table << "| " << r.shape << " | " << num(r.end_to_end(), 3) << " | " << num(s.end_to_end(), 3) << " | "
          << num(e2e, 3) << " | " << num(ratio, 3) << " | " << num(r.miou, 3) << " | " << num(s.miou, 3) << " |\n";
  }
  out << "\n## Time ratio ours / SDF, shape by shape\n\n";
  if(ratios.empty()) { out << "No shape where both methods succeeded.\n"; return; }
  out << "End to end (read + method): median ratio " << num(median(e2e_ratios), 3) << ", geometric mean "
      << num(geometric_mean(e2e_ratios), 3) << ", largest " << num(*std::max_element(e2e_ratios.begin(), e2e_ratios.end()), 3)
      << "; at most 0.5 on " << at_most_half << "/" << e2e_ratios.size() << " shapes. Method only: median "
      << num(median(ratios), 3) << ", geometric mean " << num(geometric_mean(ratios), 3) << ".\n\n"
      << "| Shape | ours end-to-end s | SDF end-to-end s | ours/SDF end-to-end | ours/SDF method | ours mIoU "
         "| SDF mIoU |\n|---|---|---|---|---|---|---|\n"
      << table.str();
}

// The same shapes on one thread: speed-up and bit-identical labels.
void write_one_thread(std::ostream& out, const std::vector<Row>& rows, int threads)
{
  const std::map<std::string, const Row*> ours = rows_by_shape(rows, "ours");
  std::vector<double> speedups, method_speedups;
  std::size_t same = 0, compared = 0;
  std::ostringstream t;
  for(const Row& r : rows)
  {
    if(r.method != "ours1" || !r.ok || !ours.count(r.shape)) continue;
    const Row& n = *ours.at(r.shape);
    speedups.push_back(r.end_to_end() / n.end_to_end());
    method_speedups.push_back(r.t_method / n.t_method);
    if(!r.same_labels.empty()) ++compared;
    if(r.same_labels == "yes") ++same;
    t << "| " << r.shape << " | " << r.faces << " | " << num(r.end_to_end(), 3) << " | " << num(n.end_to_end(), 3)
      << " | " << num(speedups.back(), 3) << " | " << num(method_speedups.back(), 3) << " | "
      << (r.same_labels.empty() ? "-" : r.same_labels) << " |\n";
  }
  out << "\n## One thread against " << threads << ", shape by shape\n\n";
  if(speedups.empty()) { out << "No shape where both runs succeeded.\n"; return; }
  out << "Speed-up end to end (1-thread time / " << threads << "-thread time, read + method): median "
      << num(median(speedups), 3) << ", geometric mean " << num(geometric_mean(speedups), 3)
      << "; method only: median " << num(median(method_speedups), 3) << ". Labels bit-identical on "
      << same << "/" << compared << " shapes.\n\n"
      << "| Shape | faces | 1 thread end-to-end s | " << threads << " threads end-to-end s | speed-up | "
      << "speed-up method only | same labels |\n|---|---|---|---|---|---|---|\n"
      << t.str();
}

void write_stage_medians(std::ostream& out, const std::vector<Row>& rows, int threads)
{
  const std::map<std::string, const Row*> ours = rows_by_shape(rows, "ours"), ours1 = rows_by_shape(rows, "ours1"),
                                          sdf = rows_by_shape(rows, "sdf");
  auto values = [](const std::map<std::string, const Row*>& m) {
    std::vector<const Row*> ok;
    for(const auto& e : m) ok.push_back(e.second);
    return ok;
  };
  if(!ours.empty() || !ours1.empty())
  {
    out << "\n## Our stages, median seconds\n\n"
        << "With two threads or more, stages that run at the same time overlap and their sum exceeds the "
           "total: the prior followed by the fitting zones, the distance field and the over-segmentation, then "
           "the superquadric fits next to what is left of the over-segmentation. \"fitting\" includes the "
           "zones.\n\n"
        << "| run | read | prior | TSDF | fitting | over-segmentation | assignment | method | end-to-end |\n"
        << "|---|---|---|---|---|---|---|---|---|\n";
    for(const auto* m : {&ours, &ours1})
    {
      if(m->empty()) continue;
      const std::vector<const Row*> ok = values(*m);
      out << "| " << (m == &ours ? std::to_string(threads) + " thread(s)" : std::string("1 thread")) << " | "
          << num(median(field(ok, [](const Row& r) { return r.t_read; })), 3) << " | "
          << num(median(field(ok, [](const Row& r) { return r.t_prior; })), 3) << " | "
          << num(median(field(ok, [](const Row& r) { return r.t_tsdf; })), 3) << " | "
          << num(median(field(ok, [](const Row& r) { return r.t_fitting; })), 3) << " | "
          << num(median(field(ok, [](const Row& r) { return r.t_overseg; })), 3) << " | "
          << num(median(field(ok, [](const Row& r) { return r.t_assign; })), 3) << " | "
          << num(median(field(ok, [](const Row& r) { return r.t_method; })), 3) << " | "
          << num(median(field(ok, [](const Row& r) { return r.end_to_end(); })), 3) << " |\n";
    }
  }
  if(sdf.empty()) return;
  const std::vector<const Row*> ok = values(sdf);
  out << "\nSDF peer, median seconds: sdf_values " << num(median(field(ok, [](const Row& r) { return r.t_sdf; })), 3)
      << ", segmentation_from_sdf_values "
      << num(median(field(ok, [](const Row& r) { return r.t_sdf_segmentation; })), 3) << ".\n";
}

void write_errors(std::ostream& out, const std::vector<Row>& rows)
{
  out << "\n## Errors and guards\n\n";
  bool any = false;
  for(const Row& r : rows)
  {
    if(!contains(all_methods(), r.method)) continue;
    if(!r.ok) { out << "- " << r.shape << " / " << r.method << ": error: " << clean(r.error) << "\n"; any = true; }
    if(!r.note.empty()) { out << "- " << r.shape << " / " << r.method << ": " << clean(r.note) << "\n"; any = true; }
  }
  if(!any) out << "None: no error, no guard fired.\n";
}

void write_summary(const Options& o, const std::string& dataset, const std::vector<Row>& rows,
                   const std::vector<std::string>& categories, int threads)
{
  std::ofstream out(fs::path(o.out) / "summary.md");
  const Summary_columns columns(rows);
  write_protocol(out, o, dataset, threads);
  write_quality_tables(out, columns, rows, categories);
  write_halves(out, columns, rows);
  write_time_ratios(out, rows);
  if(!rows_by_shape(rows, "ours1").empty()) write_one_thread(out, rows, threads);
  write_stage_medians(out, rows, threads);
  write_errors(out, rows);
}

// One level of one shape's hierarchy (--levels).
struct Level_row
{
  std::string shape;
  std::size_t oracle = 0, k = 0, leaves = 0;
  double miou = NaN, ri = NaN;
};
constexpr std::size_t max_level = 64;

// mIoU and RI against the number of parts, absolute and relative to the oracle count.
void write_levels(const Options& o, const std::string& dataset, const std::vector<Row>& rows,
                  const std::vector<Level_row>& levels, int threads)
{
  std::ofstream tsv(fs::path(o.out) / "levels.tsv");
  tsv << "shape\toracle_k\tk\tleaves\tmIoU\tRI\n";
  for(const Level_row& l : levels)
    tsv << l.shape << '\t' << l.oracle << '\t' << l.k << '\t' << l.leaves << '\t' << num(l.miou) << '\t' << num(l.ri) << '\n';
  std::ofstream out(fs::path(o.out) / "levels.md");
  out << "# Levels of the part hierarchy on " << dataset << "\n\nCommand: `" << o.command_line << "`\n\n"
      << machine_description(threads) << "\n"
      << "Each shape's hierarchy (from the `ours_k` run) cut at every k from 1 to its number of leaves (at most "
      << max_level << "), scored as in summary.md. The oracle k is the lower median of the shape's human part "
      << "counts.\n\n";
  std::size_t shapes = 0, too_coarse = 0;
  std::vector<double> leaves;
  for(const Row& r : rows)
    if(r.method == "ours_k" && r.ok)
    {
      ++shapes;
      leaves.push_back(double(r.leaves));
      if(r.leaves < r.k) ++too_coarse;
    }
  out << "Leaves (finest level): median " << num(median(leaves), 0) << "; fewer leaves than the oracle k on "
      << too_coarse << "/" << shapes << " shapes.\n\n## Relative to the oracle count\n\n"
      << "| k / oracle k | shapes | mIoU ↑ | RI ↑ |\n|---|---|---|---|\n";
  for(double f : {0.25, 0.5, 0.75, 1., 1.25, 1.5, 2., 3.})
  {
    std::vector<double> m, ri;
    for(const Level_row& l : levels)
    {
      const std::size_t want = (std::max)(std::size_t(1), std::size_t(std::lround(f * double(l.oracle))));
      if(l.k == (std::min)(want, l.leaves)) { m.push_back(l.miou); ri.push_back(l.ri); }
    }
    out << "| " << num(f, 2) << " | " << m.size() << " | " << num(mean(m), 3) << " | " << num(mean(ri), 3) << " |\n";
  }
  out << "\n## Absolute\n\nShapes whose finest level has fewer than k parts are left out of row k.\n\n"
      << "| k | shapes | mIoU ↑ | RI ↑ |\n|---|---|---|---|\n";
  for(std::size_t k = 1; k <= max_level; ++k)
  {
    std::vector<double> m, ri;
    for(const Level_row& l : levels)
      if(l.k == k) { m.push_back(l.miou); ri.push_back(l.ri); }
    if(!m.empty()) out << "| " << k << " | " << m.size() << " | " << num(mean(m), 3) << " | " << num(mean(ri), 3) << " |\n";
  }
}

void write_ablations(const Options& o, const std::string& dataset, const std::vector<Row>& rows,
                     const std::vector<Variant>& variants, int threads)
{
  std::ofstream out(fs::path(o.out) / "ablations.md");
  out << "# Ablations on " << dataset << " (shape of the paper's Tables 3 and 4)\n\n"
      << "Command: `" << o.command_line << "`\n\n" << machine_description(threads) << "\n"
      << "Metrics as in summary.md (mIoU as a fraction, VoI in nats), means over the shapes where "
      << "the variant ran; \"shapes\" counts them. Every variant passes all its settings explicitly; "
      << "the unnamed ones keep the paper's defaults (R = {16,32,64}, alpha = 0.15, lambda = "
      << "(1,1,1,1), Freeze, TSDF guidance and body seeds on). Unlike the paper's Table 3, whose "
      << "variants use a single-scale diagnostic branch, every Table 3 variant here changes one "
      << "setting of the full pipeline.\n\n";

  auto find = [&](const std::string& id) -> const Variant* {
    for(const Variant& v : variants)
      if(v.id == id) return &v;
    return nullptr;
  };
  auto metrics = [&](const std::string& id, bool with_time) {
    const Variant* v = find(id);
    std::ostringstream s;
    if(v == nullptr) { s << "| not run |  |  |  |  |" << (with_time ? "  |  |" : ""); return s.str(); }
    const Aggregate a = aggregate(rows, "ours:" + id);
    s << "| " << num(a.ri, 3) << " | " << num(a.voi, 3) << " | " << num(a.sc, 3) << " | " << num(a.miou, 3)
      << " | " << a.n_ok << "/" << a.n_all << " |";
    if(with_time) s << " " << num(a.t_mean, 3) << " | " << num(a.t_median, 3) << " |";
    return s.str();
  };

  out << "## Table 3: components\n\n| Category | Variant | RI ↑ | VoI ↓ | SC ↑ | mIoU ↑ | shapes |\n"
      << "|---|---|---|---|---|---|---|\n"
      << "| Reference | Full, {16,32,64} " << metrics("full", false) << "\n"
      << "| SQ Comp. | w/o Body " << metrics("no_body", false) << "\n"
      << "| SQ Comp. | w/o Freeze " << metrics("no_freeze", false) << "\n"
      << "| Flow-Freeze Threshold | Top 5% " << metrics("alpha05", false) << "\n"
      << "| Flow-Freeze Threshold | Top 25% " << metrics("alpha25", false) << "\n"
      << "| Geometric Cues | w/o Curvature (lambda1..3 = 0) " << metrics("no_curvature", false) << "\n"
      << "| Geometric Cues | with Normal (lambda4 = 1, the paper's) " << metrics("paper_normal", false) << "\n"
      << "| Geometric Cues | w/o Density (no sqrt(n)) " << metrics("no_density", false) << "\n"
      << "| w/o TSDF | {16,32,64} " << metrics("no_tsdf", false) << "\n";

  out << "\n## Departures from the paper, each undone alone, then all together\n\n"
      << "| Setting | RI ↑ | VoI ↓ | SC ↑ | mIoU ↑ | shapes | mean s ↓ | median s |\n|---|---|---|---|---|---|---|---|\n"
      << "| This implementation (defaults) " << metrics("full", true) << "\n"
      << "| the curvature of convex vertices counted " << metrics("paper_curvature", true) << "\n"
      << "| the normal deviation counted (lambda4 = 1) " << metrics("paper_normal", true) << "\n"
      << "| r_fit = min(r, 32) (same as the default at {16,32,64}) " << metrics("paper_fit_resolution", true) << "\n"
      << "| no exterior-band samples " << metrics("no_exterior_band", true) << "\n"
      << "| ROI and claims not stopped at Freeze walls " << metrics("no_reachable_regions", true) << "\n"
      << "| no exclusion balls around rejected seeds " << metrics("no_seed_exclusion", true) << "\n"
      << "| " << paper_solver_evaluations << " solver evaluations instead of 40 " << metrics("paper_evaluations", true) << "\n"
      << "| a stage does not end after 4 rejections in a row " << metrics("no_rejection_stop", true) << "\n"
      << "| coverage target 0.95 " << metrics("paper_coverage", true) << "\n"
      << "| no patch split size " << metrics("no_patch_split", true) << "\n"
      << "| no thin-sheet merge " << metrics("no_sheet_merge", true) << "\n"
      << "| the paper's literal version (all of the above) " << metrics("paper_literal", true) << "\n";

  out << "\n## Pieces and creases (segment_pieces())\n\n"
      << "| Setting | RI ↑ | VoI ↓ | SC ↑ | mIoU ↑ | shapes | mean s ↓ | median s |\n|---|---|---|---|---|---|---|---|\n"
      << "| defaults (crease 60 degrees, minimum part area 0.005) " << metrics("full", true) << "\n"
      << "| w/o pieces (volumetric parts only) " << metrics("no_pieces", true) << "\n"
      << "| crease angle 45 degrees " << metrics("crease45", true) << "\n"
      << "| crease angle 75 degrees " << metrics("crease75", true) << "\n"
      << "| minimum part area 0.002 " << metrics("min_part_area_2", true) << "\n"
      << "| minimum part area 0.01 " << metrics("min_part_area_10", true) << "\n"
      << "| residual patches kept, tolerance 1 voxel " << metrics("residual_1", true) << "\n"
      << "| residual patches kept, tolerance 2 voxels " << metrics("residual_2", true) << "\n"
      << "| residual patches kept, tolerance 4 voxels " << metrics("residual_4", true) << "\n";
  for(int r : {16, 32, 64})
    out << "| single scale " << r << ", r_fit = r / 2 (default) " << metrics("r" + std::to_string(r), true) << "\n"
        << "| single scale " << r << ", r_fit = min(r, 32) " << metrics("r" + std::to_string(r) + "_paper_fit_resolution", true) << "\n";

  out << "\n## Table 4: TSDF guidance, Freeze constraints, resolutions\n\n"
      << "| Setting | Resolution | RI ↑ | VoI ↓ | SC ↑ | mIoU ↑ | shapes | mean s ↓ | median s |\n"
      << "|---|---|---|---|---|---|---|---|---|\n";
  for(int r : {16, 32, 64})
    out << "| Single scale, w TSDF, w/o Freeze | " << r << " " << metrics("r" + std::to_string(r) + "_no_freeze", true) << "\n";
  for(int r : {16, 32, 64})
    out << "| Single scale, w/o TSDF, w Freeze | " << r << " " << metrics("r" + std::to_string(r) + "_no_tsdf", true) << "\n";
  for(int r : {16, 32, 64})
    out << "| Single scale, w TSDF, w Freeze | " << r << " " << metrics("r" + std::to_string(r), true) << "\n";
  out << "| w/o TSDF | {16,32,64} " << metrics("no_tsdf", true) << "\n"
      << "| Ours, hierarchical, w TSDF | {16,32,64} " << metrics("full", true) << "\n";

  out << "\n## Errors\n\n";
  bool any = false;
  for(const Row& r : rows)
    if(r.method.compare(0, 5, "ours:") == 0 && !r.ok)
    {
      out << "- " << r.shape << " / " << r.method << ": " << clean(r.error) << "\n";
      any = true;
    }
  if(!any) out << "None.\n";
}

// ------------------------------------------------------------------------------------------
// Scale run: one shape subdivided to several sizes, each decomposed from its file.

// The subdivision steps (L: Loop, 1 to 4 faces; S: sqrt(3), 1 to 3) whose face count is
// nearest to `target` in ratio among those with at least 90% of it.
std::string subdivision_steps(double base_faces, double target)
{
  std::string best;
  double best_error = std::numeric_limits<double>::infinity();
  for(int loop = 0; loop <= 8; ++loop)
    for(int sqrt3 = 0; sqrt3 <= 8; ++sqrt3)
    {
      const double f = base_faces * std::pow(4., loop) * std::pow(3., sqrt3);
      const double error = std::abs(std::log(f / target));
      if(f >= 0.9 * target && error < best_error)
      {
        best_error = error;
        best = std::string(std::size_t(loop), 'L') + std::string(std::size_t(sqrt3), 'S');
      }
    }
  return best;
}

// Seconds to read `m` written to `file` as binary PLY or STL (by extension) with
// IO::read_triangle_mesh(), the file deleted afterwards; NaN if it cannot be written.
double binary_read_seconds(const Mesh& m, const fs::path& file)
{
  {
    std::ofstream out(file, std::ios::binary);
    CGAL::IO::set_binary_mode(out);
    if(!(file.extension() == ".ply" ? CGAL::IO::write_PLY(out, m) : CGAL::IO::write_STL(out, m))) return NaN;
  }
  const auto t0 = std::chrono::steady_clock::now();
  Mesh back;
  PD::IO::read_triangle_mesh(file.string(), back);
  const double seconds = seconds_since(t0);
  fs::remove(file);
  return seconds;
}

// Writes the subdivided mesh of `steps` to `file`; false if it cannot.
bool write_subdivided(const Mesh& base, const std::string& steps, const fs::path& file)
{
  Mesh m = base;
  for(char c : steps)
    if(c == 'L') CGAL::Subdivision_method_3::Loop_subdivision(m);
    else CGAL::Subdivision_method_3::Sqrt3_subdivision(m);
  std::ofstream out(file);
  out.precision(17);
  return bool(CGAL::IO::write_OFF(out, m));
}

// Reads `file` and decomposes it at the default parameters; then times binary PLY and STL reads.
Row decompose_file(const Options& o, const fs::path& file, const std::string& steps, std::size_t& vertices,
                   double& t_read_ply, double& t_read_stl)
{
  Row r;
  auto t0 = std::chrono::steady_clock::now();
  try
  {
    Mesh mesh;
    PD::IO::read_triangle_mesh(file.string(), mesh);
    r.t_read = seconds_since(t0);
    r.faces = num_faces(mesh);
    vertices = num_vertices(mesh);
    std::vector<std::size_t> labels;
    PD::Stage_timings st;
    t0 = std::chrono::steady_clock::now();
    r.parts = run_ours(mesh, labels, PD::parameters::stage_timings(&st));
    r.t_method = seconds_since(t0);
    copy_stage_timings(st, r);
    r.ok = true;
    r.peak_mb = status_mb("VmHWM:");
    // the same mesh as binary files, read only (after the peak memory of the OFF run)
    const std::string stem = "scale_" + o.scale_shape + "_" + steps;
    t_read_ply = binary_read_seconds(mesh, fs::path(o.out) / (stem + ".ply"));
    t_read_stl = binary_read_seconds(mesh, fs::path(o.out) / (stem + ".stl"));
  }
  catch(const std::exception& e) { r.error = e.what(); }
  if(std::isnan(r.peak_mb)) r.peak_mb = status_mb("VmHWM:");
  return r;
}

// One size of the scale run: a row of scale.tsv and, if it succeeded, of the table of scale.md.
bool run_scale_size(const Options& o, const Mesh& base, double target, std::ostream& tsv, std::ostream& table,
                    std::vector<std::pair<double, double> >& sizes)
{
  const std::string steps = subdivision_steps(double(num_faces(base)), target);
  const auto t0 = std::chrono::steady_clock::now();
  const fs::path file = fs::path(o.out) / ("scale_" + o.scale_shape + "_" + steps + ".off");
  if(!write_subdivided(base, steps, file)) { std::cerr << "cannot write " << file << "\n"; return false; }
  const double t_generate = seconds_since(t0);
  const double file_mb = double(fs::file_size(file)) / (1024. * 1024.);
#ifdef __GLIBC__
  malloc_trim(0);
#endif
  const double rss_before = status_mb("VmRSS:");
  reset_peak_memory();
  std::size_t vertices = 0;
  double t_read_ply = NaN, t_read_stl = NaN;
  const Row r = decompose_file(o, file, steps, vertices, t_read_ply, t_read_stl);
  fs::remove(file);

  tsv << o.scale_shape << '\t' << steps << '\t' << r.faces << '\t' << vertices << '\t' << num(file_mb, 1) << '\t'
      << num(t_generate) << '\t' << num(r.t_read) << '\t' << num(t_read_ply) << '\t' << num(t_read_stl) << '\t'
      << num(r.t_prior) << '\t' << num(r.t_tsdf) << '\t' << num(r.t_fitting) << '\t' << num(r.t_overseg) << '\t'
      << num(r.t_assign) << '\t' << num(r.t_method) << '\t' << num(r.end_to_end()) << '\t' << num(r.peak_mb, 1) << '\t'
      << num(rss_before, 1) << '\t' << r.parts << '\t' << clean(r.error) << std::endl;
  std::cout << "scale " << steps << ": " << r.faces << " faces, " << (r.ok ? "ok" : "ERROR " + r.error) << ", read "
            << num(r.t_read, 3) << " s, decompose " << num(r.t_method, 3) << " s, peak " << num(r.peak_mb, 0)
            << " MB" << std::endl;
  if(!r.ok) return true;
  double slope = NaN;
  if(!sizes.empty())
    slope = std::log(r.end_to_end() / sizes.back().second) / std::log(double(r.faces) / sizes.back().first);
  sizes.emplace_back(double(r.faces), r.end_to_end());
  table << "| " << steps << " | " << r.faces << " | " << num(file_mb, 0) << " | " << num(r.t_read, 2) << " | "
        << num(t_read_ply, 2) << " | " << num(t_read_stl, 2) << " | " << num(r.t_prior, 2) << " | "
        << num(r.t_tsdf, 2) << " | " << num(r.t_fitting, 2) << " | " << num(r.t_overseg, 2) << " | "
        << num(r.t_assign, 2) << " | " << num(r.t_method, 2) << " | " << num(r.end_to_end(), 2) << " | "
        << num(1e5 * r.end_to_end() / double(r.faces), 3) << " | " << (std::isnan(slope) ? std::string("-") : num(slope, 2))
        << " | " << num(r.peak_mb, 0) << " | " << r.parts << " |\n";
  return true;
}

void write_scale_md(const Options& o, const Mesh& base, int threads, const std::string& table,
                    const std::vector<std::pair<double, double> >& sizes)
{
  std::ofstream md(fs::path(o.out) / "scale.md");
  md << "# Scale run: " << o.scale_shape << " (" << num_faces(base) << " faces) subdivided\n\n"
     << "Command: `" << o.command_line << "`\n\n" << machine_description(threads) << "\n"
     << "Each size is made by Loop (L, 1 to 4 faces) and sqrt(3) (S, 1 to 3) subdivision steps of CGAL's "
        "Subdivision_method_3, written as an OFF file, then read with IO::read_triangle_mesh() and decomposed "
        "with decompose() at the default parameters; the file is deleted afterwards. The same mesh is then "
        "written as binary PLY and binary STL and read again (read only). Seconds are wall-clock; "
        "end-to-end = read + decompose; peak MB is the process's VmHWM from just before the read to the end "
        "(the mesh, the file buffer and every stage). Growth exponent: log(t2/t1)/log(F2/F1) of the "
        "end-to-end time against the previous size (1 = linear).\n\n"
     << "| steps | faces | file MB | read s | read binary PLY s | read binary STL s | prior s | TSDF s | fitting s "
        "| over-seg. s | assignment s | decompose s | end-to-end s | s per 100k faces | growth exponent | peak MB | parts |\n"
     << "|---|---|---|---|---|---|---|---|---|---|---|---|---|---|---|---|---|\n"
     << table;
  if(sizes.size() >= 2)
    md << "\nFrom " << num(sizes.front().first, 0) << " to " << num(sizes.back().first, 0) << " faces ("
       << num(sizes.back().first / sizes.front().first, 1) << "x) the end-to-end time grows "
       << num(sizes.back().second / sizes.front().second, 1) << "x (exponent "
       << num(std::log(sizes.back().second / sizes.front().second) / std::log(sizes.back().first / sizes.front().first), 2)
       << ").\n";
}

int run_scale(const Options& o, int threads)
{
  const fs::path dir(o.dataset);
  fs::path input;
  for(const char* ext : {".off", ".obj", ".ply", ".stl"})
    if(fs::exists(dir / (o.scale_shape + ext))) { input = dir / (o.scale_shape + ext); break; }
  if(input.empty()) { std::cerr << "no mesh file " << o.scale_shape << ".{off,obj,ply,stl} in " << o.dataset << "\n"; return 1; }
  Mesh base;
  try { PD::IO::read_triangle_mesh(input.string(), base); }
  catch(const std::exception& e) { std::cerr << "cannot read " << input << ": " << e.what() << "\n"; return 1; }
  fs::create_directories(o.out);
  if(!reset_peak_memory()) std::cerr << "warning: cannot reset the peak memory: peak_mb is the process peak\n";

  std::ofstream tsv(fs::path(o.out) / "scale.tsv");
  tsv << "shape\tsteps\tfaces\tvertices\tfile_mb\tt_generate\tt_read\tt_read_ply\tt_read_stl\tt_prior\tt_tsdf\tt_fitting\tt_overseg\tt_assign"
         "\tt_method\tt_end_to_end\tpeak_mb\trss_before_mb\tparts\terror\n";
  std::ostringstream table;
  std::vector<std::pair<double, double> > sizes; // (faces, end-to-end seconds)
  for(double target : o.scale_faces)
    if(!run_scale_size(o, base, target, tsv, table, sizes)) return 1;
  write_scale_md(o, base, threads, table.str(), sizes);
  std::cout << "wrote " << (fs::path(o.out) / "scale.tsv").string() << ", " << (fs::path(o.out) / "scale.md").string() << "\n";
  return 0;
}

// ------------------------------------------------------------------------------------------
// The data set run

// The variants named by --variants (all of them with --ablations alone); false on an unknown name.
bool select_variants(const Options& o, std::vector<Variant>& variants)
{
  if(!o.ablations) return true;
  for(const Variant& v : all_variants())
    if(o.variants.empty() || contains(o.variants, v.id)) variants.push_back(v);
  for(const std::string& id : o.variants)
  {
    bool known = false;
    for(const Variant& v : variants) known = known || v.id == id;
    if(!known) { std::cerr << "unknown variant " << id << "\n"; return false; }
  }
  return true;
}

std::string dataset_name(const Options& o)
{
  const fs::path p = fs::path(o.dataset).lexically_normal();
  return p.filename().string().empty() ? p.parent_path().filename().string() : p.filename().string();
}

// One shape read once: the same mesh, samples and ground truths serve every method.
struct Shape_data
{
  Mesh mesh;
  std::vector<std::size_t> samples;
  std::vector<std::vector<long> > gt_samples, gt_faces; // gt_faces: in mesh face order
  std::string error, note;
};

// Reads the ground truths with one label per input face, at the samples and per mesh face; sets
// base.k (the lower median of their part counts), gt_parts and n_gt.
void read_ground_truths(const Shape_entry& e, const PD::IO::Mesh_file_info& info, Shape_data& s, Row& base)
{
  double gt_parts = 0.;
  std::vector<std::size_t> gt_counts;
  for(const fs::path& p : e.ground_truths)
  {
    std::vector<long> file_labels;
    if(!read_labels(p, file_labels) || file_labels.size() != info.number_of_input_faces)
    {
      append_note(s.note, p.filename().string() + " skipped (" + std::to_string(file_labels.size()) + " labels for " +
                            std::to_string(info.number_of_input_faces) + " faces)");
      continue;
    }
    std::vector<long> g;
    g.reserve(s.samples.size());
    for(std::size_t f : s.samples) g.push_back(file_labels[info.face_to_input[f]]);
    std::vector<long> sorted(file_labels);
    std::sort(sorted.begin(), sorted.end());
    gt_counts.push_back(std::size_t(std::unique(sorted.begin(), sorted.end()) - sorted.begin()));
    gt_parts += double(gt_counts.back());
    s.gt_samples.push_back(std::move(g));
    s.gt_faces.emplace_back();
    for(Face f : faces(s.mesh)) s.gt_faces.back().push_back(file_labels[info.face_to_input[std::size_t(f)]]);
  }
  std::sort(gt_counts.begin(), gt_counts.end());
  if(!gt_counts.empty()) base.k = gt_counts[(gt_counts.size() - 1) / 2];
  if(s.gt_samples.empty()) append_note(s.note, "no usable ground truth");
  else base.gt_parts = gt_parts / double(s.gt_samples.size());
  base.n_gt = s.gt_samples.size();
}

void read_shape(const Options& o, const Shape_entry& e, Shape_data& s, Row& base)
{
  PD::IO::Mesh_file_info info;
  const auto t0 = std::chrono::steady_clock::now();
  try
  {
    if(e.mesh.empty()) throw std::runtime_error("no mesh file " + e.name + ".{off,obj,ply,stl}");
    info = PD::IO::read_triangle_mesh(e.mesh.string(), s.mesh);
  }
  catch(const std::exception& ex) { s.error = std::string("read: ") + ex.what(); }
  base.t_read = seconds_since(t0);
  base.faces = num_faces(s.mesh);
  if(s.error.empty() && e.manifest_faces >= 0 && std::size_t(e.manifest_faces) != info.number_of_input_faces)
    s.error = "manifest says " + std::to_string(e.manifest_faces) + " faces, the file has " +
              std::to_string(info.number_of_input_faces);
  if(!s.error.empty()) return;
  s.samples = PD::sample_faces_by_area(s.mesh, CGAL::parameters::number_of_points_on_faces(o.samples).random_seed(o.seed));
  read_ground_truths(e, info, s, base);
  if(info.number_of_reversed_components > 0)
    append_note(s.note, "reader reoriented " + std::to_string(info.number_of_reversed_components) + " inward component(s)");
}

// What the methods of one shape write to and read from each other.
struct Shape_run
{
  const Options& o;
  const Shape_entry& e;
  const Shape_data& s;
  const Row& base;
  std::vector<Level_row>& level_rows;
  std::vector<std::size_t> ours_labels; // of the "ours" run, compared with "ours1"
  bool has_ours_labels = false;
};

// One thread from the file to the labels: the mesh is read again inside the arena.
void run_ours_one_thread(Shape_run& run, Row& r, std::vector<std::size_t>& labels,
                         std::vector<PD::Superquadric<K> >& primitives)
{
  PD::Stage_timings st;
  auto one_thread = [&]() {
    Mesh mesh1;
    const auto tr = std::chrono::steady_clock::now();
    PD::IO::read_triangle_mesh(run.e.mesh.string(), mesh1);
    r.t_read = seconds_since(tr);
    const auto t0 = std::chrono::steady_clock::now();
    r.parts = run_ours(mesh1, labels, PD::parameters::stage_timings(&st), &primitives);
    r.t_method = seconds_since(t0);
  };
#ifdef CGAL_LINKED_WITH_TBB
  tbb::task_arena arena(1);
  arena.execute(one_thread);
#else
  one_thread();
#endif
  copy_stage_timings(st, r);
  if(run.has_ours_labels) r.same_labels = labels == run.ours_labels ? "yes" : "no";
}

// Told the part count; with --levels, also scores every level of the hierarchy.
void run_ours_k(Shape_run& run, Row& r, std::vector<std::size_t>& labels, std::vector<PD::Superquadric<K> >& primitives)
{
  if(r.k == 0) throw std::runtime_error("no ground truth: no part count");
  PD::Stage_timings st;
  PD::Part_hierarchy<K> h;
  const auto t0 = std::chrono::steady_clock::now();
  r.parts = run_ours(run.s.mesh, labels,
                     PD::parameters::combine(PD::parameters::stage_timings(&st), PD::parameters::number_of_parts(r.k),
                                             PD::parameters::part_hierarchy(&h)),
                     &primitives);
  r.t_method = seconds_since(t0);
  r.t_hierarchy = st.hierarchy;
  r.leaves = h.number_of_leaves();
  if(!run.o.levels) return;
  for(std::size_t k = 1; k <= (std::min)(h.number_of_leaves(), max_level); ++k)
  {
    Row l = run.base;
    score(h.labels(k), run.s.samples, run.s.gt_samples, l);
    run.level_rows.push_back(Level_row{run.e.name, run.base.k, k, h.number_of_leaves(), l.miou, l.ri});
  }
}

void run_sdf(const Mesh& mesh, const std::string& method, Row& r, std::vector<std::size_t>& labels)
{
  if(method == "sdf_k" && r.k == 0) throw std::runtime_error("no ground truth: no part count");
  const auto t0 = std::chrono::steady_clock::now();
  pd_benchmark::Sdf_peer_result p = method == "sdf" ? pd_benchmark::segment_with_sdf(mesh)
                                                    : pd_benchmark::segment_with_sdf(mesh, r.k);
  r.t_method = seconds_since(t0);
  r.t_sdf = p.sdf_seconds;
  r.t_sdf_segmentation = p.segmentation_seconds;
  r.parts = p.number_of_segments;
  r.note = p.note;
  labels = std::move(p.labels);
}

// "ours" at the defaults, or one variant of it.
void run_ours_variant(Shape_run& run, const Variant* variant, Row& r, std::vector<std::size_t>& labels,
                      std::vector<PD::Superquadric<K> >& primitives)
{
  PD::Stage_timings st;
  const auto t0 = std::chrono::steady_clock::now();
  if(variant == nullptr)
    r.parts = run_ours(run.s.mesh, labels, PD::parameters::stage_timings(&st), &primitives);
  else
    r.parts = run_ours(run.s.mesh, labels,
                       PD::parameters::combine(Part_decomposition_tools::named_parameters(*variant),
                                               PD::parameters::stage_timings(&st)),
                       &primitives);
  r.t_method = seconds_since(t0);
  copy_stage_timings(st, r);
  if(r.method == "ours")
  {
    run.ours_labels = labels;
    run.has_ours_labels = true;
  }
}

// Scores the labels against the ground truths, and the primitives against the true ones.
void score_run(const Shape_run& run, const Shape_truth& truth, const std::vector<std::size_t>& labels,
               const std::vector<PD::Superquadric<K> >& primitives, Row& r)
{
  score(labels, run.s.samples, run.s.gt_samples, r);
  r.cd = mean_cut_discrepancy(run.s.mesh, labels, run.s.gt_faces);
  if(truth.primitives.empty()) return;
  r.findable = truth.findable;
  r.thin_findable = truth.thin_findable;
  if(r.method.compare(0, 3, "sdf") != 0)
  {
    score_primitives(truth.primitives, primitives, labels, run.s.gt_faces.front(), truth.face_area, r);
    write_primitives(fs::path(run.o.out) / "primitives" / (run.e.name + "." + r.method + ".tsv"), primitives);
    return;
  }
  // no primitives to match: found is n/a
  r.true_primitives = long(truth.primitives.size());
  r.thin_total = long(std::count_if(truth.primitives.begin(), truth.primitives.end(),
                                    [](const pd_benchmark::True_primitive& t) { return t.thin; }));
}

void run_method(Shape_run& run, const Shape_truth& truth, const Variant* variant, Row& r)
{
  std::vector<std::size_t> labels;
  std::vector<PD::Superquadric<K> > primitives;
  const auto t0 = std::chrono::steady_clock::now();
  try
  {
    if(r.method == "ours1") run_ours_one_thread(run, r, labels, primitives);
    else if(r.method == "ours_k") run_ours_k(run, r, labels, primitives);
    else if(r.method == "sdf" || r.method == "sdf_k") run_sdf(run.s.mesh, r.method, r, labels);
    else run_ours_variant(run, variant, r, labels, primitives);
    score_run(run, truth, labels, primitives, r);
    r.ok = true;
  }
  catch(const std::exception& ex)
  {
    r.t_method = seconds_since(t0);
    r.error = ex.what();
  }
  catch(...)
  {
    r.t_method = seconds_since(t0);
    r.error = "unknown exception";
  }
}

void print_row(std::size_t si, std::size_t n, const Row& r)
{
  std::cout << "[" << (si + 1) << "/" << n << "] " << std::left << std::setw(14) << r.shape << " " << std::setw(22)
            << r.method << std::right << (r.ok ? " ok   " : " ERROR ") << " " << num(r.t_method, 3) << " s  mIoU "
            << num(r.miou, 3) << " RI " << num(r.ri, 3) << " VoI " << num(r.voi, 3) << " SC " << num(r.sc, 3)
            << " CD " << num(r.cd, 3) << " parts " << r.parts
            << (r.found < 0 ? "" : " found " + count(r.found) + "/" + count(r.true_primitives) + " thin " +
                                     count(r.thin_found) + "/" + count(r.thin_total))
            << (r.ok ? "" : "  " + r.error) << (r.note.empty() ? "" : "  [" + r.note + "]") << std::endl;
}

// The methods asked for, in run order, then the variants of ours.
std::vector<std::pair<std::string, const Variant*> > method_runs(const Options& o, const std::vector<Variant>& variants)
{
  std::vector<std::pair<std::string, const Variant*> > runs;
  for(const std::string& m : all_methods())
    if(contains(o.methods, m)) runs.emplace_back(m, nullptr);
  if(contains(o.methods, "ours") || o.ablations)
    for(const Variant& v : variants) runs.emplace_back("ours:" + v.id, &v);
  return runs;
}

// Runs every method on one shape; one row per method, written to `tsv` as it comes.
void run_shape(const Options& o, const Shape_entry& e, const std::vector<Variant>& variants, std::size_t si,
               std::size_t n, const std::string& dataset, std::ostream& tsv, std::vector<Row>& rows,
               std::vector<Level_row>& level_rows)
{
  Row base;
  base.shape = e.name;
  base.category = e.category;
  base.n_gt = e.ground_truths.size();
  Shape_data s;
  read_shape(o, e, s, base);
  const Shape_truth truth = read_truth(e, s.mesh, s.gt_faces, s.note);
  Shape_run run{o, e, s, base, level_rows};
  for(const auto& m : method_runs(o, variants))
  {
    Row r = base;
    r.method = m.first;
    if(s.error.empty())
    {
#ifdef __GLIBC__
      malloc_trim(0); // give freed heap pages back, so that the peak counts what the method needs
#endif
      r.rss_before_mb = status_mb("VmRSS:");
      reset_peak_memory();
      run_method(run, truth, m.second, r);
    }
    else
      r.error = s.error;
    r.peak_mb = status_mb("VmHWM:");
    if(!s.note.empty()) r.note = r.note.empty() ? s.note : s.note + "; " + r.note;
    write_tsv_row(tsv, dataset, r);
    print_row(si, n, r);
    rows.push_back(r);
  }
}

} // namespace

int main(int argc, char** argv)
{
  Options o;
  if(!parse(argc, argv, o)) { usage(); return 2; }

  const int threads = o.threads > 0 ? o.threads : int(std::max(1u, std::thread::hardware_concurrency()));
#ifdef CGAL_LINKED_WITH_TBB
  tbb::global_control parallelism(tbb::global_control::max_allowed_parallelism, std::size_t(threads));
#endif
  if(!o.scale_shape.empty()) return run_scale(o, threads);

  std::string error;
  const std::vector<Shape_entry> shapes = read_dataset(o, error);
  if(!error.empty()) { std::cerr << error << "\n"; return 1; }
  if(shapes.empty()) { std::cerr << "no shape selected\n"; return 1; }
  std::vector<Variant> variants;
  if(!select_variants(o, variants)) return 2;

  fs::create_directories(o.out);
  const std::string dataset = dataset_name(o);
  std::ofstream tsv(fs::path(o.out) / "results.tsv");
  write_tsv_header(tsv);
  if(!reset_peak_memory())
    std::cerr << "warning: cannot reset the peak memory (/proc/self/clear_refs): peak_mb is the process peak\n";

  std::vector<Row> rows;
  std::vector<Level_row> level_rows;
  std::vector<std::string> categories;
  for(std::size_t si = 0; si < shapes.size(); ++si)
  {
    if(!contains(categories, shapes[si].category)) categories.push_back(shapes[si].category);
    run_shape(o, shapes[si], variants, si, shapes.size(), dataset, tsv, rows, level_rows);
  }

  write_summary(o, dataset, rows, categories, threads);
  if(o.levels) write_levels(o, dataset, rows, level_rows, threads);
  if(o.ablations) write_ablations(o, dataset, rows, variants, threads);
  std::cout << "wrote " << (fs::path(o.out) / "results.tsv").string() << ", "
            << (fs::path(o.out) / "summary.md").string()
            << (o.ablations ? ", " + (fs::path(o.out) / "ablations.md").string() : std::string()) << "\n";
  return 0;
}
