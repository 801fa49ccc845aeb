// Copyright (c) 2026 The Part_decomposition authors.
// All rights reserved.
//
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Author(s)     : The Part_decomposition authors

#ifndef CGAL_PART_DECOMPOSITION_SUPERQUADRIC_FITTING_H
#define CGAL_PART_DECOMPOSITION_SUPERQUADRIC_FITTING_H

#include <CGAL/Part_decomposition/stage_results.h>
#include <CGAL/Part_decomposition/Superquadric.h>
#include <CGAL/Part_decomposition/Voxel_grid.h>
#include <CGAL/Part_decomposition/fitting_zones.h>
#include <CGAL/Part_decomposition/flow_freeze_prior.h>
#include <CGAL/Part_decomposition/input_validation.h>
#include <CGAL/Part_decomposition/normalization.h>
#include <CGAL/Part_decomposition/parameters.h>
#include <CGAL/Part_decomposition/tsdf.h>
#include <CGAL/Part_decomposition/internal/fit_sdf.h>
#include <CGAL/Part_decomposition/internal/grid_morphology.h>
#include <CGAL/Part_decomposition/internal/superquadric_distance.h>

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Named_function_parameters.h>
#include <CGAL/tags.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <iostream>
#include <limits>
#include <vector>

namespace CGAL {
namespace Part_decomposition {



namespace internal {

// Internal switches whose defaults were chosen by measurement (see fit_superquadrics()).
struct Sdfsqfit_options
{
  bool exterior_band_samples = true; // exterior voxels of the 1.5-voxel band as non-claimable evidence
  bool connected_regions = true;     // ROI and claims restricted to the seed's side of Freeze walls
  std::size_t maximum_samples = 4096; // above this, samples are taken on a lattice of stride 2 or 4
  double surface_test_spacing = 1.;  // Flow-zone test sample spacing, in finest voxels (the zone
                                     // tolerance is >= 4 of them)
  int maximum_evaluations = 40;      // per least-squares solve
  double surface_exclusion = 0.5;    // a rejected surface seed excludes this fraction of rho
  std::size_t consecutive_rejections = 4; // a stage ends after this many rejections in a row (0: never)
  double function_tolerance = 1e-8;  // relative gain below which a solve stops
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

template <typename ConcurrencyTag, typename GeomTraits>
Superquadric_fitting_result<GeomTraits>
fit_superquadrics_in_zones(const Hierarchical_prior& prior, const Truncated_signed_distance_field& tsdf,
                           const Fitting_zones& zones, const std::vector<int>& stage_resolutions,
                           const std::vector<int>& fit_resolutions, const std::vector<double>& etas,
                           double body_threshold, double body_volume, double surface_volume,
                           double exterior_penalty, double coverage_target, double roi_radius,
                           Interior_weight_mode weight_mode, std::size_t maximum_primitives,
                           bool use_freeze_zone, bool use_tsdf_guidance, bool use_body_seeds, bool verbose,
                           const Sdfsqfit_options& options = Sdfsqfit_options())
{
  typedef Superquadric<GeomTraits> SQ;
  const auto start_time = std::chrono::steady_clock::now();
  Superquadric_fitting_result<GeomTraits> result;
  result.normalization = prior.normalization;

  const int R = prior.classes.resolution();
  const std::size_t N = prior.classes.size();
  const std::size_t RR = std::size_t(R);
  const double delta = 1. / double(R);
  const double tau = tsdf.truncation;
  result.labels = Voxel_grid<std::int32_t>(R, -1);
  Voxel_grid<std::int32_t>& labels = result.labels;
  if(N == 0) return result;

  const Voxel_grid<std::uint8_t>& freeze = use_freeze_zone ? zones.freeze_zone : zones.exterior;
  const Voxel_grid<std::uint8_t>& exterior = zones.exterior;

  // d_M, or without TSDF guidance the occupancy only: -tau in the hull, +tau in ext_void.
  Voxel_grid<double> binary_field;
  if(!use_tsdf_guidance)
  {
    binary_field = Voxel_grid<double>(R, tau);
    for(std::size_t v = 0; v < N; ++v) binary_field[v] = exterior[v] ? tau : -tau;
  }
  const Voxel_grid<double>& dM = use_tsdf_guidance ? tsdf.values : binary_field;

  // Exterior evidence: ext_void voxels of the thin outer band, which the ROI (ball minus the
  // Freeze zone) would otherwise drop; they are sampled but never claimed.
  Voxel_grid<std::uint8_t> exterior_band(R, 0);
  if(options.exterior_band_samples)
  {
    if(use_tsdf_guidance)
    {
      for(std::size_t v = 0; v < N; ++v) exterior_band[v] = (exterior[v] && dM[v] < 1.5 * delta) ? 1 : 0;
    }
    else
    {
      const Voxel_grid<std::uint8_t> hull = complement(exterior);
      const Voxel_grid<std::uint8_t> grown = dilate<ConcurrencyTag>(hull, 1.5);
      for(std::size_t v = 0; v < N; ++v) exterior_band[v] = (exterior[v] && grown[v]) ? 1 : 0;
    }
  }

  const double surface_exclusion_fraction = options.surface_exclusion;
  // wall-clock breakdown, printed when verbose
  double t_setup = 0., t_seed = 0., t_roi = 0., t_fit = 0., t_test = 0., t_claim = 0., t_merge = 0.;
  auto clock = [] { return std::chrono::steady_clock::now(); };
  auto seconds_since = [](std::chrono::steady_clock::time_point t) {
    return std::chrono::duration<double>(std::chrono::steady_clock::now() - t).count();
  };
  std::vector<std::size_t> exterior_band_voxels;
  for(std::size_t v = 0; v < N; ++v)
    if(exterior_band[v]) exterior_band_voxels.push_back(v);
  // 2 on the stride-4 lattice, 1 on the stride-2 lattice, else 0
  std::vector<std::uint8_t> lattice_level(N, 0);
  for(std::size_t v = 0; v < N; ++v)
  {
    const std::size_t i = v % RR, j = (v / RR) % RR, k = v / (RR * RR);
    const std::size_t o = i | j | k;
    lattice_level[v] = (o & 3) == 0 ? 2 : ((o & 1) == 0 ? 1 : 0);
  }
  Fit_sdf_workspace workspace;
  Fit_samples samples;
  Stamp_set reach, claim_mark;
  std::vector<std::size_t> queue, candidates, roi_voxels, claim, claim_new_body;
  std::vector<std::uint8_t> excluded(N, 0), valid(N, 0), spec(N, 0), body(N, 0);

  // V_min, given in voxels of r_fit, in voxels of the finest grid. A volume above the grid's is
  // never reached: clamped to N + 1 voxels, the same comparisons without a cast out of the range
  // of std::size_t (undefined) for huge parameters.
  auto finest_voxels = [&](double volume, int r_fit) {
    const double v = volume * std::pow(double(R) / double(r_fit), 3);
    return std::size_t(std::ceil((std::min)(v, double(N) + 1.) - 1e-9));
  };

  auto for_each_neighbor = [&](std::size_t idx, auto&& f) {
    const std::size_t i = idx % RR, j = (idx / RR) % RR, k = idx / (RR * RR);
    if(i > 0) f(idx - 1);
    if(i + 1 < RR) f(idx + 1);
    if(j > 0) f(idx - RR);
    if(j + 1 < RR) f(idx + RR);
    if(k > 0) f(idx - RR * RR);
    if(k + 1 < RR) f(idx + RR * RR);
  };

  for(std::size_t stage = 0; stage < stage_resolutions.size(); ++stage)
  {
    const int r = stage_resolutions[stage];
    const int r_fit = fit_resolutions[stage];
    const double delta_fit = 1. / double(r_fit);
    const double rho = roi_radius * delta_fit;
    const Voxel_grid<std::uint8_t>& flow = zones.flow_zone.at(r_fit);
    const Voxel_grid<double>& edt_flow = zones.flow_zone_distance.at(r_fit);
    const std::size_t vmin_body = finest_voxels(body_volume, r_fit);
    const std::size_t vmin_surface = finest_voxels(surface_volume, r_fit);

    auto t0 = clock();
    // Omega_valid = {R_map <= r} \ Omega_freeze (R_map = 0 inside: valid from the first stage),
    // Omega_spec = {R_map > r}; Omega_Body = Omega_valid \ (claimed u freeze).
    std::size_t n_valid = 0, n_covered = 0;
    candidates.clear();
    for(std::size_t v = 0; v < N; ++v)
    {
      const int res = int(prior.leaf_resolution[v]);
      valid[v] = (!freeze[v] && res <= r) ? 1 : 0;
      spec[v] = res > r ? 1 : 0;
      body[v] = (valid[v] && labels[v] < 0) ? 1 : 0;
      excluded[v] = 0;
      n_valid += valid[v];
      if(valid[v] && labels[v] >= 0) ++n_covered;
      if(body[v]) candidates.push_back(v);
    }
    // EDT of Omega_Body in voxels^2, lowered incrementally as claims grow (A.2).
    Voxel_grid<std::uint8_t> not_body(R, 0);
    for(std::size_t v = 0; v < N; ++v) not_body[v] = body[v] ? 0 : 1;
    Voxel_grid<double> body_sqd = squared_distance_transform<ConcurrencyTag>(not_body);
    t_setup += seconds_since(t0);

    std::size_t seeds_this_stage = 0, rejections_in_a_row = 0;
    const std::size_t seed_cap = 16 * (std::max<std::size_t>)(maximum_primitives, 16);
    while(n_valid > 0 && double(n_covered) < coverage_target * double(n_valid) &&
          result.primitives.size() < maximum_primitives && seeds_this_stage < seed_cap &&
          (options.consecutive_rejections == 0 || rejections_in_a_row < options.consecutive_rejections))
    {
      // ---- BodyOrSurfaceSeed (A.2-A.4)
      t0 = clock();
      std::size_t seed = N;
      double seed_sqd = 0.;
      {
        std::size_t kept = 0;
        for(std::size_t c = 0; c < candidates.size(); ++c)
        {
          const std::size_t v = candidates[c];
          if(!body[v] || excluded[v]) continue;
          candidates[kept++] = v;
          if(body_sqd[v] > seed_sqd) seed_sqd = body_sqd[v], seed = v;
        }
        candidates.resize(kept);
      }
      bool body_seed = use_body_seeds && seed < N && std::sqrt(seed_sqd) * delta >= body_threshold * delta_fit;
      if(!body_seed)
      {
        Voxel_grid<std::uint8_t> open(R, 0);
        for(std::size_t v : candidates) open[v] = 1;
        const Grid_components comps = connected_components(open);
        std::size_t best = comps.size();
        for(std::size_t c = 0; c < comps.size(); ++c)
          if(comps.sizes[c] >= vmin_surface && (best == comps.size() || comps.sizes[c] > comps.sizes[best])) best = c;
        // components below V_min cannot be accepted: left to the final merge
        for(std::size_t v : candidates)
          if(best == comps.size() || comps.sizes[std::size_t(comps.labels[v])] < vmin_surface) excluded[v] = 1;
        if(best == comps.size()) break;
        const std::array<double, 3>& g = comps.centroids[best];
        double best_d = std::numeric_limits<double>::infinity();
        seed = N;
        for(std::size_t v : candidates)
          if(comps.labels[v] == int(best))
          {
            const std::array<int, 3> ijk = prior.classes.coordinates(v);
            const double d = (ijk[0] - g[0]) * (ijk[0] - g[0]) + (ijk[1] - g[1]) * (ijk[1] - g[1]) +
                             (ijk[2] - g[2]) * (ijk[2] - g[2]);
            if(d < best_d) best_d = d, seed = v;
          }
      }
      t_seed += seconds_since(t0);
      t0 = clock();
      ++seeds_this_stage;
      ++result.number_of_seeds;
      if(body_seed) ++result.number_of_body_seeds;

      auto reject = [&]() {
        ++result.number_of_rejected_seeds;
        ++rejections_in_a_row;
        {
          // Seeds near this one would start from the same place and see nearly the same region:
          // exclude the seed's inscribed ball (body seed), or the half-ROI ball (surface seed;
          // the rest of its component is seeded again at the centroid of what remains).
          const double rad = body_seed ? (std::max)(1., std::sqrt(seed_sqd))
                                       : (std::max)(1., (surface_exclusion_fraction * rho) / delta);
          const std::array<int, 3> s = prior.classes.coordinates(seed);
          // a ball wider than the grid covers it all: the loop bound is clamped before the cast
          const int ir = int(std::floor((std::min)(rad, 2. * R)));
          for(int k = (std::max)(0, s[2] - ir); k <= (std::min)(R - 1, s[2] + ir); ++k)
            for(int j = (std::max)(0, s[1] - ir); j <= (std::min)(R - 1, s[1] + ir); ++j)
              for(int i = (std::max)(0, s[0] - ir); i <= (std::min)(R - 1, s[0] + ir); ++i)
              {
                const double d2 = double((i - s[0]) * (i - s[0]) + (j - s[1]) * (j - s[1]) + (k - s[2]) * (k - s[2]));
                if(d2 <= rad * rad) excluded[prior.classes.index(i, j, k)] = 1;
              }
        }
        excluded[seed] = 1;
      };

      // ---- ROI and samples (Alg. A.2 lines 10-11, B.1)
      const std::array<double, 3> s = prior.classes.center(seed);
      const std::array<int, 3> sijk = prior.classes.coordinates(seed);
      const double ball_r2 = (rho / delta) * (rho / delta) * (1. + 1e-12);
      auto in_ball = [&](int i, int j, int k) {
        const double d2 = double((i - sijk[0]) * (i - sijk[0]) + (j - sijk[1]) * (j - sijk[1]) +
                                 (k - sijk[2]) * (k - sijk[2]));
        return d2 <= ball_r2;
      };
      roi_voxels.clear();
      reach.reset(N);
      if(options.connected_regions)
      {
        // the part of the ball reachable from the seed without crossing Freeze or claimed voxels
        queue.clear();
        queue.push_back(seed);
        reach.insert(seed);
        for(std::size_t head = 0; head < queue.size(); ++head)
        {
          const std::size_t v = queue[head];
          if(valid[v] && labels[v] < 0) roi_voxels.push_back(v);
          const int i = int(v % RR), j = int((v / RR) % RR), k = int(v / (RR * RR));
          auto visit = [&](std::size_t n, int ni, int nj, int nk) {
            if(!reach.contains(n) && !freeze[n] && labels[n] < 0 && in_ball(ni, nj, nk))
            {
              reach.insert(n);
              queue.push_back(n);
            }
          };
          if(i > 0) visit(v - 1, i - 1, j, k);
          if(i + 1 < R) visit(v + 1, i + 1, j, k);
          if(j > 0) visit(v - RR, i, j - 1, k);
          if(j + 1 < R) visit(v + RR, i, j + 1, k);
          if(k > 0) visit(v - RR * RR, i, j, k - 1);
          if(k + 1 < R) visit(v + RR * RR, i, j, k + 1);
        }
      }
      else
      {
        const int ball = int(std::ceil((std::min)(rho / delta, 2. * R))); // as above: the grid at most
        for(int k = (std::max)(0, sijk[2] - ball); k <= (std::min)(R - 1, sijk[2] + ball); ++k)
          for(int j = (std::max)(0, sijk[1] - ball); j <= (std::min)(R - 1, sijk[1] + ball); ++j)
            for(int i = (std::max)(0, sijk[0] - ball); i <= (std::min)(R - 1, sijk[0] + ball); ++i)
            {
              const std::size_t v = prior.classes.index(i, j, k);
              if(valid[v] && labels[v] < 0 && in_ball(i, j, k))
              {
                roi_voxels.push_back(v);
                reach.insert(v);
              }
            }
      }
      // sample candidates: ROI voxels of the band d_M < 1.5 delta, plus exterior evidence
      std::vector<std::size_t>& cand = claim; // reused buffer
      cand.clear();
      for(std::size_t v : roi_voxels)
        if(dM[v] < 1.5 * delta) cand.push_back(v);
      for(std::size_t v : exterior_band_voxels)
      {
        const int i = int(v % RR), j = int((v / RR) % RR), k = int(v / (RR * RR));
        if(in_ball(i, j, k)) cand.push_back(v);
      }
      // the densest lattice (stride 1, 2 or 4) that keeps at most maximum_samples samples
      std::size_t count[3] = {0, 0, 0};
      for(std::size_t v : cand)
        for(int l = 0; l <= int(lattice_level[v]); ++l) ++count[l];
      int level = 0;
      while(level < 2 && count[level] > options.maximum_samples) ++level;
      samples.clear();
      for(std::size_t v : cand)
        if(int(lattice_level[v]) >= level)
        {
          const std::array<double, 3> c = prior.classes.center(v);
          samples.push_back(c[0], c[1], c[2], dM[v]);
        }
      result.number_of_samples += samples.size();

      t_roi += seconds_since(t0);
      // ---- InitSQ (A.5): centre s, axis-aligned ellipsoid of radius min(rho0, EDT_flow(s))
      internal::Superquadric_data theta0;
      const double a_lower = delta_fit / 4., a_upper = (std::max)(rho, delta_fit / 4.);
      const double a0 = (std::min)(a_upper, (std::max)(a_lower, (std::min)(delta_fit, edt_flow[seed])));
      for(int i = 0; i < 3; ++i) theta0.a[i] = a0, theta0.c[i] = s[i];
      Superquadric_vector lb, ub;
      const double inf = std::numeric_limits<double>::infinity();
      lb << a_lower, a_lower, a_lower, internal::superquadric_minimum_exponent,
        internal::superquadric_minimum_exponent, -inf, -inf, -inf, s[0] - rho / 2., s[1] - rho / 2., s[2] - rho / 2.;
      ub << a_upper, a_upper, a_upper, 2., 2., inf, inf, inf, s[0] + rho / 2., s[1] + rho / 2., s[2] + rho / 2.;

      Fit_sdf_settings settings;
      settings.truncation = tau;
      settings.exterior_penalty = exterior_penalty;
      settings.reestimate_variance = weight_mode == Interior_weight_mode::MPS_REESTIMATED;
      settings.maximum_evaluations = options.maximum_evaluations;
      settings.function_tolerance = options.function_tolerance;

      // ---- retry loop over eta with the Flow-zone test (Alg. A.2 lines 13-17, B.3)
      bool passed = false, degenerate = false;
      Fit_sdf_result fit;
      double eta_used = 0.;
      for(double eta : etas)
      {
        settings.semi_axis_scale = eta;
        t0 = clock();
        fit = fit_sdf<ConcurrencyTag>(samples, theta0, lb, ub, settings, workspace);
        t_fit += seconds_since(t0);
        t0 = clock();
        result.number_of_solves += std::size_t(fit.solves);
        result.number_of_evaluations += std::size_t(fit.evaluations);
        if(!fit.valid)
        {
          degenerate = true;
          break;
        }
        const bool inside_flow = for_each_surface_sample(fit.theta, options.surface_test_spacing * delta,
                                                         [&](const double p[3]) {
          for(int l = 0; l < 3; ++l)
            if(!(p[l] >= -0.5 && p[l] <= 0.5)) return false;
          const std::size_t v = prior.classes.index(voxel_coordinate(p[0], R), voxel_coordinate(p[1], R),
                                                    voxel_coordinate(p[2], R));
          return flow[v] != 0;
        });
        t_test += seconds_since(t0);
        if(inside_flow)
        {
          passed = true;
          eta_used = eta;
          break;
        }
      }
      if(!passed)
      {
        if(degenerate) ++result.rejected_degenerate;
        else ++result.rejected_by_flow_zone;
        reject();
        continue;
      }

      // ---- M_fit = {d~ <= 2 delta}, net claim and hard clipping (B.3, Alg. A.2 lines 18-22)
      t0 = clock();
      claim.clear();
      claim_mark.reset(N);
      for_each_voxel_within(fit.theta, R, 2. * delta, [&](int, int, int, std::size_t v) {
        if(!freeze[v] && labels[v] < 0)
        {
          claim.push_back(v);
          claim_mark.insert(v);
        }
      });
      if(options.connected_regions)
      {
        // keep the parts of the claim connected to the seed's reachable region: a claim never
        // jumps across a Freeze wall
        queue.clear();
        Stamp_set& kept = reach; // reach is no longer needed: reuse it as the kept set
        std::vector<std::size_t> starts;
        for(std::size_t v : claim)
          if(reach.contains(v)) starts.push_back(v);
        kept.reset(N);
        for(std::size_t v : starts)
        {
          kept.insert(v);
          queue.push_back(v);
        }
        for(std::size_t head = 0; head < queue.size(); ++head)
          for_each_neighbor(queue[head], [&](std::size_t n) {
            if(claim_mark.contains(n) && !kept.contains(n))
            {
              kept.insert(n);
              queue.push_back(n);
            }
          });
        std::size_t m = 0;
        for(std::size_t v : claim)
          if(kept.contains(v)) claim[m++] = v;
        claim.resize(m);
      }
      std::size_t net = 0;
      for(std::size_t v : claim) net += spec[v] ? 0 : 1;
      const std::size_t vmin = body_seed ? vmin_body : vmin_surface;
      t_claim += seconds_since(t0);
      if(net < vmin)
      {
        ++result.rejected_by_volume;
        reject();
        continue;
      }

      // ---- accept
      const std::int32_t label = std::int32_t(result.primitives.size());
      claim_new_body.clear();
      for(std::size_t v : claim)
      {
        labels[v] = label;
        if(valid[v]) ++n_covered;
        if(body[v])
        {
          body[v] = 0;
          claim_new_body.push_back(v);
        }
      }
      excluded[seed] = 1;
      rejections_in_a_row = 0;
      add_features_to_squared_distance_transform<ConcurrencyTag>(body_sqd, claim_new_body);
      const SQ sq(fit.theta);
      result.primitives.push_back(sq);
      result.input_primitives.push_back(sq.in_input_coordinates(prior.normalization));
      result.stage_resolution.push_back(r);
      result.body_seeded.push_back(body_seed);
      result.seed_voxel.push_back(seed);
      result.semi_axis_scale.push_back(eta_used);
      result.fit_cost.push_back(fit.cost);
      if(verbose)
        std::cerr << "  SQ " << label << " stage " << r << (body_seed ? " body" : " surface") << " seed " << seed
                  << " a = (" << fit.theta.a[0] << ", " << fit.theta.a[1] << ", " << fit.theta.a[2] << ") eps = ("
                  << fit.theta.e1 << ", " << fit.theta.e2 << ") eta " << eta_used << " claim " << claim.size()
                  << " samples " << samples.size() << "\n";
    }
    result.stage_coverage.push_back(n_valid > 0 ? double(n_covered) / double(n_valid) : 1.);
    if(verbose)
      std::cerr << "stage " << r << " (r_fit " << r_fit << "): coverage " << result.stage_coverage.back() << " of "
                << n_valid << " valid voxels, " << result.primitives.size() << " primitives, " << seeds_this_stage
                << " seeds\n";
  }

  const auto t_merge_start = clock();
  // ---- small residual regions merged into the nearest primitive: unclaimed, non-Freeze
  // components of the hull smaller than V_min (surface, last stage) take the label of the
  // nearest claimed voxel, by a breadth-first search from all claimed voxels through the hull
  // (6-neighbour steps; ties go to the voxel reached first from the lowest claimed index).
  if(!result.primitives.empty())
  {
    const int r_fit_last = fit_resolutions.empty() ? R : fit_resolutions.back();
    const std::size_t vmin = finest_voxels(surface_volume, r_fit_last);
    Voxel_grid<std::uint8_t> residual(R, 0);
    for(std::size_t v = 0; v < N; ++v) residual[v] = (!freeze[v] && labels[v] < 0) ? 1 : 0;
    const Grid_components comps = connected_components(residual);
    std::size_t targets = 0;
    for(std::size_t v = 0; v < N; ++v)
      if(residual[v] && comps.sizes[std::size_t(comps.labels[v])] < vmin) ++targets;
    if(targets > 0)
    {
      std::vector<std::int32_t> reached(labels.values());
      queue.clear();
      for(std::size_t v = 0; v < N; ++v)
        if(labels[v] >= 0) queue.push_back(v);
      for(std::size_t head = 0; head < queue.size() && targets > 0; ++head)
      {
        const std::size_t v = queue[head];
        for_each_neighbor(v, [&](std::size_t n) {
          if(reached[n] >= 0 || exterior[n]) return;
          reached[n] = reached[v];
          queue.push_back(n);
          if(residual[n] && comps.sizes[std::size_t(comps.labels[n])] < vmin)
          {
            labels[n] = reached[v];
            ++result.merged_voxels;
            --targets;
          }
        });
      }
    }
  }
  result.claimed_voxels.assign(result.primitives.size(), std::vector<std::size_t>());
  for(std::size_t v = 0; v < N; ++v)
    if(labels[v] >= 0) result.claimed_voxels[std::size_t(labels[v])].push_back(v);
  t_merge = seconds_since(t_merge_start);
  result.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start_time).count();
  if(verbose)
    std::cerr << "time (ms): stage setup " << 1e3 * t_setup << ", seeds " << 1e3 * t_seed << ", ROI/samples "
              << 1e3 * t_roi << ", FitSDF " << 1e3 * t_fit << ", Flow-zone test " << 1e3 * t_test << ", claims "
              << 1e3 * t_claim << ", merge " << 1e3 * t_merge << ", total " << 1e3 * result.seconds << "; "
              << result.number_of_seeds << " seeds, " << result.number_of_solves << " solves, "
              << result.number_of_evaluations << " evaluations of " << result.number_of_samples << " samples\n";
  return result;
}

// fit_superquadrics() with the zones given (checked against the prior) or computed if null
template <typename ConcurrencyTag, typename GeomTraits, typename NamedParameters>
Superquadric_fitting_result<GeomTraits> fit_superquadrics_with_zones(const Hierarchical_prior& prior,
                                                                     const Truncated_signed_distance_field& tsdf,
                                                                     const Fitting_zones* zones,
                                                                     const NamedParameters& np)
{
  using CGAL::parameters::choose_parameter;
  using CGAL::parameters::get_parameter;
#ifndef CGAL_LINKED_WITH_TBB
  CGAL_static_assertion_msg(!(std::is_convertible<ConcurrencyTag, CGAL::Parallel_tag>::value),
                            "Parallel_tag is enabled but TBB is unavailable.");
#endif
  auto fail = [](const char* what) { throw Invalid_input(Input_error::INVALID_PARAMETER, what); };
  const std::vector<double> etas =
    choose_parameter(get_parameter(np, internal_np::trust_region_scales), std::vector<double>{1., 0.5, 0.25});
  const double body_threshold = choose_parameter(get_parameter(np, internal_np::body_seed_threshold), 1.5);
  const double body_volume = choose_parameter(get_parameter(np, internal_np::minimum_body_volume), 5.);
  const double surface_volume = choose_parameter(get_parameter(np, internal_np::minimum_surface_volume), 3.);
  const double exterior_penalty = choose_parameter(get_parameter(np, internal_np::exterior_penalty), 5.);
  const double coverage = choose_parameter(get_parameter(np, internal_np::coverage_target), defaults::coverage_target);
  const double roi = choose_parameter(get_parameter(np, internal_np::roi_radius), 8.);
  const Interior_weight_mode mode =
    choose_parameter(get_parameter(np, internal_np::interior_weight_mode), Interior_weight_mode::ONE_SHOT);
  const std::size_t cap = choose_parameter(get_parameter(np, internal_np::maximum_number_of_primitives), std::size_t(256));
  const bool use_freeze = choose_parameter(get_parameter(np, internal_np::use_freeze_zone), true);
  const bool use_tsdf = choose_parameter(get_parameter(np, internal_np::use_tsdf_guidance), true);
  const bool use_body = choose_parameter(get_parameter(np, internal_np::use_body_seeds), true);
  const bool verbose = choose_parameter(get_parameter(np, CGAL::internal_np::verbose), false);

  if(etas.empty()) fail("trust_region_scales must not be empty");
  for(double e : etas)
    if(!(e > 0.) || !std::isfinite(e)) fail("trust_region_scales must be positive");
  if(!(body_threshold > 0.) || !std::isfinite(body_threshold)) fail("body_seed_threshold must be positive");
  if(!(body_volume >= 0.) || !(surface_volume >= 0.) || !std::isfinite(body_volume) || !std::isfinite(surface_volume))
    fail("minimum_body_volume and minimum_surface_volume must be non-negative");
  if(!(exterior_penalty >= 0.) || !std::isfinite(exterior_penalty)) fail("exterior_penalty must be non-negative");
  if(!(coverage > 0. && coverage <= 1.)) fail("coverage_target must be in (0, 1]");
  if(!(roi > 0.) || !std::isfinite(roi)) fail("roi_radius must be positive");
  if(cap == 0) fail("maximum_number_of_primitives must be positive");

  // Results of other calls: checked at run time, a mismatch would index out of the grids.
  bool consistent = !prior.resolutions.empty() && prior.resolutions.front() >= 1 &&
                    prior.resolutions.back() == prior.classes.resolution() &&
                    tsdf.values.resolution() == prior.classes.resolution();
  for(std::size_t l = 1; consistent && l < prior.resolutions.size(); ++l)
    consistent = prior.resolutions[l - 1] < prior.resolutions[l];
  if(!consistent)
    fail("the prior and the distance field must be computed with the same voxel_resolutions");

  const std::vector<int>& stages = prior.resolutions;
  const std::vector<int> fit_res = internal::stage_fitting_resolutions(stages);
  Fitting_zones own_zones;
  if(zones == nullptr)
  {
    own_zones = compute_fitting_zones<ConcurrencyTag>(prior.classes, fitting_resolutions(stages), np);
    zones = &own_zones;
  }
  else
  {
    bool match = zones->freeze_zone.resolution() == prior.classes.resolution() &&
                 zones->exterior.resolution() == prior.classes.resolution();
    for(int r_fit : fit_res)
      match = match && zones->flow_zone.count(r_fit) == 1 && zones->flow_zone_distance.count(r_fit) == 1 &&
              zones->flow_zone.at(r_fit).resolution() == prior.classes.resolution() &&
              zones->flow_zone_distance.at(r_fit).resolution() == prior.classes.resolution();
    if(!match) fail("the fitting zones must be computed from this prior at its fitting_resolutions()");
  }
  return internal::fit_superquadrics_in_zones<ConcurrencyTag, GeomTraits>(
    prior, tsdf, *zones, stages, fit_res, etas, body_threshold, body_volume, surface_volume, exterior_penalty,
    coverage, roi, mode, cap, use_freeze, use_tsdf, use_body, verbose);
}

} // namespace internal

/*!
\ingroup PkgPartDecompositionRef
SDFSQFit (paper Alg.\ A.2, with FitSDF, Alg.\ A.3): fits superquadrics to the truncated signed
distance field of a shape, coarse to fine over the resolutions of the prior, growing them in the
Flow zone and stopping them at the Freeze zone.

For each stage \f$r\f$ (16, 32, 64), with \f$r_{fit} = \min(r, 32)\f$ (the resolution before the
finest), the valid set \f$\Omega_{valid} = \{\mathcal{R}_{map} \le r\} \setminus \Omega_{freeze}\f$
is covered until a fraction `coverage_target` (0.999 by default) of it is claimed: a body seed is placed at the maximum of the Euclidean
distance transform of the unclaimed valid voxels if it reaches `body_seed_threshold` voxels of
\f$r_{fit}\f$, otherwise a surface seed at the centroid of the largest remaining 6-connected
component; a superquadric is initialized there (a ball of radius
\f$\min(\Delta^{r_{fit}}, \mathrm{EDT}_{\Omega_{flow}}(s))\f$), fitted to the samples of its
region of interest with the trust-region scales \f$\eta\f$ in turn until its surface stays in the
Flow zone, and accepted if the voxels within \f$2\Delta\f$ of it that are neither Freeze, claimed
nor reserved for a finer stage number at least \f$V_{min}\f$.

Choices where the paper is silent (measured on the development meshes, see the package manual):
- \f$\Omega_{Body}\f$ is the whole unclaimed valid volume (interior voxels included), not only
  its Flow carrier voxels, so that EDT maxima are centres of thick cross-sections.
- \f$\Delta\f$ of the sample band (\f$d_\mathcal{M} < 1.5\Delta\f$) and of
  \f$M_{fit} = \{\tilde d \le 2\Delta\}\f$ is the voxel of the finest grid; \f$V_{min}\f$ counts
  voxels of \f$r_{fit}\f$; the region of interest is the ball of radius `roi_radius`
  \f$\cdot\Delta^{r_{fit}}\f$ restricted to the voxels reachable from the seed without crossing
  Freeze or claimed voxels, and a claim keeps only the voxels of \f$M_{fit}\f$ connected to that
  region, so that no claim jumps across a Freeze wall.
- Samples are the finest-grid voxel centres of the region (on a lattice of stride 2 or 4 when
  there are more than 4096), plus the exterior voxels of the \f$1.5\Delta\f$ band in the ball as
  evidence that is never claimed.
- Bounds: semi-axes in \f$[\Delta^{r_{fit}}/4, \rho]\f$, exponents in \f$[10^{-3}, 2]\f$, centre
  within \f$\rho/2\f$ of the seed; rotations are unbounded (body-frame increments).
- A rejected body seed excludes its inscribed ball from later seeds of the stage, a rejected
  surface seed the ball of radius \f$\rho/2\f$ around it (the rest of its component is seeded
  again at the centroid of what remains); components smaller than \f$V_{min}\f$ are not seeded;
  a stage also ends after 4 rejected seeds in a row (the paper's iteration budget; on the
  development meshes it removed 22% of the solves and slightly improved the parts).
- Claimed voxels include reserved voxels of finer stages (Alg.\ A.2 line 22); the volume test
  does not count them.
- FitSDF runs the projected Levenberg-Marquardt solver of the package (active-set freezing,
  Marquardt scaling divided by \f$\eta^2\f$ along the semi-axes, i.e.\ scipy's `x_scale`) with
  at most 40 residual evaluations per solve; the first interior-weight variance is the mean
  squared clipped residual at \f$\theta_0\f$. On the development meshes `ONE_SHOT` and
  `MPS_REESTIMATED` scored within noise of each other (the MPS rule had a lower variation of
  information, one-shot a higher mIoU) and one-shot fits in about half the time: it is the default.
- Without TSDF guidance, \f$d_\mathcal{M}\f$ is replaced by \f$-\tau\f$ inside the hull and
  \f$+\tau\f$ in the exterior.
- Small residual regions: unclaimed non-Freeze components smaller than the surface \f$V_{min}\f$
  of the last stage take the label of their nearest claimed voxel.

\tparam ConcurrencyTag enables sequential versus parallel evaluation of the residuals and
distance transforms. Possible values are `Sequential_tag`, `Parallel_tag` and
`Parallel_if_available_tag`. Results are identical for every number of threads.
\tparam GeomTraits a model of `Kernel`, the kernel of the returned superquadrics
\tparam NamedParameters a sequence of named parameters

\param prior the hierarchical Flow/Freeze prior (`classes`, `leaf_resolution`, `resolutions`,
       `normalization` are read)
\param tsdf the truncated signed distance field on the finest grid of the prior
\param np an optional sequence of named parameters among the ones listed below

\cgalNamedParamsBegin
  \cgalParamNBegin{flow_zone_tolerance}
    \cgalParamDescription{the dilation of the hull that defines the Flow zone, in voxels of \f$r_{fit}\f$}
    \cgalParamType{`double`, non-negative}
    \cgalParamDefault{`2.0`}
  \cgalParamNEnd
  \cgalParamNBegin{trust_region_scales}
    \cgalParamDescription{the semi-axis trust-region scales \f$\eta\f$ tried in turn}
    \cgalParamType{`std::vector<double>`, positive values}
    \cgalParamDefault{`{1.0, 0.5, 0.25}`}
  \cgalParamNEnd
  \cgalParamNBegin{body_seed_threshold}
    \cgalParamDescription{the EDT depth, in voxels of \f$r_{fit}\f$, from which a body seed is used}
    \cgalParamType{`double`, positive}
    \cgalParamDefault{`1.5`}
  \cgalParamNEnd
  \cgalParamNBegin{minimum_body_volume}
    \cgalParamDescription{\f$V_{min}\f$ of body seeds, in voxels of \f$r_{fit}\f$}
    \cgalParamType{`double`, non-negative}
    \cgalParamDefault{`5`}
  \cgalParamNEnd
  \cgalParamNBegin{minimum_surface_volume}
    \cgalParamDescription{\f$V_{min}\f$ of surface seeds, in voxels of \f$r_{fit}\f$}
    \cgalParamType{`double`, non-negative}
    \cgalParamDefault{`3`}
  \cgalParamNEnd
  \cgalParamNBegin{exterior_penalty}
    \cgalParamDescription{\f$\mu_{ext}\f$, the exterior intrusion penalty of FitSDF}
    \cgalParamType{`double`, non-negative}
    \cgalParamDefault{`5`}
  \cgalParamNEnd
  \cgalParamNBegin{coverage_target}
    \cgalParamDescription{the fraction of \f$\Omega_{valid}\f$ to claim before a stage ends}
    \cgalParamType{`double`, in \f$(0,1]\f$}
    \cgalParamDefault{`0.999` (the paper's 0.95 leaves thin limbs, a few voxels each, without a
                      primitive)}
  \cgalParamNEnd
  \cgalParamNBegin{roi_radius}
    \cgalParamDescription{\f$\rho(r_{fit})\f$, the radius of the region of interest, in voxels of \f$r_{fit}\f$}
    \cgalParamType{`double`, positive}
    \cgalParamDefault{`8`}
  \cgalParamNEnd
  \cgalParamNBegin{interior_weight_mode}
    \cgalParamDescription{how the variance of the interior Gaussian weight is set}
    \cgalParamType{`CGAL::Part_decomposition::Interior_weight_mode`}
    \cgalParamDefault{`Interior_weight_mode::ONE_SHOT`}
  \cgalParamNEnd
  \cgalParamNBegin{maximum_number_of_primitives}
    \cgalParamDescription{a safety cap on the number of accepted superquadrics}
    \cgalParamType{`std::size_t`, positive}
    \cgalParamDefault{`256`}
  \cgalParamNEnd
  \cgalParamNBegin{use_freeze_zone}
    \cgalParamDescription{if `false` (ablation "w/o Freeze"), Freeze voxels are treated as Flow:
                          the Freeze zone is the exterior only}
    \cgalParamType{`bool`}
    \cgalParamDefault{`true`}
  \cgalParamNEnd
  \cgalParamNBegin{use_tsdf_guidance}
    \cgalParamDescription{if `false` (ablation "w/o TSDF"), the fit sees the occupancy only:
                          \f$-\tau\f$ in the hull, \f$+\tau\f$ outside}
    \cgalParamType{`bool`}
    \cgalParamDefault{`true`}
  \cgalParamNEnd
  \cgalParamNBegin{use_body_seeds}
    \cgalParamDescription{if `false` (ablation "w/o Body"), only surface seeds are used}
    \cgalParamType{`bool`}
    \cgalParamDefault{`true`}
  \cgalParamNEnd
  \cgalParamNBegin{verbose}
    \cgalParamDescription{if `true`, prints every accepted primitive and stage to `std::cerr`}
    \cgalParamType{`bool`}
    \cgalParamDefault{`false`}
  \cgalParamNEnd
\cgalNamedParamsEnd

\par Complexity
Independent of the number of faces of the mesh. A stage ends after 4 rejected seeds in a row, so
there are at most \f$5P + 4L\f$ seeds for \f$P\f$ accepted primitives and \f$L\f$ resolutions. Each seed
costs at most linear time in the \f$r^3\f$ voxels of the finest grid (finding it, claiming, and the
incremental update of the distance transform after an acceptance) plus its solves: one fit per
trust-region scale, each of one solve (`ONE_SHOT`) or at most 4 (`MPS_REESTIMATED`), and each solve
evaluates the residuals of at most about 4096 samples (plus exterior band samples) at most 40
times.

\returns the accepted superquadrics and the claimed-voxel labels.
\throws Invalid_input (`INVALID_PARAMETER`) if a parameter is out of range, or unless `tsdf.values`
has the resolution of `prior.classes`, the resolutions of the prior are increasing, and the finest
is that of `prior.classes`.
*/
template <typename ConcurrencyTag = CGAL::Sequential_tag,
          typename GeomTraits = CGAL::Exact_predicates_inexact_constructions_kernel,
          typename NamedParameters = CGAL::parameters::Default_named_parameters>
Superquadric_fitting_result<GeomTraits> fit_superquadrics(const Hierarchical_prior& prior,
                                                          const Truncated_signed_distance_field& tsdf,
                                                          const NamedParameters& np = CGAL::parameters::default_values())
{
  return internal::fit_superquadrics_with_zones<ConcurrencyTag, GeomTraits>(prior, tsdf, nullptr, np);
}

/*!
\ingroup PkgPartDecompositionRef
the same as `fit_superquadrics(prior, tsdf, np)` with the zones computed beforehand, for instance
next to the distance field, by
`compute_fitting_zones(prior.classes, fitting_resolutions(prior.resolutions), np)` with the same
`flow_zone_tolerance` and `use_freeze_zone`.
\throws Invalid_input (`INVALID_PARAMETER`) as `fit_superquadrics(prior, tsdf, np)`, and if
`zones` are not on the grid of `prior.classes` or miss one of its fitting resolutions.
*/
template <typename ConcurrencyTag = CGAL::Sequential_tag,
          typename GeomTraits = CGAL::Exact_predicates_inexact_constructions_kernel,
          typename NamedParameters = CGAL::parameters::Default_named_parameters>
Superquadric_fitting_result<GeomTraits> fit_superquadrics(const Hierarchical_prior& prior,
                                                          const Truncated_signed_distance_field& tsdf,
                                                          const Fitting_zones& zones,
                                                          const NamedParameters& np = CGAL::parameters::default_values())
{
  return internal::fit_superquadrics_with_zones<ConcurrencyTag, GeomTraits>(prior, tsdf, &zones, np);
}

} // namespace Part_decomposition
} // namespace CGAL

#endif // CGAL_PART_DECOMPOSITION_SUPERQUADRIC_FITTING_H
