// Copyright (c) 2026 The Part_decomposition authors.
// All rights reserved.
//
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Author(s)     : The Part_decomposition authors

#ifndef CGAL_PART_DECOMPOSITION_INTERNAL_SUPERQUADRIC_FITTER_H
#define CGAL_PART_DECOMPOSITION_INTERNAL_SUPERQUADRIC_FITTER_H

// SDFSQFit (paper Alg. A.2): the coarse-to-fine loop of seeds, fits, claims and rejections behind
// fit_superquadrics(), one method per step of the algorithm.

#include <CGAL/Part_decomposition/stage_results.h>
#include <CGAL/Part_decomposition/Superquadric.h>
#include <CGAL/Part_decomposition/Voxel_grid.h>
#include <CGAL/Part_decomposition/parameters.h>
#include <CGAL/Part_decomposition/internal/fit_sdf.h>
#include <CGAL/Part_decomposition/internal/grid_morphology.h>
#include <CGAL/Part_decomposition/internal/superquadric_distance.h>
#include <CGAL/Part_decomposition/internal/toolbox.h>

#include <algorithm>
#include <array>
#include <chrono>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <iostream>
#include <limits>
#include <utility>
#include <vector>

namespace CGAL {
namespace Part_decomposition {
namespace internal {

// The named parameters of fit_superquadrics() (see its documentation), as read by
// read_fitting_parameters().
struct Fitting_parameters
{
  double flow_zone_tolerance = defaults::flow_zone_tolerance;
  std::vector<double> trust_region_scales = defaults::trust_region_scales();
  double body_seed_threshold = defaults::body_seed_threshold;
  double minimum_body_volume = defaults::minimum_body_volume;
  double minimum_surface_volume = defaults::minimum_surface_volume;
  double exterior_penalty = defaults::exterior_penalty;
  double coverage_target = defaults::coverage_target;
  double roi_radius = defaults::roi_radius;
  Interior_weight_mode interior_weight_mode = defaults::interior_weight_mode;
  std::size_t maximum_number_of_primitives = defaults::maximum_number_of_primitives;
  bool use_freeze_zone = defaults::use_freeze_zone;
  bool use_tsdf_guidance = defaults::use_tsdf_guidance;
  bool use_body_seeds = defaults::use_body_seeds;
  int fitting_resolution_cap = defaults::fitting_resolution_cap;
  bool use_exterior_band_samples = defaults::use_exterior_band_samples;
  bool use_reachable_regions = defaults::use_reachable_regions;
  bool use_seed_exclusion = defaults::use_seed_exclusion;
  int maximum_solver_evaluations = defaults::maximum_solver_evaluations;
  std::size_t maximum_rejections_in_a_row = defaults::maximum_rejections_in_a_row;
  bool merge_primitives = defaults::merge_primitives;
  double minimum_merge_iou = defaults::minimum_merge_iou;
  bool verbose = false;
};

// Stamped marks: O(1) clearing between seeds.
struct Stamp_set
{
  std::vector<std::uint32_t> stamp;
  std::uint32_t current = 0;
  void reset(std::size_t n)
  {
    if(stamp.size() != n)
    {
      stamp.assign(n, 0);
      current = 0;
    }
    if(++current == 0)
    {
      std::fill(stamp.begin(), stamp.end(), 0);
      current = 1;
    }
  }
  bool contains(std::size_t i) const { return stamp[i] == current; }
  void insert(std::size_t i) { stamp[i] = current; }
};

// Wall-clock seconds spent in each step, for the verbose report.
class Step_times
{
public:
  enum Step { STAGE_SETUP, SEED, REGION_AND_SAMPLES, FIT, CLAIM, MERGE, NUMBER_OF_STEPS };

  // Runs f() and adds its duration to `step`; returns what f() returns.
  template <typename F>
  decltype(auto) time(Step step, const F& f)
  {
    return add_seconds(m_seconds[step], f);
  }

  double milliseconds(Step step) const { return 1e3 * m_seconds[step]; }

private:
  std::array<double, NUMBER_OF_STEPS> m_seconds{};
};

template <typename ConcurrencyTag, typename GeomTraits>
class Superquadric_fitter
{
public:
  typedef Superquadric_fitting_result<GeomTraits> Result;

