// render_mesh: a small offscreen software rasterizer for the figures of the manual.
//
// Renders triangle meshes (OFF, PLY) with per-face colours, coloured point sets (PLY without faces,
// drawn as voxel cubes) and images (binary PPM), several panels side by side, into one PNG. Flat
// shading, orthographic camera, z-buffer, supersampling. The rasterizer and PNG writer are those of
// examples/Part_decomposition/include/part_renderer.h, which hitops draws its thumbnails with.
//
// usage: render_mesh -o OUT.png [options] PANEL [PANEL ...]
//   PANEL    one or more layers joined by '+'; a layer is FILE[@option,option...]; the items
//            view=AZ,EL  up=AXIS  zoom=Z  among the layers give the panel a camera of its own
//   layer options:
//     color=RRGGBB      one colour for the whole layer (default: the file's colours, else grey)
//     components        one palette colour per connected component (e.g. one per superquadric)
//     labels=FILE       one palette colour per face label, one label per line in file order
//     alpha=A           translucent layer, 0 < A < 1 (drawn over the opaque layers)
//     voxel=S           the edge of the cubes of a point set (default: its grid spacing)
//   options:
//     --panel WxH       pixels of each panel (default 400x400)
//     --columns N       panels per row (default: all in one row)
//     --view AZ,EL      azimuth and elevation of the camera in degrees (default 30,20)
//     --up x|y|z|-x|-y|-z   the axis that points up in the picture (default y)
//     --frame shared|own    one framing for all panels (default) or each its own
//     --zoom Z          scales the framing (default 1)
//     --ss N            supersampling factor (default 3)
//     --background RRGGBB   (default ffffff)
//
// The palette is the one of the hitops tool (part_palette.h), so that part k and primitive k have
// the same colour.

#include "part_palette.h"
#include "part_renderer.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <cstdlib>
#include <cstring>
#include <fstream>
#include <iostream>
#include <limits>
#include <map>
#include <numeric>
#include <sstream>
#include <stdexcept>
#include <string>
#include <vector>

