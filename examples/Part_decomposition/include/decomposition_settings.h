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
// The list is the library's, CGAL_PART_DECOMPOSITION_PARAMETERS.

#include <CGAL/Part_decomposition/decompose.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <iterator>
#include <optional>
#include <sstream>
#include <stdexcept>
#include <string>
#include <type_traits>
#include <vector>

namespace Part_decomposition_tools {

namespace PD = CGAL::Part_decomposition;

// Every named parameter of PD::parameter_table that holds a value, at its default: the library's
// own structure of the values of decompose(), one field per parameter, passed by
// named_parameters() (the reader's weld_tolerance is passed too, and ignored).
typedef PD::internal::Pipeline_values Decomposition_settings;

// Calls f(name, member pointer) for every field of Decomposition_settings, in table order.
template <typename F>
void for_each_setting(F&& f)
{
#define PART_DECOMPOSITION_TOOLS_VISIT(NAME, ...) f(#NAME, &Decomposition_settings::NAME);
  CGAL_PART_DECOMPOSITION_PARAMETERS(PART_DECOMPOSITION_TOOLS_VISIT, PART_DECOMPOSITION_TOOLS_VISIT)
#undef PART_DECOMPOSITION_TOOLS_VISIT
}

// All the settings as one pack; the caller chains its own parameters (outputs, timings) after it
// with PD::parameters::combine().
inline auto named_parameters(const Decomposition_settings& s)
{
  namespace PDP = PD::parameters;
#define PART_DECOMPOSITION_TOOLS_PASS(NAME, ...) , PDP::NAME(s.NAME)
#define PART_DECOMPOSITION_TOOLS_CGAL(...)
  // CGAL's own parameters by CGAL's functions
  return PDP::combine(
    CGAL::parameters::number_of_points_per_face(s.number_of_points_per_face).verbose(s.verbose)
    CGAL_PART_DECOMPOSITION_PARAMETERS(PART_DECOMPOSITION_TOOLS_PASS, PART_DECOMPOSITION_TOOLS_CGAL));
#undef PART_DECOMPOSITION_TOOLS_CGAL
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

template <typename T>
std::string format_value(const std::optional<T>& v)
{
  return v ? format_value(*v) : std::string("none");
}

// The switches of the method as the items NAME=VALUE of those that differ from the package's method.
inline std::string format_value(const PD::Method_variant& v)
{
  const PD::Method_variant d;
  std::string out;
#define PART_DECOMPOSITION_TOOLS_SWITCH(NAME, ...)                                                \
  if(v.NAME != d.NAME) out += (out.empty() ? "" : ",") + std::string(#NAME "=") + format_value(v.NAME);
  CGAL_PART_DECOMPOSITION_METHOD_SWITCHES(PART_DECOMPOSITION_TOOLS_SWITCH)
#undef PART_DECOMPOSITION_TOOLS_SWITCH
  return out.empty() ? "default" : out;
}

// The switch `name` of `v` as text; empty if there is none of that name.
inline std::string format_switch(const PD::Method_variant& v, const std::string& name)
{
#define PART_DECOMPOSITION_TOOLS_SWITCH(NAME, ...)                                                \
  if(name == #NAME) return format_value(v.NAME);
  CGAL_PART_DECOMPOSITION_METHOD_SWITCHES(PART_DECOMPOSITION_TOOLS_SWITCH)
#undef PART_DECOMPOSITION_TOOLS_SWITCH
  return "";
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
void parse_value(const std::string& text, std::optional<T>& v)
{
  if(text == "none") { v.reset(); return; }
  T x;
  parse_value(text, x);
  if(x < T(1)) throw std::invalid_argument("at least 1, or none");
  v = x;
}

// Comma-separated items applied in order to the switches: default, paper_literal, or NAME=VALUE.
inline void parse_value(const std::string& text, PD::Method_variant& v)
{
  std::stringstream in(text);
  for(std::string item; std::getline(in, item, ',');)
  {
    const std::size_t eq = item.find('=');
    const std::string name = item.substr(0, eq), value = eq == std::string::npos ? "" : item.substr(eq + 1);
    bool known = false;
    if(item == "default") v = PD::Method_variant(), known = true;
    if(item == "paper_literal") v = PD::Method_variant::paper_literal(), known = true;
#define PART_DECOMPOSITION_TOOLS_SWITCH(NAME, ...)                                                \
    if(eq != std::string::npos && name == #NAME) parse_value(value, v.NAME), known = true;
    CGAL_PART_DECOMPOSITION_METHOD_SWITCHES(PART_DECOMPOSITION_TOOLS_SWITCH)
#undef PART_DECOMPOSITION_TOOLS_SWITCH
    if(!known) throw std::invalid_argument("default, paper_literal or SWITCH=VALUE items, comma-separated");
  }
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