  // `fitting_resolutions`: r_fit of each stage of `prior.resolutions`; `zones` holds each of them.
  Superquadric_fitter(const Hierarchical_prior& prior, const Truncated_signed_distance_field& tsdf,
                      const Fitting_zones& zones, const std::vector<int>& fitting_resolutions,
                      const Fitting_parameters& parameters)
    : m_prior(prior), m_tsdf(tsdf), m_zones(zones), m_stage_resolutions(prior.resolutions),
      m_fitting_resolutions(fitting_resolutions), m_parameters(parameters),
      m_R(prior.classes.resolution()), m_N(prior.classes.size()), m_RR(std::size_t(m_R)),
      m_delta(1. / double(m_R)),
      m_freeze(parameters.use_freeze_zone ? zones.freeze_zone : zones.exterior)
  {
    m_result.normalization = prior.normalization;
    m_result.labels = Voxel_grid<std::int32_t>(m_R, -1);
  }

  Result run()
  {
    const auto start = std::chrono::steady_clock::now();
    if(m_N == 0) return m_result;
    prepare_fields();
    for(std::size_t s = 0; s < m_stage_resolutions.size(); ++s)
    {
      Stage stage = m_times.time(Step_times::STAGE_SETUP, [&] { return set_up_stage(s); });
      while(stage_continues(stage))
      {
        Seed seed;
        if(!m_times.time(Step_times::SEED, [&] { return pick_seed(stage, seed); })) break;
        try_seed(stage, seed);
      }
      end_stage(stage);
    }
    m_times.time(Step_times::MERGE, [&] {
      merge_small_residual_regions();
      collect_claimed_voxels();
    });
    m_result.seconds = seconds_since(start);
    if(m_parameters.verbose) report_times();
    return std::move(m_result);
  }

private:
  // Fixed choices, not parameters:
  // - samples above this count are taken on a lattice of stride 2 or 4: bounds the cost of a solve;
  static constexpr std::size_t maximum_samples = 4096;
  // - spacing of the Flow-zone test samples, in finest voxels (the zone tolerance is >= 4 of them);
  static constexpr double surface_test_spacing = 1.;
  // - a rejected surface seed excludes this fraction of rho: the rest of its component is seeded again;
  static constexpr double surface_exclusion = 0.5;
  // - relative gain below which a solve stops: scipy's default ftol;
  static constexpr double function_tolerance = 1e-8;
  // - the sample band d_M < 1.5 Delta and M_fit = {d~ <= 2 Delta}, in finest voxels (paper B.1, B.3);
  static constexpr double sample_band = 1.5;
  static constexpr double claim_band = 2.;
  // - a stage tries at most this many seeds per allowed primitive (at least 16 primitives): a
  //   safety bound for when rejections in a row never end it.
  static constexpr std::size_t seeds_per_primitive = 16;

  struct Stage
  {
    int r = 0, r_fit = 0;
    double delta_fit = 0., rho = 0.; // Delta^{r_fit} and the ROI radius, normalized units
    const Voxel_grid<std::uint8_t>* flow = nullptr;
    const Voxel_grid<double>* flow_distance = nullptr;
    std::size_t vmin_body = 0, vmin_surface = 0; // in finest voxels
    std::size_t valid_voxels = 0, covered_voxels = 0, seeds = 0, rejections_in_a_row = 0;
  };

  struct Seed
  {
    std::size_t voxel = 0;
    bool body = false;
    double depth_sqd = 0.; // the largest squared EDT of Omega_Body (a body seed's own)
    std::array<int, 3> ijk = {{0, 0, 0}};
    std::array<double, 3> center = {{0., 0., 0.}};
    double ball_sqd = 0.; // squared ROI radius in finest voxels
  };

  struct Initial_superquadric
  {
    Superquadric_data theta;
    Superquadric_vector lb, ub;
  };

  struct Fit_outcome
  {
    Fit_sdf_result fit;
    double eta = 0.;
    bool passed = false, degenerate = false;
  };

  // ---- Set-up of the whole run and of each stage (Alg. A.2 lines 1-7)

  // d_M (or the occupancy only), the exterior band samples, the sampling lattices, FitSDF settings.
  void prepare_fields()
  {
    const double tau = m_tsdf.truncation;
    if(!m_parameters.use_tsdf_guidance)
    {
      // without TSDF guidance: -tau in the hull, +tau in ext_void
      m_binary_field = Voxel_grid<double>(m_R, tau);
      for(std::size_t v = 0; v < m_N; ++v) m_binary_field[v] = m_zones.exterior[v] ? tau : -tau;
    }
    m_dM = m_parameters.use_tsdf_guidance ? &m_tsdf.values : &m_binary_field;
    if(m_parameters.use_exterior_band_samples) collect_exterior_band();
    // 2 on the stride-4 lattice, 1 on the stride-2 lattice, else 0
    m_lattice_level.assign(m_N, 0);
    for(std::size_t v = 0; v < m_N; ++v)
    {
      const std::size_t i = v % m_RR, j = (v / m_RR) % m_RR, k = v / (m_RR * m_RR);
      const std::size_t o = i | j | k;
      m_lattice_level[v] = (o & 3) == 0 ? 2 : ((o & 1) == 0 ? 1 : 0);
    }
    m_excluded.assign(m_N, 0);
    m_valid.assign(m_N, 0);
    m_spec.assign(m_N, 0);
    m_body.assign(m_N, 0);
    m_settings.truncation = tau;
    m_settings.exterior_penalty = m_parameters.exterior_penalty;
    m_settings.reestimate_variance = m_parameters.interior_weight_mode == Interior_weight_mode::MPS_REESTIMATED;
    m_settings.maximum_evaluations = m_parameters.maximum_solver_evaluations;
    m_settings.function_tolerance = function_tolerance;
  }

