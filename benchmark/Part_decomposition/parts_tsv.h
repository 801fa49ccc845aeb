// Copyright (c) 2026 The Part_decomposition authors.
// All rights reserved.
//
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Author(s)     : The Part_decomposition authors

// NAME.parts.tsv: the true superquadrics of a generated shape, one per line, written by
// generate_superquadric_unions and read by benchmark_segmentation. Its label in NAME.seg is `id`.
//
// Columns (tab-separated, header line first):
//   id  cx cy cz  a1 a2 a3  e1 e2  r00 r01 r02 r10 r11 r12 r20 r21 r22  thin  thickness_over_diagonal
// with the conventions of CGAL::Part_decomposition::Superquadric: semi-axes (a1, a2, a3) along the
// local x, y, z axes, e1 the exponent along local z, e2 in the local xy plane, the rotation row by
// row with column j the local axis j in world coordinates. thin = 1 if the smallest semi-axis is at
// most 1/8 of the largest; thickness_over_diagonal = 2 min(a) over the mesh's bounding-box diagonal.
#ifndef PD_BENCHMARK_PARTS_TSV_H
#define PD_BENCHMARK_PARTS_TSV_H

#include <algorithm>
#include <array>
#include <cstddef>
#include <cstdlib>
#include <fstream>
#include <iomanip>
#include <ostream>
#include <sstream>
#include <string>
#include <vector>

namespace pd_benchmark {

struct True_primitive
{
  std::size_t id = 0;
  std::array<double, 3> center = {{0., 0., 0.}};
  std::array<double, 3> semi_axes = {{1., 1., 1.}};
  double epsilon1 = 1., epsilon2 = 1.;
  std::array<double, 9> rotation = {{1., 0., 0., 0., 1., 0., 0., 0., 1.}};
  bool thin = false;
  double thickness_over_diagonal = 0.;

  double smallest_semi_axis() const { return *std::min_element(semi_axes.begin(), semi_axes.end()); }
};

// The non-empty items of `s` between the separators (the lists of the programs' options).
inline std::vector<std::string> split(const std::string& s, char sep)
{
  std::vector<std::string> out;
  std::string item;
  std::istringstream in(s);
  while(std::getline(in, item, sep))
    if(!item.empty()) out.push_back(item);
  return out;
}

// The rule of the data set: the smallest semi-axis at most 1/8 of the largest.
inline bool is_thin(const std::array<double, 3>& a)
{
  return 8. * *std::min_element(a.begin(), a.end()) <= *std::max_element(a.begin(), a.end());
}

inline const char* parts_tsv_header()
{
  return "id\tcx\tcy\tcz\ta1\ta2\ta3\te1\te2\tr00\tr01\tr02\tr10\tr11\tr12\tr20\tr21\tr22\tthin"
         "\tthickness_over_diagonal";
}

inline void write_parts_tsv(std::ostream& out, const std::vector<True_primitive>& parts)
{
  out << parts_tsv_header() << '\n' << std::setprecision(9);
  for(const True_primitive& p : parts)
  {
    out << p.id;
    for(double x : p.center) out << '\t' << x;
    for(double x : p.semi_axes) out << '\t' << x;
    out << '\t' << p.epsilon1 << '\t' << p.epsilon2;
    for(double x : p.rotation) out << '\t' << x;
    out << '\t' << (p.thin ? 1 : 0) << '\t' << p.thickness_over_diagonal << '\n';
  }
}

// Reads the columns by name (any order, extra columns ignored); false with a message on error.
inline bool read_parts_tsv(const std::string& path, std::vector<True_primitive>& parts, std::string& error)
{
  parts.clear();
  std::ifstream in(path);
  if(!in) { error = "cannot open " + path; return false; }
  auto fields = [](const std::string& line) {
    std::vector<std::string> f;
    std::string item;
    std::istringstream ls(line);
    while(std::getline(ls, item, '\t')) f.push_back(item);
    return f;
  };
  std::string line;
  std::getline(in, line);
  const std::vector<std::string> header = fields(line);
  const std::vector<std::string> wanted = fields(parts_tsv_header());
  std::vector<std::size_t> column;
  for(const std::string& w : wanted)
  {
    const std::size_t c = std::size_t(std::find(header.begin(), header.end(), w) - header.begin());
    if(c == header.size()) { error = path + ": no column " + w; return false; }
    column.push_back(c);
  }
  while(std::getline(in, line))
  {
    if(!line.empty() && line.back() == '\r') line.pop_back();
    if(line.empty()) continue;
    const std::vector<std::string> f = fields(line);
    std::vector<double> v;
    for(std::size_t c : column)
    {
      if(c >= f.size()) { error = path + ": short line"; return false; }
      v.push_back(std::strtod(f[c].c_str(), nullptr));
    }
    True_primitive p;
    p.id = std::size_t(v[0]);
    for(int i = 0; i < 3; ++i) p.center[i] = v[1 + i], p.semi_axes[i] = v[4 + i];
    p.epsilon1 = v[7];
    p.epsilon2 = v[8];
    for(int i = 0; i < 9; ++i) p.rotation[i] = v[9 + i];
    p.thin = v[18] != 0.;
    p.thickness_over_diagonal = v[19];
    parts.push_back(p);
  }
  return true;
}

} // namespace pd_benchmark

#endif // PD_BENCHMARK_PARTS_TSV_H
