// Copyright (c) 2026 The Part_decomposition authors.
// All rights reserved.
//
// SPDX-License-Identifier: GPL-3.0-or-later

#ifndef PART_DECOMPOSITION_TEST_METHOD_SWITCHES_H
#define PART_DECOMPOSITION_TEST_METHOD_SWITCHES_H

#include <CGAL/Part_decomposition/parameters.h>

typedef CGAL::Part_decomposition::Method_variant Variant;

template <typename T>
struct Same_type
{
  typedef T type;
};

// The package's method with the switches `field` set to `value`, pair by pair.
inline Variant variant() { return Variant(); }

template <typename T, typename... Rest>
Variant variant(T Variant::*field, const typename Same_type<T>::type& value, const Rest&... rest)
{
  Variant v = variant(rest...);
  v.*field = value;
  return v;
}

// The named parameter `method_variant` of variant(pairs...).
template <typename... Pairs>
auto switches(const Pairs&... pairs)
{
  return CGAL::Part_decomposition::parameters::method_variant(variant(pairs...));
}

#endif // PART_DECOMPOSITION_TEST_METHOD_SWITCHES_H