  // Exterior evidence: ext_void voxels of the thin outer band, which the ROI (ball minus the
  // Freeze zone) would otherwise drop; they are sampled but never claimed.
  void collect_exterior_band()
  {
    const Voxel_grid<std::uint8_t>& exterior = m_zones.exterior;
    const Voxel_grid<double>& dM = *m_dM;
    if(m_parameters.use_tsdf_guidance)
    {
      for(std::size_t v = 0; v < m_N; ++v)
        if(exterior[v] && dM[v] < sample_band * m_delta) m_exterior_band_voxels.push_back(v);
      return;
    }
    const Voxel_grid<std::uint8_t> grown = dilate<ConcurrencyTag>(complement(exterior), sample_band);
    for(std::size_t v = 0; v < m_N; ++v)
      if(exterior[v] && grown[v]) m_exterior_band_voxels.push_back(v);
  }

  // V_min, given in voxels of r_fit, in voxels of the finest grid. A volume above the grid's is
  // never reached: clamped to N + 1 voxels, the same comparisons without a cast out of the range
  // of std::size_t (undefined) for huge parameters.
  std::size_t finest_voxels(double volume, int r_fit) const
  {
    const double v = volume * std::pow(double(m_R) / double(r_fit), 3);
    return std::size_t(std::ceil((std::min)(v, double(m_N) + 1.) - 1e-9));
  }

  // Omega_valid = {R_map <= r} \ Omega_freeze (R_map = 0 inside: valid from the first stage),
  // Omega_spec = {R_map > r}, Omega_Body = Omega_valid \ claimed, and the EDT of Omega_Body.
  Stage set_up_stage(std::size_t s)
  {
    Stage st;
    st.r = m_stage_resolutions[s];
    st.r_fit = m_fitting_resolutions[s];
    st.delta_fit = 1. / double(st.r_fit);
    st.rho = m_parameters.roi_radius * st.delta_fit;
    st.flow = &m_zones.flow_zone.at(st.r_fit);
    st.flow_distance = &m_zones.flow_zone_distance.at(st.r_fit);
    st.vmin_body = finest_voxels(m_parameters.minimum_body_volume, st.r_fit);
    st.vmin_surface = finest_voxels(m_parameters.minimum_surface_volume, st.r_fit);
    const Voxel_grid<std::int32_t>& labels = m_result.labels;
    m_body_candidates.clear();
    for(std::size_t v = 0; v < m_N; ++v)
    {
      const int res = int(m_prior.leaf_resolution[v]);
      m_valid[v] = (!m_freeze[v] && res <= st.r) ? 1 : 0;
      m_spec[v] = res > st.r ? 1 : 0;
      m_body[v] = (m_valid[v] && labels[v] < 0) ? 1 : 0;
      m_excluded[v] = 0;
      st.valid_voxels += m_valid[v];
      if(m_valid[v] && labels[v] >= 0) ++st.covered_voxels;
      if(m_body[v]) m_body_candidates.push_back(v);
    }
    // in voxels^2, lowered incrementally as claims grow (A.2)
    Voxel_grid<std::uint8_t> not_body(m_R, 0);
    for(std::size_t v = 0; v < m_N; ++v) not_body[v] = m_body[v] ? 0 : 1;
    m_body_sqd = squared_distance_transform<ConcurrencyTag>(not_body);
    return st;
  }

  bool stage_continues(const Stage& st) const
  {
    const std::size_t seed_limit =
      seeds_per_primitive * (std::max<std::size_t>)(m_parameters.maximum_number_of_primitives, 16);
    const std::size_t rejection_limit = m_parameters.maximum_rejections_in_a_row;
    return st.valid_voxels > 0 && double(st.covered_voxels) < m_parameters.coverage_target * double(st.valid_voxels) &&
           m_result.primitives.size() < m_parameters.maximum_number_of_primitives && st.seeds < seed_limit &&
           (rejection_limit == 0 || st.rejections_in_a_row < rejection_limit);
  }