namespace {

using namespace Part_decomposition_tools::render;

// The colour of part k, as in hitops.
Rgb palette(std::size_t k) { return Part_decomposition_tools::part_rgb(k); }

Rgb parse_hex(const std::string& s)
{
  if(s.size() != 6) throw std::runtime_error("colour '" + s + "' is not RRGGBB");
  const unsigned long v = std::stoul(s, nullptr, 16);
  return {{std::uint8_t(v >> 16), std::uint8_t(v >> 8), std::uint8_t(v)}};
}

// ------------------------------------------------------------------------------------------
// Input

struct Mesh
{
  std::vector<Vec3> points;
  std::vector<std::array<std::size_t, 3> > triangles;
  std::vector<Rgb> face_colors;   // empty, or one per triangle
  std::vector<Rgb> point_colors;  // empty, or one per point (vertex colours, or point-set colours)
  std::vector<std::size_t> source_face; // the polygon of the file each triangle comes from
};

std::string read_token(std::istream& in)
{
  std::string t;
  while(in >> t)
  {
    if(t[0] == '#')
    {
      std::string rest;
      std::getline(in, rest);
      continue;
    }
    return t;
  }
  throw std::runtime_error("unexpected end of file");
}

void add_polygon(Mesh& m, const std::vector<std::size_t>& poly, std::size_t source)
{
  for(std::size_t i = 1; i + 1 < poly.size(); ++i)
  {
    m.triangles.push_back({{poly[0], poly[i], poly[i + 1]}});
    m.source_face.push_back(source);
  }
}

Mesh read_off(const std::string& file)
{
  std::ifstream in(file);
  if(!in) throw std::runtime_error("cannot open " + file);
  std::string head = read_token(in);
  if(head.find("OFF") == std::string::npos) throw std::runtime_error(file + " is not an OFF file");
  Mesh m;
  const std::size_t nv = std::stoul(read_token(in)), nf = std::stoul(read_token(in));
  read_token(in);
  m.points.resize(nv);
  for(Vec3& p : m.points)
    for(double& c : p) c = std::stod(read_token(in));
  std::string line;
  std::getline(in, line);
  bool colored = false;
  std::vector<Rgb> colors;
  for(std::size_t f = 0; f < nf; ++f)
  {
    do
    {
      if(!std::getline(in, line)) throw std::runtime_error(file + ": too few faces");
    } while(line.find_first_not_of(" \t\r") == std::string::npos || line[line.find_first_not_of(" \t\r")] == '#');
    std::istringstream ls(line);
    std::size_t n;
    ls >> n;
    std::vector<std::size_t> poly(n);
    for(std::size_t& v : poly) ls >> v;
    std::vector<double> extra;
    double x;
    while(ls >> x) extra.push_back(x);
    Rgb c{{200, 200, 200}};
    if(extra.size() >= 3)
    {
      colored = true;
      const bool unit = extra[0] <= 1. && extra[1] <= 1. && extra[2] <= 1. && line.find('.') != std::string::npos;
      for(int i = 0; i < 3; ++i) c[i] = std::uint8_t(std::lround(std::min(255., std::max(0., unit ? 255 * extra[i] : extra[i]))));
    }
    const std::size_t before = m.triangles.size();
    add_polygon(m, poly, f);
    colors.insert(colors.end(), m.triangles.size() - before, c);
  }
  if(colored) m.face_colors = colors;
  return m;
}

struct Ply_property
{
  std::string name, type, count_type; // count_type non-empty for lists
};

struct Ply_element
{
  std::string name;
  std::size_t count = 0;
  std::vector<Ply_property> properties;
};

struct Ply_header
{
  std::vector<Ply_element> elements;
  bool ascii = true;
};

Ply_header read_ply_header(std::istream& in, const std::string& file)
{
  Ply_header h;
  std::string line, format;
  std::getline(in, line);
  if(line.compare(0, 3, "ply") != 0) throw std::runtime_error(file + " is not a PLY file");
  while(std::getline(in, line))
  {
    if(!line.empty() && line.back() == '\r') line.pop_back();
    std::istringstream ls(line);
    std::string key;
    ls >> key;
    if(key == "format") ls >> format;
    else if(key == "element")
    {
      Ply_element e;
      ls >> e.name >> e.count;
      h.elements.push_back(e);
    }
    else if(key == "property")
    {
      Ply_property p;
      ls >> p.type;
      if(p.type == "list") ls >> p.count_type >> p.type;
      ls >> p.name;
      if(h.elements.empty()) throw std::runtime_error(file + ": property before element");
      h.elements.back().properties.push_back(p);
    }
    else if(key == "end_header") break;
  }
  h.ascii = format == "ascii";
  if(!h.ascii && format != "binary_little_endian") throw std::runtime_error(file + ": unsupported PLY format " + format);
  return h;
}

int ply_type_size(const std::string& t)
{
  if(t == "char" || t == "uchar" || t == "int8" || t == "uint8") return 1;
  if(t == "short" || t == "ushort" || t == "int16" || t == "uint16") return 2;
  if(t == "int" || t == "uint" || t == "float" || t == "int32" || t == "uint32" || t == "float32") return 4;
  if(t == "double" || t == "float64") return 8;
  throw std::runtime_error("unknown PLY type " + t);
}

// One value of type `t`, as a double.
double read_ply_value(std::istream& in, bool ascii, const std::string& t, const std::string& file)
{
  if(ascii)
  {
    std::string s;
    if(!(in >> s)) throw std::runtime_error(file + ": truncated");
    return std::stod(s);
  }
  unsigned char b[8];
  const int n = ply_type_size(t);
  if(!in.read(reinterpret_cast<char*>(b), n)) throw std::runtime_error(file + ": truncated");
  if(t == "char" || t == "int8") return double(std::int8_t(b[0]));
  if(t == "uchar" || t == "uint8") return double(b[0]);
  if(t == "short" || t == "int16") { std::int16_t v; std::memcpy(&v, b, 2); return v; }
  if(t == "ushort" || t == "uint16") { std::uint16_t v; std::memcpy(&v, b, 2); return v; }
  if(t == "int" || t == "int32") { std::int32_t v; std::memcpy(&v, b, 4); return v; }
  if(t == "uint" || t == "uint32") { std::uint32_t v; std::memcpy(&v, b, 4); return v; }
  if(t == "float" || t == "float32") { float v; std::memcpy(&v, b, 4); return v; }
  double v;
  std::memcpy(&v, b, 8);
  return v;
}

// One item of an element: its position, colour and vertex indices.
struct Ply_item
{
  Vec3 p{{0, 0, 0}};
  Rgb c{{200, 200, 200}};
  std::vector<std::size_t> poly;
};

// Reads one item of `e`; sets `colored` when it has a colour.
Ply_item read_ply_item(std::istream& in, bool ascii, const Ply_element& e, const std::string& file, bool& colored)
{
  Ply_item item;
  for(const Ply_property& prop : e.properties)
  {
    if(!prop.count_type.empty())
    {
      const std::size_t n = std::size_t(read_ply_value(in, ascii, prop.count_type, file));
      std::vector<std::size_t> values(n);
      for(std::size_t& v : values) v = std::size_t(read_ply_value(in, ascii, prop.type, file));
      if(prop.name == "vertex_indices" || prop.name == "vertex_index") item.poly = values;
      continue;
    }
    const double v = read_ply_value(in, ascii, prop.type, file);
    if(prop.name == "x") item.p[0] = v;
    else if(prop.name == "y") item.p[1] = v;
    else if(prop.name == "z") item.p[2] = v;
    else if(prop.name == "red" || prop.name == "green" || prop.name == "blue")
    {
      const int ch = prop.name == "red" ? 0 : prop.name == "green" ? 1 : 2;
      const bool unit = prop.type == "float" || prop.type == "double";
      item.c[ch] = std::uint8_t(std::lround(std::min(255., std::max(0., unit ? 255 * v : v))));
      colored = true;
    }
  }
  return item;
}

// PLY: ascii or binary little endian; vertex x y z [red green blue]; face vertex_indices [red green blue].
Mesh read_ply(const std::string& file)
{
  std::ifstream in(file, std::ios::binary);
  if(!in) throw std::runtime_error("cannot open " + file);
  const Ply_header h = read_ply_header(in, file);
  Mesh m;
  std::vector<Rgb> face_colors;
  bool vertex_colored = false, face_colored = false;
  for(const Ply_element& e : h.elements)
    for(std::size_t i = 0; i < e.count; ++i)
    {
      const Ply_item item = read_ply_item(in, h.ascii, e, file, e.name == "vertex" ? vertex_colored : face_colored);
      if(e.name == "vertex")
      {
        m.points.push_back(item.p);
        m.point_colors.push_back(item.c);
      }
      else if(e.name == "face")
      {
        const std::size_t before = m.triangles.size();
        add_polygon(m, item.poly, i);
        face_colors.insert(face_colors.end(), m.triangles.size() - before, item.c);
      }
    }
  if(face_colored) m.face_colors = face_colors;
  if(!vertex_colored) m.point_colors.clear();
  return m;
}

Image read_ppm(const std::string& file)
{
  std::ifstream in(file, std::ios::binary);
  if(!in) throw std::runtime_error("cannot open " + file);
  if(read_token(in) != "P6") throw std::runtime_error(file + " is not a binary PPM (P6)");
  Image img;
  img.width = std::stoi(read_token(in));
  img.height = std::stoi(read_token(in));
  if(std::stoi(read_token(in)) != 255) throw std::runtime_error(file + ": only 8-bit PPM");
  in.get();
  img.pixels.resize(std::size_t(img.width) * std::size_t(img.height));
  if(!in.read(reinterpret_cast<char*>(img.pixels.data()), std::streamsize(img.pixels.size() * 3)))
    throw std::runtime_error(file + ": truncated");
  return img;
}

std::string lower_extension(const std::string& file)
{
  const std::size_t dot = file.find_last_of('.');
  std::string ext = dot == std::string::npos ? "" : file.substr(dot + 1);
  for(char& c : ext) c = char(std::tolower(static_cast<unsigned char>(c)));
  return ext;
}

// ------------------------------------------------------------------------------------------
// Scene

struct Layer
{
  std::vector<Triangle> triangles;
  double alpha = 1.;
  bool is_image = false;
  Image image;
};

struct Panel
{
  std::vector<Layer> layers;
  bool own_view = false; // a view of its own, framed on its own
  double azimuth = 0, elevation = 0, zoom = 1;
  std::string up;
};

// One colour per connected component (triangles sharing a vertex index).
std::vector<std::size_t> component_of_triangles(const Mesh& m)
{
  std::vector<std::size_t> parent(m.points.size());
  std::iota(parent.begin(), parent.end(), std::size_t(0));
  auto find = [&](std::size_t x) {
    while(parent[x] != x) x = parent[x] = parent[parent[x]];
    return x;
  };
  for(const auto& t : m.triangles)
  {
    const std::size_t a = find(t[0]), b = find(t[1]), c = find(t[2]);
    parent[b] = a;
    parent[find(c)] = find(a);
  }
  std::map<std::size_t, std::size_t> id; // roots numbered by first appearance in triangle order
  std::vector<std::size_t> result;
  for(const auto& t : m.triangles)
    result.push_back(id.emplace(find(t[0]), id.size()).first->second);
  return result;
}

Layer make_layer(const std::string& spec)
{
  std::string file = spec, options;
  const std::size_t at = spec.find('@');
  if(at != std::string::npos)
  {
    file = spec.substr(0, at);
    options = spec.substr(at + 1);
  }
  Layer layer;
  bool has_color = false, components = false;
  Rgb color{{200, 200, 200}};
  double voxel = 0.;
  std::string labels_file;
  std::istringstream os(options);
  std::string opt;
  while(std::getline(os, opt, ','))
  {
    if(opt.empty()) continue;
    const std::size_t eq = opt.find('=');
    const std::string key = opt.substr(0, eq), value = eq == std::string::npos ? "" : opt.substr(eq + 1);
    if(key == "color") { color = parse_hex(value); has_color = true; }
    else if(key == "components") components = true;
    else if(key == "labels") labels_file = value;
    else if(key == "alpha") layer.alpha = std::stod(value);
    else if(key == "voxel") voxel = std::stod(value);
    else throw std::runtime_error("unknown layer option '" + opt + "'");
  }
  const std::string ext = lower_extension(file);
  if(ext == "ppm")
  {
    layer.is_image = true;
    layer.image = read_ppm(file);
    return layer;
  }
  Mesh m;
  if(ext == "off") m = read_off(file);
  else if(ext == "ply") m = read_ply(file);
  else throw std::runtime_error("unsupported file " + file);

  if(m.triangles.empty())
  {
    // A point set: one cube per point, of the spacing of the grid the points come from.
    if(voxel <= 0.)
    {
      double spacing = std::numeric_limits<double>::infinity();
      for(int axis = 0; axis < 3; ++axis)
      {
        std::vector<double> c;
        for(const Vec3& p : m.points) c.push_back(p[std::size_t(axis)]);
        std::sort(c.begin(), c.end());
        const double span = c.empty() ? 0. : c.back() - c.front();
        for(std::size_t i = 1; i < c.size(); ++i)
          if(c[i] - c[i - 1] > 1e-6 * span) spacing = std::min(spacing, c[i] - c[i - 1]);
      }
      voxel = std::isfinite(spacing) ? spacing : 1.;
    }
    const double h = voxel / 2.;
    static const int quads[6][4] = {{0, 2, 3, 1}, {4, 5, 7, 6}, {0, 1, 5, 4}, {2, 6, 7, 3}, {0, 4, 6, 2}, {1, 3, 7, 5}};
    for(std::size_t i = 0; i < m.points.size(); ++i)
    {
      const Vec3& p = m.points[i];
      Vec3 c[8];
      for(int k = 0; k < 8; ++k)
        c[k] = {{p[0] + (k & 1 ? h : -h), p[1] + (k & 2 ? h : -h), p[2] + (k & 4 ? h : -h)}};
      const Rgb col = has_color ? color : (m.point_colors.empty() ? color : m.point_colors[i]);
      for(const auto& q : quads)
      {
        layer.triangles.push_back({{{c[q[0]], c[q[1]], c[q[2]]}}, col});
        layer.triangles.push_back({{{c[q[0]], c[q[2]], c[q[3]]}}, col});
      }
    }
    return layer;
  }

  std::vector<std::size_t> labels;
  if(!labels_file.empty())
  {
    std::ifstream in(labels_file);
    if(!in) throw std::runtime_error("cannot open " + labels_file);
    std::size_t l;
    while(in >> l) labels.push_back(l);
  }
  const std::vector<std::size_t> component = components ? component_of_triangles(m) : std::vector<std::size_t>();
  for(std::size_t t = 0; t < m.triangles.size(); ++t)
  {
    Triangle tri;
    for(int k = 0; k < 3; ++k) tri.p[std::size_t(k)] = m.points.at(m.triangles[t][std::size_t(k)]);
    if(has_color) tri.color = color;
    else if(components) tri.color = palette(component[t]);
    else if(!labels.empty())
    {
      if(m.source_face[t] >= labels.size()) throw std::runtime_error(labels_file + ": fewer labels than faces");
      tri.color = palette(labels[m.source_face[t]]);
    }
    else if(!m.face_colors.empty()) tri.color = m.face_colors[t];
    else if(!m.point_colors.empty())
    {
      int s[3] = {0, 0, 0};
      for(int k = 0; k < 3; ++k)
        for(int ch = 0; ch < 3; ++ch) s[ch] += m.point_colors[m.triangles[t][std::size_t(k)]][std::size_t(ch)];
      tri.color = {{std::uint8_t(s[0] / 3), std::uint8_t(s[1] / 3), std::uint8_t(s[2] / 3)}};
    }
    else tri.color = color;
    layer.triangles.push_back(tri);
  }
  return layer;
}

// ------------------------------------------------------------------------------------------
// Framing and drawing (the rasterizer itself is in part_renderer.h)

Bounds camera_bounds(const Panel& panel, const Camera& cam)
{
  Bounds b;
  for(const Layer& l : panel.layers) add_bounds(b, l.triangles, cam);
  return b;
}
// ------------------------------------------------------------------------------------------

struct Options
{
  std::string output;
  int panel_width = 400, panel_height = 400, columns = 0, ss = 3;
  double azimuth = 30, elevation = 20, zoom = 1;
  std::string up = "y";
  bool shared_frame = true;
  Rgb background{{255, 255, 255}};
  std::vector<std::string> panels;
};

Options parse(int argc, char** argv)
{
  Options o;
  for(int i = 1; i < argc; ++i)
  {
    const std::string a = argv[i];
    auto value = [&]() -> std::string {
      if(i + 1 >= argc) throw std::runtime_error("option " + a + " needs a value");
      return argv[++i];
    };
    if(a == "-o") o.output = value();
    else if(a == "--panel")
    {
      const std::string v = value();
      const std::size_t x = v.find('x');
      if(x == std::string::npos) throw std::runtime_error("--panel expects WxH");
      o.panel_width = std::stoi(v.substr(0, x));
      o.panel_height = std::stoi(v.substr(x + 1));
    }
    else if(a == "--columns") o.columns = std::stoi(value());
    else if(a == "--view")
    {
      const std::string v = value();
      const std::size_t c = v.find(',');
      if(c == std::string::npos) throw std::runtime_error("--view expects AZ,EL");
      o.azimuth = std::stod(v.substr(0, c));
      o.elevation = std::stod(v.substr(c + 1));
    }
    else if(a == "--up") o.up = value();
    else if(a == "--frame") o.shared_frame = value() != "own";
    else if(a == "--zoom") o.zoom = std::stod(value());
    else if(a == "--ss") o.ss = std::max(1, std::stoi(value()));
    else if(a == "--background") o.background = parse_hex(value());
    else if(a == "-h" || a == "--help")
    {
      std::cout << "usage: render_mesh -o OUT.png [--panel WxH] [--columns N] [--view AZ,EL] [--up AXIS]\n"
                   "                   [--frame shared|own] [--zoom Z] [--ss N] [--background RRGGBB]\n"
                   "                   PANEL [PANEL ...]\n"
                   "PANEL = LAYER[+LAYER...], LAYER = FILE.(off|ply|ppm)[@color=RRGGBB|components|labels=FILE|alpha=A|voxel=S,...]\n";
      std::exit(EXIT_SUCCESS);
    }
    else if(!a.empty() && a[0] == '-') throw std::runtime_error("unknown option " + a);
    else o.panels.push_back(a);
  }
  if(o.output.empty() || o.panels.empty()) throw std::runtime_error("usage: render_mesh -o OUT.png PANEL [PANEL ...] (--help)");
  return o;
}

// One panel of `spec`: layers separated by '+', and view=AZ,EL, up=AXIS, zoom=F of its own.
Panel parse_panel(const std::string& spec, const Options& o)
{
  Panel p;
  std::istringstream ss(spec);
  std::string layer;
  p.azimuth = o.azimuth;
  p.elevation = o.elevation;
  p.zoom = o.zoom;
  p.up = o.up;
  while(std::getline(ss, layer, '+'))
  {
    if(layer.empty()) continue;
    if(layer.compare(0, 5, "view=") == 0)
    {
      const std::size_t c = layer.find(',');
      if(c == std::string::npos) throw std::runtime_error("view= expects AZ,EL");
      p.azimuth = std::stod(layer.substr(5, c - 5));
      p.elevation = std::stod(layer.substr(c + 1));
      p.own_view = true;
    }
    else if(layer.compare(0, 3, "up=") == 0)
    {
      p.up = layer.substr(3);
      p.own_view = true;
    }
    else if(layer.compare(0, 5, "zoom=") == 0)
    {
      p.zoom = std::stod(layer.substr(5));
      p.own_view = true;
    }
    else p.layers.push_back(make_layer(layer));
  }
  return p;
}

// The bounds, in the camera's frame, of the panels that share the common view.
Bounds shared_bounds(const std::vector<Panel>& panels, const Camera& cam)
{
  Bounds shared;
  for(const Panel& p : panels)
  {
    if(p.own_view) continue;
    const Bounds b = camera_bounds(p, cam);
    if(b.empty()) continue;
    shared.add(b.lo[0], b.lo[1], b.lo[2]);
    shared.add(b.hi[0], b.hi[1], b.hi[2]);
  }
  return shared;
}

// The image layers of a panel at (px, py) of size pw x ph, scaled to fit it with nearest-neighbour
// sampling (voxel slices).
void draw_images(Canvas& cv, const Panel& panel, int px, int py, int pw, int ph)
{
  for(const Layer& l : panel.layers)
  {
    if(!l.is_image) continue;
    const double f = 0.92 * std::min(double(pw) / l.image.width, double(ph) / l.image.height);
    const int w = int(l.image.width * f), h = int(l.image.height * f);
    const int x0 = px + (pw - w) / 2, y0 = py + (ph - h) / 2;
    for(int y = 0; y < h; ++y)
      for(int x = 0; x < w; ++x)
      {
        const Rgb& c = l.image.pixels[std::size_t(std::min(l.image.height - 1, int(y / f))) * std::size_t(l.image.width) +
                                      std::size_t(std::min(l.image.width - 1, int(x / f)))];
        cv.color[std::size_t(y0 + y) * std::size_t(cv.width) + std::size_t(x0 + x)] = {{c[0] / 255., c[1] / 255., c[2] / 255.}};
      }
  }
}

// The 3D layers of a panel, opaque ones first, outlined, copied into `cv` at (px, py). Each panel is
// rendered on its own canvas so that nothing spills over its neighbours.
void draw_meshes(Canvas& cv, const Panel& panel, Camera pc, const Bounds& frame_bounds, int px, int py, int pw,
                 int ph, const Vec3& bg)
{
  frame(pc, frame_bounds, pw, ph, panel.zoom);
  Canvas local(pw, ph, bg);
  for(const Layer& l : panel.layers)
    if(!l.is_image && l.alpha >= 1.)
      for(const Triangle& t : l.triangles) rasterize(local, t, pc, pw / 2, ph / 2, 1.);
  for(const Layer& l : panel.layers)
    if(!l.is_image && l.alpha < 1.)
      for(const Triangle& t : l.triangles) rasterize(local, t, pc, pw / 2, ph / 2, l.alpha);
  outline_and_copy(cv, local, pc, px, py);
}

} // namespace

