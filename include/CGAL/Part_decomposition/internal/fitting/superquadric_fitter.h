// Copyright (c) 2026 The Part_decomposition authors.
// All rights reserved.
//
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Author(s)     : The Part_decomposition authors

#ifndef CGAL_PART_DECOMPOSITION_INTERNAL_SUPERQUADRIC_FITTER_H
#define CGAL_PART_DECOMPOSITION_INTERNAL_SUPERQUADRIC_FITTER_H

// SDFSQFit (paper Alg. A.2): the coarse-to-fine loop of seeds, fits, claims and rejections behind
// fit_superquadrics(), one method per step of the algorithm, on the leaves of the adaptive grid of
// the distance field. Volumes, coverage and sample weights are leaf volumes; distances are
// between leaf centres; lengths are in normalized units, Delta being the side of the finest
// leaves.

#include <CGAL/Part_decomposition/internal/fitting/fit_sdf.h>
#include <CGAL/Part_decomposition/internal/grid/leaf_distance.h>
#include <CGAL/Part_decomposition/internal/fitting/superquadric_distance.h>
#include <CGAL/Part_decomposition/internal/fitting/superquadric_leaves.h>
#include <CGAL/Part_decomposition/internal/toolbox/toolbox.h>

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

// `Types` names the types of the stage (see Fitting_types in superquadric_fitting.h): `Result`
// (Superquadric_fitting_result), `Prior` (Hierarchical_prior), `Field`
// (Truncated_signed_distance_field), `Zones` (Fitting_zones) and `Parameters` (Fitting_parameters).
template <typename ConcurrencyTag, typename Types>
class Superquadric_fitter
{
public:
  typedef typename Types::Result Result;
  typedef typename Types::Prior Prior;
  typedef typename Types::Field Field;
  typedef typename Types::Zones Zones;
  typedef typename Types::Parameters Parameters;
  typedef typename decltype(Result::primitives)::value_type Primitive; // a Superquadric
  typedef decltype(Field::grid) Grid;                                  // the Adaptive_grid

  // `fitting_resolutions`: r_fit of each stage of `prior.resolutions`; `zones` holds each of them.
  Superquadric_fitter(const Prior& prior, const Field& tsdf, const Zones& zones,
                      const std::vector<int>& fitting_resolutions, const Parameters& parameters)
    : m_prior(prior), m_tsdf(tsdf), m_grid(tsdf.grid), m_zones(zones), m_stage_resolutions(prior.resolutions),
      m_fitting_resolutions(fitting_resolutions), m_parameters(parameters), m_N(tsdf.grid.number_of_leaves()),
      m_delta(1. / double(tsdf.grid.finest_resolution())),
      m_freeze(parameters.use_freeze_zone ? zones.freeze_zone : zones.exterior),
      m_sample_voxel(1. / double(prior.resolutions.back()))
  {
    m_result.normalization = prior.normalization;
    m_result.labels.assign(m_N, -1);
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
      collect_claimed_leaves();
    });
    m_result.seconds = seconds_since(start);
    if(m_parameters.verbose) report_times();
    return std::move(m_result);
  }