  void end_stage(const Stage& st)
  {
    m_result.stage_coverage.push_back(st.valid_voxels > 0 ? double(st.covered_voxels) / double(st.valid_voxels) : 1.);
    if(m_parameters.verbose)
      std::cerr << "stage " << st.r << " (r_fit " << st.r_fit << "): coverage " << m_result.stage_coverage.back()
                << " of " << st.valid_voxels << " valid voxels, " << m_result.primitives.size() << " primitives, "
                << st.seeds << " seeds\n";
  }

  // ---- BodyOrSurfaceSeed (A.2-A.4)

  // false if no seed is left in the stage
  bool pick_seed(const Stage& st, Seed& seed)
  {
    deepest_body_voxel(seed);
    seed.body = m_parameters.use_body_seeds && seed.voxel < m_N &&
                std::sqrt(seed.depth_sqd) * m_delta >= m_parameters.body_seed_threshold * st.delta_fit;
    if(!seed.body && !surface_seed(st, seed)) return false;
    seed.ijk = m_prior.classes.coordinates(seed.voxel);
    seed.center = m_prior.classes.center(seed.voxel);
    seed.ball_sqd = (st.rho / m_delta) * (st.rho / m_delta) * (1. + 1e-12);
    return true;
  }

  // The EDT maximum of the candidates still in Omega_Body and not excluded (dropping the others).
  void deepest_body_voxel(Seed& seed)
  {
    seed.voxel = m_N;
    seed.depth_sqd = 0.;
    std::size_t kept = 0;
    for(std::size_t c = 0; c < m_body_candidates.size(); ++c)
    {
      const std::size_t v = m_body_candidates[c];
      if(!m_body[v] || m_excluded[v]) continue;
      m_body_candidates[kept++] = v;
      if(m_body_sqd[v] > seed.depth_sqd) seed.depth_sqd = m_body_sqd[v], seed.voxel = v;
    }
    m_body_candidates.resize(kept);
  }

  // The candidate nearest the centroid of the largest 6-connected component of the candidates.
  bool surface_seed(const Stage& st, Seed& seed)
  {
    Voxel_grid<std::uint8_t> open(m_R, 0);
    for(std::size_t v : m_body_candidates) open[v] = 1;
    const Grid_components comps = connected_components(open);
    std::size_t best = comps.size();
    for(std::size_t c = 0; c < comps.size(); ++c)
      if(comps.sizes[c] >= st.vmin_surface && (best == comps.size() || comps.sizes[c] > comps.sizes[best])) best = c;
    // components below V_min cannot be accepted: left to the final merge
    for(std::size_t v : m_body_candidates)
      if(best == comps.size() || comps.sizes[std::size_t(comps.labels[v])] < st.vmin_surface) m_excluded[v] = 1;
    if(best == comps.size()) return false;
    const std::array<double, 3>& g = comps.centroids[best];
    double best_d = std::numeric_limits<double>::infinity();
    for(std::size_t v : m_body_candidates)
      if(comps.labels[v] == int(best))
      {
        const std::array<int, 3> ijk = m_prior.classes.coordinates(v);
        const double d = (ijk[0] - g[0]) * (ijk[0] - g[0]) + (ijk[1] - g[1]) * (ijk[1] - g[1]) +
                         (ijk[2] - g[2]) * (ijk[2] - g[2]);
        if(d < best_d) best_d = d, seed.voxel = v;
      }
    return true;
  }

  // ---- One seed: ROI, samples, InitSQ, fit, claim, then accept or reject (Alg. A.2 lines 10-22)

  void try_seed(Stage& st, const Seed& seed)
  {
    ++st.seeds;
    ++m_result.number_of_seeds;
    if(seed.body) ++m_result.number_of_body_seeds;
    const Initial_superquadric init = m_times.time(Step_times::REGION_AND_SAMPLES, [&] {
      select_region_of_interest(st, seed);
      collect_samples(seed);
      return initial_superquadric(st, seed);
    });
    const Fit_outcome outcome = m_times.time(Step_times::FIT, [&] { return fit_in_flow_zone(st, init); });
    if(!outcome.passed)
    {
      if(outcome.degenerate) ++m_result.rejected_degenerate;
      else ++m_result.rejected_by_flow_zone;
      report_rejection(st, seed, outcome.degenerate ? "degenerate fit" : "surface leaves the Flow zone");
      reject(st, seed);
      return;
    }
    const std::size_t net = m_times.time(Step_times::CLAIM, [&] { return claim(outcome.fit.theta); });
    if(net < (seed.body ? st.vmin_body : st.vmin_surface))
    {
      ++m_result.rejected_by_volume;
      report_rejection(st, seed, "net claim below V_min");
      reject(st, seed);
      return;
    }
    m_times.time(Step_times::CLAIM, [&] { accept(st, seed, outcome); });
  }

