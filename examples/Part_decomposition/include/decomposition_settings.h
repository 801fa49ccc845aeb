// Copyright (c) 2026 The Part_decomposition authors.
// All rights reserved.
//
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Author(s)     : The Part_decomposition authors

#ifndef PART_DECOMPOSITION_TOOLS_DECOMPOSITION_SETTINGS_H
#define PART_DECOMPOSITION_TOOLS_DECOMPOSITION_SETTINGS_H

// The named parameters of Part_decomposition::decompose() as plain values at the package's
// defaults, for the programs that take them from their users (hitops, the Python module) or vary
// them (the benchmark), the one named-parameter pack that passes them all, and their text form.
// The list is made from PD::parameter_table by doc/Part_decomposition/tools/parameter_table.py.

#include <CGAL/Part_decomposition/decompose.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <iterator>
#include <sstream>
#include <stdexcept>
#include <string>
#include <type_traits>
#include <vector>

namespace Part_decomposition_tools {

namespace PD = CGAL::Part_decomposition;

// The package's named parameters that hold a value, in the order of PD::parameter_table: type,
// name, default. Each is a field of Decomposition_settings, passed by named_parameters().
// settings: made by doc/Part_decomposition/tools/parameter_table.py from parameter_table, do not edit
#define PART_DECOMPOSITION_TOOLS_SETTINGS(X)                                               \
  X(bool, use_pieces, PD::defaults::use_pieces)                                            \
  X(double, crease_angle, PD::defaults::crease_angle)                                      \
  X(double, minimum_part_area, PD::defaults::minimum_part_area)                            \
  X(std::vector<int>, voxel_resolutions, PD::defaults::voxel_resolutions())                \
  X(unsigned int, number_of_neighbors, PD::defaults::number_of_neighbors)                  \
  X(double, curvature_percentile, PD::defaults::curvature_percentile)                      \
  X(bool, use_concave_curvature, PD::defaults::use_concave_curvature)                      \
  X(PD_cue_weights, cue_weights, PD::defaults::cue_weights)                                \
  X(double, freeze_ratio, PD::defaults::freeze_ratio)                                      \
  X(bool, use_density, PD::defaults::use_density)                                          \
  X(double, normalization_margin, PD::defaults::normalization_margin)                      \
  X(double, tsdf_truncation, PD::defaults::tsdf_truncation)                                \
  X(PD::Tsdf_sign_method, tsdf_sign_method, PD::defaults::tsdf_sign_method)                \
  X(int, grid_resolution, PD::defaults::grid_resolution)                                   \
  X(bool, adaptive_grid, PD::defaults::adaptive_grid)                                      \
  X(double, flow_zone_tolerance, PD::defaults::flow_zone_tolerance)                        \
  X(std::vector<double>, trust_region_scales, PD::defaults::trust_region_scales())         \
  X(double, body_seed_threshold, PD::defaults::body_seed_threshold)                        \
  X(double, minimum_body_volume, PD::defaults::minimum_body_volume)                        \
  X(double, minimum_surface_volume, PD::defaults::minimum_surface_volume)                  \
  X(double, exterior_penalty, PD::defaults::exterior_penalty)                              \
  X(double, coverage_target, PD::defaults::coverage_target)                                \
  X(double, roi_radius, PD::defaults::roi_radius)                                          \
  X(PD::Interior_weight_mode, interior_weight_mode, PD::defaults::interior_weight_mode)    \
  X(std::size_t, maximum_number_of_primitives, PD::defaults::maximum_number_of_primitives) \
  X(bool, use_freeze_zone, PD::defaults::use_freeze_zone)                                  \
  X(bool, use_tsdf_guidance, PD::defaults::use_tsdf_guidance)                              \
  X(bool, use_body_seeds, PD::defaults::use_body_seeds)                                    \
  X(int, fitting_resolution_cap, PD::defaults::fitting_resolution_cap)                     \
  X(bool, use_exterior_band_samples, PD::defaults::use_exterior_band_samples)              \
  X(bool, use_reachable_regions, PD::defaults::use_reachable_regions)                      \
  X(bool, use_seed_exclusion, PD::defaults::use_seed_exclusion)                            \
  X(int, maximum_solver_evaluations, PD::defaults::maximum_solver_evaluations)             \
  X(std::size_t, maximum_rejections_in_a_row, PD::defaults::maximum_rejections_in_a_row)   \
  X(bool, merge_primitives, PD::defaults::merge_primitives)                                \
  X(double, minimum_merge_iou, PD::defaults::minimum_merge_iou)                            \
  X(double, dihedral_percentile, PD::defaults::dihedral_percentile)                        \
  X(unsigned int, smoothing_iterations, PD::defaults::smoothing_iterations)                \
  X(double, minimum_patch_size, PD::defaults::minimum_patch_size)                          \
  X(double, patch_split_size, PD::defaults::patch_split_size)                              \
  X(double, vote_temperature, PD::defaults::vote_temperature)                              \
  X(double, boundary_smoothness, PD::defaults::boundary_smoothness)                        \
  X(bool, keep_residual_patches, PD::defaults::keep_residual_patches)                      \
  X(double, residual_tolerance, PD::defaults::residual_tolerance)                          \
  X(bool, merge_thin_sheets, PD::defaults::merge_thin_sheets)                              \
  X(double, maximum_merge_cost, PD::defaults::maximum_merge_cost)
// end of the settings

typedef std::array<double, 4> PD_cue_weights; // a macro argument cannot hold the comma

struct Decomposition_settings
{
#define PART_DECOMPOSITION_TOOLS_FIELD(TYPE, NAME, DEFAULT) TYPE NAME = DEFAULT;
  PART_DECOMPOSITION_TOOLS_SETTINGS(PART_DECOMPOSITION_TOOLS_FIELD)
#undef PART_DECOMPOSITION_TOOLS_FIELD
  // CGAL's own named parameters
  unsigned int number_of_points_per_face = PD::defaults::number_of_points_per_face;
  bool verbose = PD::defaults::verbose;
};

// Calls f(name, member pointer) for every field of Decomposition_settings, in table order.
template <typename F>
void for_each_setting(F&& f)
{
#define PART_DECOMPOSITION_TOOLS_VISIT(TYPE, NAME, DEFAULT) f(#NAME, &Decomposition_settings::NAME);
  PART_DECOMPOSITION_TOOLS_SETTINGS(PART_DECOMPOSITION_TOOLS_VISIT)
#undef PART_DECOMPOSITION_TOOLS_VISIT
  f("number_of_points_per_face", &Decomposition_settings::number_of_points_per_face);
  f("verbose", &Decomposition_settings::verbose);
}

// All the settings as one pack; the caller chains its own parameters (outputs, timings) after it
// with PD::parameters::combine().
inline auto named_parameters(const Decomposition_settings& s)
{
  namespace PDP = PD::parameters;
#define PART_DECOMPOSITION_TOOLS_PASS(TYPE, NAME, DEFAULT) , PDP::NAME(s.NAME)
  return PDP::combine(
    CGAL::parameters::number_of_points_per_face(s.number_of_points_per_face).verbose(s.verbose)
    PART_DECOMPOSITION_TOOLS_SETTINGS(PART_DECOMPOSITION_TOOLS_PASS));
#undef PART_DECOMPOSITION_TOOLS_PASS
}

// The names of the enumerators: the lower-case name of the enumerator first, then the short names
// that hitops took before (still accepted).
template <typename E>
struct Enumerator_name
{
  const char* name;
  E value;
};

inline const std::vector<Enumerator_name<PD::Tsdf_sign_method> >& enumerator_names(PD::Tsdf_sign_method)
{
  typedef PD::Tsdf_sign_method M;
  static const std::vector<Enumerator_name<M> > names = {
    {"automatic", M::AUTOMATIC}, {"inside_test", M::INSIDE_TEST}, {"winding_number", M::WINDING_NUMBER},
    {"flood_fill", M::FLOOD_FILL}, {"ray_votes", M::RAY_VOTES}, {"auto", M::AUTOMATIC}, {"inside", M::INSIDE_TEST},
    {"winding", M::WINDING_NUMBER}, {"flood", M::FLOOD_FILL}, {"votes", M::RAY_VOTES}};
  return names;
}

inline const std::vector<Enumerator_name<PD::Interior_weight_mode> >& enumerator_names(PD::Interior_weight_mode)
{
  typedef PD::Interior_weight_mode M;
  static const std::vector<Enumerator_name<M> > names = {
    {"one_shot", M::ONE_SHOT}, {"mps_reestimated", M::MPS_REESTIMATED}, {"one-shot", M::ONE_SHOT},
    {"mps", M::MPS_REESTIMATED}};
  return names;
}

// Values as text, as hitops reads and prints them; parse_value() throws std::invalid_argument with
// what it expects.

inline std::string format_value(double v)
{
  // the fewest digits that read back as v (0.15, not 0.14999999999999999), with all the digits of
  // the integer part (60, not 6e+01): as Python prints a float
  const int integer_digits = v == 0. ? 1 : int(std::floor(std::log10(std::fabs(v)))) + 1;
  for(int digits = 1;; ++digits)
  {
    std::ostringstream out;
    out.precision((std::min)(17, (std::max)(digits, integer_digits)));
    out << v;
    if(std::stod(out.str()) == v || digits >= 17) return out.str();
  }
}
inline std::string format_value(bool v) { return v ? "true" : "false"; }
template <typename T>
std::enable_if_t<std::is_integral<T>::value, std::string> format_value(T v) { return std::to_string(v); }
template <typename E>
std::enable_if_t<std::is_enum<E>::value, std::string> format_value(E v)
{
  for(const auto& n : enumerator_names(v))
    if(n.value == v) return n.name;
  return "?";
}
template <typename Range>
auto format_value(const Range& r) -> decltype(std::begin(r), std::string())
{
  std::string out;
  for(const auto& x : r) out += (out.empty() ? "" : ",") + format_value(x);
  return out;
}

inline void parse_value(const std::string& text, double& v)
{
  std::istringstream in(text);
  char extra;
  if(!(in >> v) || (in >> extra) || !std::isfinite(v)) throw std::invalid_argument("a number");
}
inline void parse_value(const std::string& text, bool& v)
{
  if(text == "true") v = true;
  else if(text == "false") v = false;
  else throw std::invalid_argument("true or false");
}
template <typename T>
std::enable_if_t<std::is_integral<T>::value> parse_value(const std::string& text, T& v)
{
  double x;
  parse_value(text, x);
  if(x < 0 || x != std::floor(x) || x > 1e9) throw std::invalid_argument("a non-negative integer");
  v = T(x);
}
template <typename E>
std::enable_if_t<std::is_enum<E>::value> parse_value(const std::string& text, E& v)
{
  std::string choices;
  for(const auto& n : enumerator_names(v))
  {
    if(text == n.name) { v = n.value; return; }
    choices += std::string(choices.empty() ? "" : ", ") + n.name;
  }
  throw std::invalid_argument("one of " + choices);
}
template <typename T>
void parse_value(const std::string& text, std::vector<T>& v)
{
  std::vector<T> out;
  std::stringstream in(text);
  for(std::string item; std::getline(in, item, ',');)
  {
    out.emplace_back();
    try { parse_value(item, out.back()); }
    catch(const std::invalid_argument& e) { throw std::invalid_argument("a comma-separated list of " + std::string(e.what()) + "s"); }
  }
  if(out.empty()) throw std::invalid_argument("a comma-separated list");
  v = out;
}
template <typename T, std::size_t N>
void parse_value(const std::string& text, std::array<T, N>& v)
{
  std::vector<T> out;
  parse_value(text, out);
  if(out.size() != N) throw std::invalid_argument(std::to_string(N) + " comma-separated values");
  std::copy(out.begin(), out.end(), v.begin());
}

} // namespace Part_decomposition_tools

#endif // PART_DECOMPOSITION_TOOLS_DECOMPOSITION_SETTINGS_H