private:
  // Fixed choices, not parameters:
  // - samples above this count are taken on a lattice of stride 2 or 4: bounds the cost of a solve;
  static constexpr std::size_t maximum_samples = 4096;
  // - spacing of the Flow-zone test samples, in voxels of the finest prior resolution (the zone
  //   tolerance is >= 2 of them);
  static constexpr double surface_test_spacing = 1.;
  // - a rejected surface seed excludes this fraction of rho: the rest of its component is seeded again;
  static constexpr double surface_exclusion = 0.5;
  // - relative gain below which a solve stops: scipy's default ftol;
  static constexpr double function_tolerance = 1e-8;
  // - the sample band d_M < 1.5 Delta and M_fit = {d~ <= 2 Delta} (paper B.1, B.3);
  static constexpr double sample_band = 1.5;
  static constexpr double claim_band = 2.;
  // - a stage tries at most this many seeds per allowed primitive (at least 16 primitives): a
  //   safety bound for when rejections in a row never end it.
  static constexpr std::size_t seeds_per_primitive = 16;

  struct Stage
  {
    int r = 0, r_fit = 0;
    double delta_fit = 0., rho = 0.; // Delta^{r_fit} and the ROI radius, normalized units
    const std::vector<std::uint8_t>* flow = nullptr;
    double vmin_body = 0., vmin_surface = 0.; // normalized volumes
    double valid_volume = 0., covered_volume = 0.;
    std::size_t seeds = 0, rejections_in_a_row = 0;
  };

  struct Seed
  {
    std::size_t leaf = 0;
    bool body = false;
    double depth_sqd = 0.; // the largest squared distance to the outside of Omega_Body (a body seed's own)
    std::array<double, 3> center = {{0., 0., 0.}};
    double ball_sqd = 0.; // squared ROI radius
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
      m_binary_field.assign(m_N, tau);
      for(std::size_t l = 0; l < m_N; ++l) m_binary_field[l] = m_zones.exterior[l] ? tau : -tau;
    }
    m_dM = m_parameters.use_tsdf_guidance ? &m_tsdf.values : &m_binary_field;
    if(m_parameters.use_exterior_band_samples) collect_exterior_band();
    set_lattice_levels();
    prepare_hull_distances();
    m_excluded.assign(m_N, 0);
    m_valid.assign(m_N, 0);
    m_spec.assign(m_N, 0);
    m_body.assign(m_N, 0);
    m_settings.truncation = tau;
    m_settings.exterior_penalty = m_parameters.exterior_penalty;
    typedef decltype(m_parameters.interior_weight_mode) Weight_mode;
    m_settings.reestimate_variance = m_parameters.interior_weight_mode == Weight_mode::MPS_REESTIMATED;
    m_settings.maximum_evaluations = m_parameters.maximum_solver_evaluations;
    m_settings.function_tolerance = function_tolerance;
  }

  // The distance from the centre of each exterior leaf larger than Delta to the nearest centre of
  // the hull (the leaves that are not exterior), for the Flow-zone test at points.
  void prepare_hull_distances()
  {
    auto coarse = [&](std::size_t l) { return m_zones.exterior[l] && m_grid.size(l) > m_delta * (1. + 1e-9); };
    m_hull.template build<ConcurrencyTag>(m_grid, [&](std::size_t l) { return m_zones.exterior[l] == 0; });
    m_hull_sqd = leaf_squared_distances<ConcurrencyTag>(
      m_grid, [&](std::size_t l) { return m_zones.exterior[l] == 0; }, coarse);
  }

  // Per leaf, the coarsest of the lattices of Delta, 2 Delta, 4 Delta (0, 1, 2) its smallest corner
  // lies on, -1 for a leaf finer than Delta off the lattice of Delta.
  void set_lattice_levels()
  {
    const int shift = Grid::depth_of(m_grid.finest_resolution()) - Grid::depth_of(int(std::lround(1. / m_sample_voxel)));
    const std::uint32_t finer = (std::uint32_t(1) << shift) - 1;
    m_lattice_level.assign(m_N, 0);
    for(std::size_t l = 0; l < m_N; ++l)
    {
      const typename Grid::Voxel& c = m_grid.corner(l);
      const std::uint32_t fine = (c[0] | c[1] | c[2]) & finer, o = (c[0] | c[1] | c[2]) >> shift;
      m_lattice_level[l] = fine != 0 ? -1 : ((o & 3) == 0 ? 2 : ((o & 1) == 0 ? 1 : 0));
    }
  }

  // Exterior evidence: ext_void leaves of the thin outer band, which the ROI (ball minus the
  // Freeze zone) would otherwise drop; they are sampled but never claimed.
  void collect_exterior_band()
  {
    const std::vector<std::uint8_t>& exterior = m_zones.exterior;
    const std::vector<double>& dM = *m_dM;
    if(m_parameters.use_tsdf_guidance)
    {
      for(std::size_t l = 0; l < m_N; ++l)
        if(exterior[l] && dM[l] < sample_band * m_delta) m_exterior_band_leaves.push_back(l);
      return;
    }
    const double band2 = sample_band * m_delta * sample_band * m_delta * (1. + 1e-12);
    const std::vector<double> d2 = leaf_squared_distances<ConcurrencyTag>(
      m_grid, [&](std::size_t l) { return exterior[l] == 0; }, [&](std::size_t l) { return exterior[l] != 0; });
    for(std::size_t l = 0; l < m_N; ++l)
      if(exterior[l] && d2[l] <= band2) m_exterior_band_leaves.push_back(l);
  }

  // A volume given in voxels of r_fit, in normalized units.
  static double volume_of_voxels(double voxels, int r_fit) { return voxels / std::pow(double(r_fit), 3); }

  // Omega_valid = {R_map <= r} \ Omega_freeze (R_map = 0 inside: valid from the first stage),
  // Omega_spec = {R_map > r}, Omega_Body = Omega_valid \ claimed, and the distances of Omega_Body
  // to its outside.
  Stage set_up_stage(std::size_t s)
  {
    Stage st;
    st.r = m_stage_resolutions[s];
    st.r_fit = m_fitting_resolutions[s];
    st.delta_fit = 1. / double(st.r_fit);
    st.rho = m_parameters.roi_radius * st.delta_fit;
    st.flow = &m_zones.flow_zone.at(st.r_fit);
    st.vmin_body = volume_of_voxels(m_parameters.minimum_body_volume, st.r_fit);
    st.vmin_surface = volume_of_voxels(m_parameters.minimum_surface_volume, st.r_fit);
    const std::vector<std::int32_t>& labels = m_result.labels;
    m_body_candidates.clear();
    for(std::size_t l = 0; l < m_N; ++l)
    {
      const int res = int(m_zones.leaf_resolution[l]);
      m_valid[l] = (!m_freeze[l] && res <= st.r) ? 1 : 0;
      m_spec[l] = res > st.r ? 1 : 0;
      m_body[l] = (m_valid[l] && labels[l] < 0) ? 1 : 0;
      m_excluded[l] = 0;
      if(m_valid[l]) st.valid_volume += m_grid.volume(l);
      if(m_valid[l] && labels[l] >= 0) st.covered_volume += m_grid.volume(l);
      if(m_body[l]) m_body_candidates.push_back(l);
    }
    // lowered incrementally as claims grow (A.2)
    m_body_sqd = leaf_squared_distances<ConcurrencyTag>(
      m_grid, [&](std::size_t l) { return m_body[l] == 0; }, [&](std::size_t l) { return m_body[l] != 0; });
    m_flow_outside.template build<ConcurrencyTag>(m_grid, [&](std::size_t l) { return (*st.flow)[l] == 0; }, true);
    return st;
  }

  bool stage_continues(const Stage& st) const
  {
    const std::size_t seed_limit =
      seeds_per_primitive * (std::max<std::size_t>)(m_parameters.maximum_number_of_primitives, 16);
    const std::size_t rejection_limit = m_parameters.maximum_rejections_in_a_row;
    return st.valid_volume > 0. && st.covered_volume < m_parameters.coverage_target * st.valid_volume &&
           m_result.primitives.size() < m_parameters.maximum_number_of_primitives && st.seeds < seed_limit &&
           (rejection_limit == 0 || st.rejections_in_a_row < rejection_limit);
  }

  void end_stage(const Stage& st)
  {
    m_result.stage_coverage.push_back(st.valid_volume > 0. ? st.covered_volume / st.valid_volume : 1.);
    if(m_parameters.verbose)
      std::cerr << "stage " << st.r << " (r_fit " << st.r_fit << "): coverage " << m_result.stage_coverage.back()
                << " of a valid volume of " << st.valid_volume << ", " << m_result.primitives.size()
                << " primitives, " << st.seeds << " seeds\n";
  }

  // ---- BodyOrSurfaceSeed (A.2-A.4)

  // false if no seed is left in the stage
  bool pick_seed(const Stage& st, Seed& seed)
  {
    deepest_body_leaf(seed);
    seed.body = m_parameters.use_body_seeds && seed.leaf < m_N &&
                std::sqrt(seed.depth_sqd) >= m_parameters.body_seed_threshold * st.delta_fit;
    if(!seed.body && !surface_seed(st, seed)) return false;
    seed.center = m_grid.center(seed.leaf);
    seed.ball_sqd = st.rho * st.rho * (1. + 1e-12);
    return true;
  }

  // The deepest of the candidates still in Omega_Body and not excluded (dropping the others).
  void deepest_body_leaf(Seed& seed)
  {
    seed.leaf = m_N;
    seed.depth_sqd = 0.;
    std::size_t kept = 0;
    for(std::size_t c = 0; c < m_body_candidates.size(); ++c)
    {
      const std::size_t l = m_body_candidates[c];
      if(!m_body[l] || m_excluded[l]) continue;
      m_body_candidates[kept++] = l;
      if(m_body_sqd[l] > seed.depth_sqd) seed.depth_sqd = m_body_sqd[l], seed.leaf = l;
    }
    m_body_candidates.resize(kept);
  }

  // The candidate nearest the centroid of the largest 6-connected component of the candidates.
  bool surface_seed(const Stage& st, Seed& seed)
  {
    m_candidate_mark.reset(m_N);
    for(std::size_t l : m_body_candidates) m_candidate_mark.insert(l);
    const Leaf_components comps =
      leaf_components(m_grid, [&](std::size_t l) { return m_candidate_mark.contains(l); }, &m_body_candidates);
    std::size_t best = comps.size();
    for(std::size_t c = 0; c < comps.size(); ++c)
      if(comps.volumes[c] >= st.vmin_surface && (best == comps.size() || comps.volumes[c] > comps.volumes[best])) best = c;
    // components below V_min cannot be accepted: left to the final merge
    for(std::size_t l : m_body_candidates)
      if(best == comps.size() || comps.volumes[std::size_t(comps.labels[l])] < st.vmin_surface) m_excluded[l] = 1;
    if(best == comps.size()) return false;
    const std::array<double, 3>& g = comps.centroids[best];
    double best_d = std::numeric_limits<double>::infinity();
    for(std::size_t l : m_body_candidates)
      if(comps.labels[l] == int(best))
      {
        const std::array<double, 3> c = m_grid.center(l);
        const double d = (c[0] - g[0]) * (c[0] - g[0]) + (c[1] - g[1]) * (c[1] - g[1]) + (c[2] - g[2]) * (c[2] - g[2]);
        if(d < best_d) best_d = d, seed.leaf = l;
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
    const double net = m_times.time(Step_times::CLAIM, [&] { return claim(outcome.fit.theta); });
    if(net < (seed.body ? st.vmin_body : st.vmin_surface) * (1. - 1e-9))
    {
      ++m_result.rejected_by_volume;
      report_rejection(st, seed, "net claim below V_min");
      reject(st, seed);
      return;
    }
    m_times.time(Step_times::CLAIM, [&] { accept(st, seed, outcome); });
  }

  bool in_seed_ball(const Seed& seed, std::size_t l) const
  {
    const std::array<double, 3> c = m_grid.center(l);
    const double d2 = (c[0] - seed.center[0]) * (c[0] - seed.center[0]) + (c[1] - seed.center[1]) * (c[1] - seed.center[1]) +
                      (c[2] - seed.center[2]) * (c[2] - seed.center[2]);
    return d2 <= seed.ball_sqd;
  }

  // ROI = ball(s, rho) n Omega_valid \ claimed, and in m_reached the leaves the claim may start from.
  void select_region_of_interest(const Stage& st, const Seed& seed)
  {
    m_roi_leaves.clear();
    m_reached.reset(m_N);
    if(m_parameters.use_reachable_regions) reachable_region(seed);
    else ball_region(st, seed);
  }

  // The part of the ball reachable from the seed without crossing Freeze or claimed leaves.
  void reachable_region(const Seed& seed)
  {
    const std::vector<std::int32_t>& labels = m_result.labels;
    m_queue.clear();
    m_queue.push_back(seed.leaf);
    m_reached.insert(seed.leaf);
    for(std::size_t head = 0; head < m_queue.size(); ++head)
    {
      const std::size_t l = m_queue[head];
      if(m_valid[l] && labels[l] < 0) m_roi_leaves.push_back(l);
      m_grid.for_each_neighbor(l, [&](std::size_t n) {
        if(m_reached.contains(n) || m_freeze[n] || labels[n] >= 0 || !in_seed_ball(seed, n)) return;
        m_reached.insert(n);
        m_queue.push_back(n);
      });
    }
  }

  void ball_region(const Stage& st, const Seed& seed)
  {
    const std::vector<std::int32_t>& labels = m_result.labels;
    const std::array<double, 3>& s = seed.center;
    m_grid.for_each_leaf_in_box({{s[0] - st.rho, s[1] - st.rho, s[2] - st.rho}},
                                {{s[0] + st.rho, s[1] + st.rho, s[2] + st.rho}}, [&](std::size_t l) {
                                  if(m_valid[l] && labels[l] < 0 && in_seed_ball(seed, l)) m_roi_leaves.push_back(l);
                                });
    std::sort(m_roi_leaves.begin(), m_roi_leaves.end());
    for(std::size_t l : m_roi_leaves) m_reached.insert(l);
  }

  // P_s: ROI leaves of the band d_M < 1.5 Delta plus exterior evidence in the ball (B.1), on the
  // densest lattice (stride 1, 2 or 4 voxels of Delta) that keeps at most maximum_samples of them;
  // each stands for its volume, or the lattice cell's if that is larger, in lattice cells (the
  // solver is not quite invariant under a common scale of the weights).
  void collect_samples(const Seed& seed)
  {
    const std::vector<double>& dM = *m_dM;
    m_sample_leaves.clear();
    for(std::size_t l : m_roi_leaves)
      if(dM[l] < sample_band * m_delta) m_sample_leaves.push_back(l);
    for(std::size_t l : m_exterior_band_leaves)
      if(in_seed_ball(seed, l)) m_sample_leaves.push_back(l);
    std::size_t count[3] = {0, 0, 0};
    for(std::size_t l : m_sample_leaves)
      for(int level = 0; level <= int(m_lattice_level[l]); ++level) ++count[level];
    int level = 0;
    while(level < 2 && count[level] > maximum_samples) ++level;
    const double voxel_volume = std::pow(m_sample_voxel, 3), cell = std::pow(double(1 << level), 3);
    m_samples.clear();
    for(std::size_t l : m_sample_leaves)
      if(int(m_lattice_level[l]) >= level)
      {
        const std::array<double, 3> c = m_grid.center(l);
        const double volume = m_grid.volume(l) / voxel_volume;
        m_samples.push_back(c[0], c[1], c[2], dM[l], (std::max)(volume, cell) / cell);
      }
    m_result.number_of_samples += m_samples.size();
  }

  // InitSQ (A.5): centre s, an axis-aligned ball of radius min(Delta^{r_fit}, EDT_flow(s)), or the
  // side of a body seed's leaf if larger; semi-axes in [Delta^{r_fit}/4, rho], exponents in
  // [1e-3, 2], centre within rho/2 of s, free rotation.
  Initial_superquadric initial_superquadric(const Stage& st, const Seed& seed) const
  {
    Initial_superquadric init;
    const std::array<double, 3>& s = seed.center;
    const double rho = st.rho;
    const double a_lower = st.delta_fit / 4., a_upper = (std::max)(rho, st.delta_fit / 4.);
    const double to_outside = (*st.flow)[seed.leaf] ? std::sqrt(m_flow_outside.squared_distance(seed.leaf)) : 0.;
    // A ball smaller than the seed's leaf holds no other sample: the residuals of the samples
    // outside it are clipped and the fit would not move. It reaches the neighbouring leaves'
    // centres, within the seed's depth.
    const double reach = (std::min)(m_grid.size(seed.leaf) * (1. + 1e-9), seed.body ? std::sqrt(seed.depth_sqd) : 0.);
    const double a0 = (std::min)(a_upper, (std::max)(a_lower, (std::max)((std::min)(st.delta_fit, to_outside), reach)));
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
    return for_each_surface_sample(theta, surface_test_spacing * m_sample_voxel, [&](const double p[3]) {
      for(int l = 0; l < 3; ++l)
        if(!(p[l] >= -0.5 && p[l] <= 0.5)) return false;
      return in_flow_zone(st, p);
    });
  }

  // Whether the point p is in the Flow zone: in a leaf of the zone no larger than Delta, as the
  // zone is defined at leaf centres; in a larger exterior leaf, if p itself lies within the
  // tolerance of a centre of the hull (a leaf is not the unit of the test where it is coarse).
  bool in_flow_zone(const Stage& st, const double p[3]) const
  {
    const std::size_t l = m_grid.locate(p[0], p[1], p[2]);
    if(!m_zones.exterior[l] || m_grid.size(l) <= m_delta * (1. + 1e-9)) return (*st.flow)[l] != 0;
    const double radius = m_parameters.flow_zone_tolerance * st.delta_fit, reach = 0.5 * std::sqrt(3.) * m_grid.size(l);
    const double d = std::sqrt(m_hull_sqd[l]);
    if(d + reach <= radius) return true;
    if(d - reach > radius) return false;
    const std::array<double, 3> q = {{p[0], p[1], p[2]}};
    return m_hull.nearest(q).second <= radius * radius * (1. + 1e-12);
  }

  // ---- Claim: M_fit = {d~ <= 2 Delta} minus Freeze and claimed leaves, kept where connected to
  // the seed's region; returns the net volume, without the leaves reserved for finer stages (B.3).
  double claim(const Superquadric_data& theta)
  {
    const std::vector<std::int32_t>& labels = m_result.labels;
    m_claim.clear();
    m_claim_mark.reset(m_N);
    for_each_leaf_within(theta, m_grid, claim_band * m_delta, [&](std::size_t l) {
      if(!m_freeze[l] && labels[l] < 0)
      {
        m_claim.push_back(l);
        m_claim_mark.insert(l);
      }
    });
    std::sort(m_claim.begin(), m_claim.end());
    if(m_parameters.use_reachable_regions) keep_claim_connected_to_region();
    double net = 0.;
    for(std::size_t l : m_claim) net += m_spec[l] ? 0. : m_grid.volume(l);
    // a leaf is claimed whole by its centre: a small primitive among coarse leaves claims no more
    // than the volume within the band of it
    Superquadric_data grown = theta;
    for(int a = 0; a < 3; ++a) grown.a[a] += claim_band * m_delta;
    return (std::min)(net, Primitive(grown).volume());
  }

  // A claim never jumps across a Freeze wall: keep its leaves connected to the reachable region.
  void keep_claim_connected_to_region()
  {
    m_queue.clear();
    m_kept.reset(m_N);
    for(std::size_t l : m_claim)
      if(m_reached.contains(l))
      {
        m_kept.insert(l);
        m_queue.push_back(l);
      }
    for(std::size_t head = 0; head < m_queue.size(); ++head)
      m_grid.for_each_neighbor(m_queue[head], [&](std::size_t n) {
        if(m_claim_mark.contains(n) && !m_kept.contains(n))
        {
          m_kept.insert(n);
          m_queue.push_back(n);
        }
      });
    std::size_t m = 0;
    for(std::size_t l : m_claim)
      if(m_kept.contains(l)) m_claim[m++] = l;
    m_claim.resize(m);
  }

  // ---- Accept (claimed leaves include reserved leaves of finer stages, Alg. A.2 line 22) or reject

  void accept(Stage& st, const Seed& seed, const Fit_outcome& outcome)
  {
    std::vector<std::int32_t>& labels = m_result.labels;
    const std::int32_t label = std::int32_t(m_result.primitives.size());
    m_new_body_features.clear();
    for(std::size_t l : m_claim)
    {
      labels[l] = label;
      if(m_valid[l]) st.covered_volume += m_grid.volume(l);
      if(m_body[l])
      {
        m_body[l] = 0;
        m_new_body_features.push_back(l);
      }
    }
    m_excluded[seed.leaf] = 1;
    st.rejections_in_a_row = 0;
    lower_body_distances();
    record_primitive(st, seed, outcome);
  }

  // The candidates' distances to the outside of Omega_Body after the leaves of
  // m_new_body_features left it: only those nearer the box of the new leaves than their distance
  // can change.
  void lower_body_distances()
  {
    if(m_new_body_features.empty()) return;
    std::array<double, 3> lo, hi;
    lo.fill(std::numeric_limits<double>::infinity());
    hi.fill(-std::numeric_limits<double>::infinity());
    for(std::size_t l : m_new_body_features)
    {
      const std::array<double, 3> c = m_grid.center(l);
      for(int a = 0; a < 3; ++a) lo[a] = (std::min)(lo[a], c[a]), hi[a] = (std::max)(hi[a], c[a]);
    }
    m_affected.clear();
    for(std::size_t l : m_body_candidates)
    {
      if(!m_body[l]) continue;
      const std::array<double, 3> c = m_grid.center(l);
      double d2 = 0.;
      for(int a = 0; a < 3; ++a)
      {
        const double e = (std::max)((std::max)(lo[a] - c[a], c[a] - hi[a]), 0.);
        d2 += e * e;
      }
      if(d2 < m_body_sqd[l]) m_affected.push_back(l);
    }
    if(m_affected.empty()) return;
    Leaf_feature_search<Grid> added;
    added.template build_on<ConcurrencyTag>(m_grid, m_new_body_features);
    for_each_range<ConcurrencyTag>(m_affected.size(), [&](std::size_t b, std::size_t e) {
      for(std::size_t i = b; i < e; ++i)
      {
        const std::size_t l = m_affected[i];
        m_body_sqd[l] = (std::min)(m_body_sqd[l], added.squared_distance(l));
      }
    }, 256);
  }

  void record_primitive(const Stage& st, const Seed& seed, const Fit_outcome& outcome)
  {
    const Superquadric_data& q = outcome.fit.theta;
    const Primitive sq(q);
    if(m_parameters.verbose)
      std::cerr << "  SQ " << m_result.primitives.size() << " stage " << st.r << (seed.body ? " body" : " surface")
                << " seed " << seed.leaf << " a = (" << q.a[0] << ", " << q.a[1] << ", " << q.a[2] << ") eps = ("
                << q.e1 << ", " << q.e2 << ") eta " << outcome.eta << " claim " << m_claim.size() << " leaves, samples "
                << m_samples.size() << "\n";
    m_result.primitives.push_back(sq);
    m_result.input_primitives.push_back(sq.in_input_coordinates(m_prior.normalization));
    m_result.stage_resolution.push_back(st.r);
    m_result.body_seeded.push_back(seed.body);
    m_result.seed_leaf.push_back(seed.leaf);
    m_result.semi_axis_scale.push_back(outcome.eta);
    m_result.fit_cost.push_back(outcome.fit.cost);
  }

  void report_rejection(const Stage& st, const Seed& seed, const char* reason) const
  {
    if(m_parameters.verbose)
      std::cerr << "  rejected: stage " << st.r << (seed.body ? " body" : " surface") << " seed " << seed.leaf
                << ", ROI of " << m_roi_leaves.size() << " leaves: " << reason << "\n";
  }

  // Excludes the seed from later seeds of the stage and, with seed exclusion, the ball around it
  // (seeds near it would start from the same place and see nearly the same region): a body seed's
  // inscribed ball, or a surface seed's half-ROI ball (the rest of its component is seeded again).
  void reject(Stage& st, const Seed& seed)
  {
    ++m_result.number_of_rejected_seeds;
    ++st.rejections_in_a_row;
    if(m_parameters.use_seed_exclusion)
      exclude_ball(seed.center, seed.body ? (std::max)(m_delta, std::sqrt(seed.depth_sqd))
                                          : (std::max)(m_delta, surface_exclusion * st.rho));
    m_excluded[seed.leaf] = 1;
  }

  void exclude_ball(const std::array<double, 3>& s, double radius)
  {
    const double r2 = radius * radius * (1. + 1e-12);
    m_grid.for_each_leaf_in_box({{s[0] - radius, s[1] - radius, s[2] - radius}},
                                {{s[0] + radius, s[1] + radius, s[2] + radius}}, [&](std::size_t l) {
                                  const std::array<double, 3> c = m_grid.center(l);
                                  const double d2 = (c[0] - s[0]) * (c[0] - s[0]) + (c[1] - s[1]) * (c[1] - s[1]) +
                                                    (c[2] - s[2]) * (c[2] - s[2]);
                                  if(d2 <= r2) m_excluded[l] = 1;
                                });
  }

  // ---- Small residual regions merged into the nearest primitive: unclaimed, non-Freeze components
  // of the hull smaller than V_min (surface, last stage) take the label of the nearest claimed leaf,
  // by a breadth-first search from all claimed leaves through the hull (face-neighbour steps; ties
  // go to the leaf reached first from the lowest claimed index).
  void merge_small_residual_regions()
  {
    std::vector<std::int32_t>& labels = m_result.labels;
    if(m_result.primitives.empty()) return;
    const int r_fit_last = m_fitting_resolutions.empty() ? m_stage_resolutions.back() : m_fitting_resolutions.back();
    const double vmin = volume_of_voxels(m_parameters.minimum_surface_volume, r_fit_last);
    auto residual = [&](std::size_t l) { return !m_freeze[l] && labels[l] < 0; };
    const Leaf_components comps = leaf_components(m_grid, residual);
    auto is_target = [&](std::size_t l) {
      return residual(l) && comps.volumes[std::size_t(comps.labels[l])] < vmin * (1. - 1e-9);
    };
    std::size_t targets = 0;
    for(std::size_t l = 0; l < m_N; ++l)
      if(is_target(l)) ++targets;
    if(targets == 0) return;
    std::vector<std::uint8_t> target(m_N, 0);
    for(std::size_t l = 0; l < m_N; ++l) target[l] = is_target(l) ? 1 : 0;
    std::vector<std::int32_t> reached(labels);
    m_queue.clear();
    for(std::size_t l = 0; l < m_N; ++l)
      if(labels[l] >= 0) m_queue.push_back(l);
    for(std::size_t head = 0; head < m_queue.size() && targets > 0; ++head)
    {
      const std::size_t l = m_queue[head];
      m_grid.for_each_neighbor(l, [&](std::size_t n) {
        if(reached[n] >= 0 || m_zones.exterior[n]) return;
        reached[n] = reached[l];
        m_queue.push_back(n);
        if(target[n])
        {
          labels[n] = reached[l];
          ++m_result.merged_leaves;
          --targets;
        }
      });
    }
  }

  void collect_claimed_leaves()
  {
    const std::vector<std::int32_t>& labels = m_result.labels;
    m_result.claimed_leaves.assign(m_result.primitives.size(), std::vector<std::size_t>());
    for(std::size_t l = 0; l < m_N; ++l)
      if(labels[l] >= 0) m_result.claimed_leaves[std::size_t(labels[l])].push_back(l);
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
              << m_result.number_of_samples << " samples, " << m_N << " leaves\n";
  }

  // inputs
  const Prior& m_prior;
  const Field& m_tsdf;
  const Grid& m_grid;
  const Zones& m_zones;
  const std::vector<int>& m_stage_resolutions;
  const std::vector<int>& m_fitting_resolutions;
  const Parameters m_parameters;
  const std::size_t m_N;
  const double m_delta; // Delta: the side of the finest leaves, the unit of the bands
  const std::vector<std::uint8_t>& m_freeze; // the Freeze zone, or the exterior without it
  const double m_sample_voxel; // the voxel of the finest prior resolution: the unit of the sample lattices

  // fields of the run
  std::vector<double> m_binary_field;          // d_M without TSDF guidance
  const std::vector<double>* m_dM = nullptr;   // d_M as the fit sees it
  std::vector<std::size_t> m_exterior_band_leaves;
  std::vector<std::int8_t> m_lattice_level;    // see set_lattice_levels()
  Fit_sdf_settings m_settings;

  // sets of the current stage
  std::vector<std::uint8_t> m_valid, m_spec, m_body, m_excluded;
  std::vector<std::size_t> m_body_candidates; // Omega_Body leaves not yet excluded (compacted lazily)
  std::vector<double> m_body_sqd;             // squared distance of Omega_Body to its outside
  Leaf_feature_search<Grid> m_flow_outside;   // the leaves outside the stage's Flow zone
  Leaf_feature_search<Grid> m_hull;           // the leaves that are not exterior
  std::vector<double> m_hull_sqd;             // per coarse exterior leaf, its squared distance to them
  std::vector<std::size_t> m_affected;        // candidates whose distance may drop

  // buffers of the current seed
  Stamp_set m_reached;                        // leaves of the seed's region
  Stamp_set m_candidate_mark;                 // the surface seed's candidates
  std::vector<std::size_t> m_roi_leaves, m_sample_leaves;
  Fit_samples m_samples;
  Fit_sdf_workspace m_workspace;
  std::vector<std::size_t> m_claim;
  Stamp_set m_claim_mark, m_kept;             // M_fit candidates; those connected to the region
  std::vector<std::size_t> m_new_body_features; // leaves that left Omega_Body with an acceptance
  std::vector<std::size_t> m_queue;           // breadth-first searches

  Result m_result;
  Step_times m_times;
};

} // namespace internal
} // namespace Part_decomposition
} // namespace CGAL

#endif // CGAL_PART_DECOMPOSITION_INTERNAL_SUPERQUADRIC_FITTER_H