  bool in_seed_ball(const Seed& seed, int i, int j, int k) const
  {
    const std::array<int, 3>& s = seed.ijk;
    const double d2 = double((i - s[0]) * (i - s[0]) + (j - s[1]) * (j - s[1]) + (k - s[2]) * (k - s[2]));
    return d2 <= seed.ball_sqd;
  }

  // ROI = ball(s, rho) n Omega_valid \ claimed, and in m_reached the voxels the claim may start from.
  void select_region_of_interest(const Stage& st, const Seed& seed)
  {
    m_roi_voxels.clear();
    m_reached.reset(m_N);
    if(m_parameters.use_reachable_regions) reachable_region(seed);
    else ball_region(st, seed);
  }

  // The part of the ball reachable from the seed without crossing Freeze or claimed voxels.
  void reachable_region(const Seed& seed)
  {
    const Voxel_grid<std::int32_t>& labels = m_result.labels;
    m_queue.clear();
    m_queue.push_back(seed.voxel);
    m_reached.insert(seed.voxel);
    for(std::size_t head = 0; head < m_queue.size(); ++head)
    {
      const std::size_t v = m_queue[head];
      if(m_valid[v] && labels[v] < 0) m_roi_voxels.push_back(v);
      for_each_face_neighbor(v, m_RR, [&](std::size_t n) {
        if(m_reached.contains(n) || m_freeze[n] || labels[n] >= 0) return;
        const std::array<int, 3> c = m_prior.classes.coordinates(n);
        if(!in_seed_ball(seed, c[0], c[1], c[2])) return;
        m_reached.insert(n);
        m_queue.push_back(n);
      });
    }
  }

  void ball_region(const Stage& st, const Seed& seed)
  {
    const Voxel_grid<std::int32_t>& labels = m_result.labels;
    const std::array<int, 3>& s = seed.ijk;
    const int ball = int(std::ceil((std::min)(st.rho / m_delta, 2. * m_R))); // the grid at most
    for(int k = (std::max)(0, s[2] - ball); k <= (std::min)(m_R - 1, s[2] + ball); ++k)
      for(int j = (std::max)(0, s[1] - ball); j <= (std::min)(m_R - 1, s[1] + ball); ++j)
        for(int i = (std::max)(0, s[0] - ball); i <= (std::min)(m_R - 1, s[0] + ball); ++i)
        {
          const std::size_t v = m_prior.classes.index(i, j, k);
          if(m_valid[v] && labels[v] < 0 && in_seed_ball(seed, i, j, k))
          {
            m_roi_voxels.push_back(v);
            m_reached.insert(v);
          }
        }
  }

  // P_s: ROI voxels of the band d_M < 1.5 Delta plus exterior evidence in the ball (B.1), on the
  // densest lattice (stride 1, 2 or 4) that keeps at most maximum_samples of them.
  void collect_samples(const Seed& seed)
  {
    const Voxel_grid<double>& dM = *m_dM;
    m_sample_voxels.clear();
    for(std::size_t v : m_roi_voxels)
      if(dM[v] < sample_band * m_delta) m_sample_voxels.push_back(v);
    for(std::size_t v : m_exterior_band_voxels)
    {
      const int i = int(v % m_RR), j = int((v / m_RR) % m_RR), k = int(v / (m_RR * m_RR));
      if(in_seed_ball(seed, i, j, k)) m_sample_voxels.push_back(v);
    }
    std::size_t count[3] = {0, 0, 0};
    for(std::size_t v : m_sample_voxels)
      for(int l = 0; l <= int(m_lattice_level[v]); ++l) ++count[l];
    int level = 0;
    while(level < 2 && count[level] > maximum_samples) ++level;
    m_samples.clear();
    for(std::size_t v : m_sample_voxels)
      if(int(m_lattice_level[v]) >= level)
      {
        const std::array<double, 3> c = m_prior.classes.center(v);
        m_samples.push_back(c[0], c[1], c[2], dM[v]);
      }
    m_result.number_of_samples += m_samples.size();
  }