int main(int argc, char** argv)
{
  try
  {
    const Options o = parse(argc, argv);
    std::vector<Panel> panels;
    for(const std::string& spec : o.panels) panels.push_back(parse_panel(spec, o));
    const int n = int(panels.size());
    const int columns = o.columns > 0 ? std::min(o.columns, n) : n;
    const int rows = (n + columns - 1) / columns;
    const int s = o.ss, pw = o.panel_width * s, ph = o.panel_height * s;
    const int width = columns * pw, height = rows * ph;

    Camera cam;
    orient(cam, axis_vector(o.up), o.azimuth, o.elevation);
    const Bounds shared = shared_bounds(panels, cam);
    const Vec3 bg{{o.background[0] / 255., o.background[1] / 255., o.background[2] / 255.}};
    Canvas cv(width, height, bg);
    for(int pi = 0; pi < n; ++pi)
    {
      const Panel& panel = panels[std::size_t(pi)];
      const int px = (pi % columns) * pw, py = (pi / columns) * ph;
      draw_images(cv, panel, px, py, pw, ph);
      Camera pc = cam;
      if(panel.own_view) orient(pc, axis_vector(panel.up), panel.azimuth, panel.elevation);
      const Bounds own = camera_bounds(panel, pc);
      if(own.empty()) continue;
      draw_meshes(cv, panel, pc, o.shared_frame && !panel.own_view ? shared : own, px, py, pw, ph, bg);
    }
    const int W = width / s, H = height / s;
    Image image;
    image.width = W;
    image.height = H;
    image.pixels = downsample(cv, s, W, H);
    write_png(o.output, image);
    std::cout << "wrote " << o.output << " (" << W << "x" << H << ", " << n << " panels)" << std::endl;
  }
  catch(const std::exception& e)
  {
    std::cerr << "render_mesh: " << e.what() << std::endl;
    return EXIT_FAILURE;
  }
  return EXIT_SUCCESS;
}