  // InitSQ (A.5): centre s, an axis-aligned ball of radius min(Delta^{r_fit}, EDT_flow(s)); semi-axes
  // in [Delta^{r_fit}/4, rho], exponents in [1e-3, 2], centre within rho/2 of s, free rotation.
  Initial_superquadric initial_superquadric(const Stage& st, const Seed& seed) const
  {
    Initial_superquadric init;
    const std::array<double, 3>& s = seed.center;
    const double rho = st.rho;
    const double a_lower = st.delta_fit / 4., a_upper = (std::max)(rho, st.delta_fit / 4.);
    const double a0 =
      (std::min)(a_upper, (std::max)(a_lower, (std::min)(st.delta_fit, (*st.flow_distance)[seed.voxel])));
    for(int i = 0; i < 3; ++i) init.theta.a[i] = a0, init.theta.c[i] = s[i];
    const double inf = std::numeric_limits<double>::infinity();
    const double e_min = superquadric_minimum_exponent;
    init.lb << a_lower, a_lower, a_lower, e_min, e_min, -inf, -inf, -inf, s[0] - rho / 2., s[1] - rho / 2.,
      s[2] - rho / 2.;
    init.ub << a_upper, a_upper, a_upper, 2., 2., inf, inf, inf, s[0] + rho / 2., s[1] + rho / 2., s[2] + rho / 2.;
    return init;
  }

  // FitSDF with each trust-region scale eta in turn until the surface stays in the Flow zone
  // (Alg. A.2 lines 13-17, B.3).
  Fit_outcome fit_in_flow_zone(const Stage& st, const Initial_superquadric& init)
  {
    Fit_outcome out;
    for(double eta : m_parameters.trust_region_scales)
    {
      m_settings.semi_axis_scale = eta;
      out.fit = fit_sdf<ConcurrencyTag>(m_samples, init.theta, init.lb, init.ub, m_settings, m_workspace);
      m_result.number_of_solves += std::size_t(out.fit.solves);
      m_result.number_of_evaluations += std::size_t(out.fit.evaluations);
      if(!out.fit.valid)
      {
        out.degenerate = true;
        return out;
      }
      if(surface_in_flow_zone(st, out.fit.theta))
      {
        out.passed = true;
        out.eta = eta;
        return out;
      }
    }
    return out;
  }

  bool surface_in_flow_zone(const Stage& st, const Superquadric_data& theta) const
  {
    const Voxel_grid<std::uint8_t>& flow = *st.flow;
    return for_each_surface_sample(theta, surface_test_spacing * m_delta, [&](const double p[3]) {
      for(int l = 0; l < 3; ++l)
        if(!(p[l] >= -0.5 && p[l] <= 0.5)) return false;
      const std::size_t v = m_prior.classes.index(voxel_coordinate(p[0], m_R), voxel_coordinate(p[1], m_R),
                                                  voxel_coordinate(p[2], m_R));
      return flow[v] != 0;
    });
  }

  // ---- Claim: M_fit = {d~ <= 2 Delta} minus Freeze and claimed voxels, kept where connected to
  // the seed's region; returns the net volume, without the voxels reserved for finer stages (B.3).
  std::size_t claim(const Superquadric_data& theta)
  {
    const Voxel_grid<std::int32_t>& labels = m_result.labels;
    m_claim.clear();
    m_claim_mark.reset(m_N);
    for_each_voxel_within(theta, m_R, claim_band * m_delta, [&](int, int, int, std::size_t v) {
      if(!m_freeze[v] && labels[v] < 0)
      {
        m_claim.push_back(v);
        m_claim_mark.insert(v);
      }
    });
    if(m_parameters.use_reachable_regions) keep_claim_connected_to_region();
    std::size_t net = 0;
    for(std::size_t v : m_claim) net += m_spec[v] ? 0 : 1;
    return net;
  }

  // A claim never jumps across a Freeze wall: keep its voxels connected to the reachable region.
  void keep_claim_connected_to_region()
  {
    m_queue.clear();
    m_kept.reset(m_N);
    for(std::size_t v : m_claim)
      if(m_reached.contains(v))
      {
        m_kept.insert(v);
        m_queue.push_back(v);
      }
    for(std::size_t head = 0; head < m_queue.size(); ++head)
      for_each_face_neighbor(m_queue[head], m_RR, [&](std::size_t n) {
        if(m_claim_mark.contains(n) && !m_kept.contains(n))
        {
          m_kept.insert(n);
          m_queue.push_back(n);
        }
      });
    std::size_t m = 0;
    for(std::size_t v : m_claim)
      if(m_kept.contains(v)) m_claim[m++] = v;
    m_claim.resize(m);
  }

  // ---- Accept (claimed voxels include reserved voxels of finer stages, Alg. A.2 line 22) or reject

  void accept(Stage& st, const Seed& seed, const Fit_outcome& outcome)
  {
    Voxel_grid<std::int32_t>& labels = m_result.labels;
    const std::int32_t label = std::int32_t(m_result.primitives.size());
    m_new_body_features.clear();
    for(std::size_t v : m_claim)
    {
      labels[v] = label;
      if(m_valid[v]) ++st.covered_voxels;
      if(m_body[v])
      {
        m_body[v] = 0;
        m_new_body_features.push_back(v);
      }
    }
    m_excluded[seed.voxel] = 1;
    st.rejections_in_a_row = 0;
    add_features_to_squared_distance_transform<ConcurrencyTag>(m_body_sqd, m_new_body_features);
    record_primitive(st, seed, outcome);
  }

  void record_primitive(const Stage& st, const Seed& seed, const Fit_outcome& outcome)
  {
    const Superquadric_data& q = outcome.fit.theta;
    const Superquadric<GeomTraits> sq(q);
    if(m_parameters.verbose)
      std::cerr << "  SQ " << m_result.primitives.size() << " stage " << st.r << (seed.body ? " body" : " surface")
                << " seed " << seed.voxel << " a = (" << q.a[0] << ", " << q.a[1] << ", " << q.a[2] << ") eps = ("
                << q.e1 << ", " << q.e2 << ") eta " << outcome.eta << " claim " << m_claim.size() << " samples "
                << m_samples.size() << "\n";
    m_result.primitives.push_back(sq);
    m_result.input_primitives.push_back(sq.in_input_coordinates(m_prior.normalization));
    m_result.stage_resolution.push_back(st.r);
    m_result.body_seeded.push_back(seed.body);
    m_result.seed_voxel.push_back(seed.voxel);
    m_result.semi_axis_scale.push_back(outcome.eta);
    m_result.fit_cost.push_back(outcome.fit.cost);
  }

  void report_rejection(const Stage& st, const Seed& seed, const char* reason) const
  {
    if(m_parameters.verbose)
      std::cerr << "  rejected: stage " << st.r << (seed.body ? " body" : " surface") << " seed " << seed.voxel
                << ", ROI of " << m_roi_voxels.size() << " voxels: " << reason << "\n";
  }

  // Excludes the seed from later seeds of the stage and, with seed exclusion, the ball around it
  // (seeds near it would start from the same place and see nearly the same region): a body seed's
  // inscribed ball, or a surface seed's half-ROI ball (the rest of its component is seeded again).
  void reject(Stage& st, const Seed& seed)
  {
    ++m_result.number_of_rejected_seeds;
    ++st.rejections_in_a_row;
    if(m_parameters.use_seed_exclusion)
      exclude_ball(seed.ijk, seed.body ? (std::max)(1., std::sqrt(seed.depth_sqd))
                                       : (std::max)(1., (surface_exclusion * st.rho) / m_delta));
    m_excluded[seed.voxel] = 1;
  }

  void exclude_ball(const std::array<int, 3>& s, double radius)
  {
    // a ball wider than the grid covers it all: the loop bound is clamped before the cast
    const int ir = int(std::floor((std::min)(radius, 2. * m_R)));
    for(int k = (std::max)(0, s[2] - ir); k <= (std::min)(m_R - 1, s[2] + ir); ++k)
      for(int j = (std::max)(0, s[1] - ir); j <= (std::min)(m_R - 1, s[1] + ir); ++j)
        for(int i = (std::max)(0, s[0] - ir); i <= (std::min)(m_R - 1, s[0] + ir); ++i)
        {
          const double d2 = double((i - s[0]) * (i - s[0]) + (j - s[1]) * (j - s[1]) + (k - s[2]) * (k - s[2]));
          if(d2 <= radius * radius) m_excluded[m_prior.classes.index(i, j, k)] = 1;
        }
  }

  // ---- Small residual regions merged into the nearest primitive: unclaimed, non-Freeze components
  // of the hull smaller than V_min (surface, last stage) take the label of the nearest claimed voxel,
  // by a breadth-first search from all claimed voxels through the hull (6-neighbour steps; ties go
  // to the voxel reached first from the lowest claimed index).
  void merge_small_residual_regions()
  {
    Voxel_grid<std::int32_t>& labels = m_result.labels;
    if(m_result.primitives.empty()) return;
    const int r_fit_last = m_fitting_resolutions.empty() ? m_R : m_fitting_resolutions.back();
    const std::size_t vmin = finest_voxels(m_parameters.minimum_surface_volume, r_fit_last);
    Voxel_grid<std::uint8_t> residual(m_R, 0);
    for(std::size_t v = 0; v < m_N; ++v) residual[v] = (!m_freeze[v] && labels[v] < 0) ? 1 : 0;
    const Grid_components comps = connected_components(residual);
    auto is_target = [&](std::size_t v) {
      return residual[v] && comps.sizes[std::size_t(comps.labels[v])] < vmin;
    };
    std::size_t targets = 0;
    for(std::size_t v = 0; v < m_N; ++v)
      if(is_target(v)) ++targets;
    if(targets == 0) return;
    std::vector<std::int32_t> reached(labels.values());
    m_queue.clear();
    for(std::size_t v = 0; v < m_N; ++v)
      if(labels[v] >= 0) m_queue.push_back(v);
    for(std::size_t head = 0; head < m_queue.size() && targets > 0; ++head)
    {
      const std::size_t v = m_queue[head];
      for_each_face_neighbor(v, m_RR, [&](std::size_t n) {
        if(reached[n] >= 0 || m_zones.exterior[n]) return;
        reached[n] = reached[v];
        m_queue.push_back(n);
        if(is_target(n))
        {
          labels[n] = reached[v];
          ++m_result.merged_voxels;
          --targets;
        }
      });
    }
  }

  void collect_claimed_voxels()
  {
    const Voxel_grid<std::int32_t>& labels = m_result.labels;
    m_result.claimed_voxels.assign(m_result.primitives.size(), std::vector<std::size_t>());
    for(std::size_t v = 0; v < m_N; ++v)
      if(labels[v] >= 0) m_result.claimed_voxels[std::size_t(labels[v])].push_back(v);
  }

  void report_times() const
  {
    typedef Step_times T;
    std::cerr << "time (ms): stage setup " << m_times.milliseconds(T::STAGE_SETUP) << ", seeds "
              << m_times.milliseconds(T::SEED) << ", ROI/samples " << m_times.milliseconds(T::REGION_AND_SAMPLES)
              << ", FitSDF and Flow-zone test " << m_times.milliseconds(T::FIT) << ", claims "
              << m_times.milliseconds(T::CLAIM) << ", merge " << m_times.milliseconds(T::MERGE) << ", total "
              << 1e3 * m_result.seconds << "; " << m_result.number_of_seeds << " seeds, "
              << m_result.number_of_solves << " solves, " << m_result.number_of_evaluations << " evaluations of "
              << m_result.number_of_samples << " samples\n";
  }

  // inputs
  const Hierarchical_prior& m_prior;
  const Truncated_signed_distance_field& m_tsdf;
  const Fitting_zones& m_zones;
  const std::vector<int>& m_stage_resolutions;
  const std::vector<int>& m_fitting_resolutions;
  const Fitting_parameters m_parameters;
  const int m_R;
  const std::size_t m_N, m_RR;
  const double m_delta; // Delta of the finest grid
  const Voxel_grid<std::uint8_t>& m_freeze; // the Freeze zone, or the exterior without it

  // fields of the run
  Voxel_grid<double> m_binary_field;          // d_M without TSDF guidance
  const Voxel_grid<double>* m_dM = nullptr;   // d_M as the fit sees it
  std::vector<std::size_t> m_exterior_band_voxels;
  std::vector<std::uint8_t> m_lattice_level;  // 2 on the stride-4 lattice, 1 on stride 2, else 0
  Fit_sdf_settings m_settings;

  // sets of the current stage
  std::vector<std::uint8_t> m_valid, m_spec, m_body, m_excluded;
  std::vector<std::size_t> m_body_candidates; // Omega_Body voxels not yet excluded (compacted lazily)
  Voxel_grid<double> m_body_sqd;              // squared EDT of Omega_Body, in voxels^2

  // buffers of the current seed
  Stamp_set m_reached;                        // voxels of the seed's region
  std::vector<std::size_t> m_roi_voxels, m_sample_voxels;
  Fit_samples m_samples;
  Fit_sdf_workspace m_workspace;
  std::vector<std::size_t> m_claim;
  Stamp_set m_claim_mark, m_kept;             // M_fit candidates; those connected to the region
  std::vector<std::size_t> m_new_body_features; // voxels that left Omega_Body with an acceptance
  std::vector<std::size_t> m_queue;           // breadth-first searches

  Result m_result;
  Step_times m_times;
};

} // namespace internal
} // namespace Part_decomposition
} // namespace CGAL

#endif // CGAL_PART_DECOMPOSITION_INTERNAL_SUPERQUADRIC_FITTER_H
