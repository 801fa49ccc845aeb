// render_mesh: a small offscreen software rasterizer for the figures of the manual.
//
// Renders triangle meshes (OFF, PLY) with per-face colours, coloured point sets (PLY without faces,
// drawn as voxel cubes) and images (binary PPM), several panels side by side, into one PNG. Flat
// shading, orthographic camera, z-buffer, supersampling; no dependency but the standard library
// (the PNG writer carries its own deflate coder), so the pictures can be regenerated anywhere.
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
// The palette is the one of the hitops tool, so that part k and primitive k have the same colour.

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

typedef std::array<double, 3> Vec3;
typedef std::array<std::uint8_t, 3> Rgb;

Vec3 sub(const Vec3& a, const Vec3& b) { return {{a[0] - b[0], a[1] - b[1], a[2] - b[2]}}; }
Vec3 cross(const Vec3& a, const Vec3& b)
{
  return {{a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]}};
}
double dot(const Vec3& a, const Vec3& b) { return a[0] * b[0] + a[1] * b[1] + a[2] * b[2]; }
Vec3 normalized(const Vec3& a)
{
  const double n = std::sqrt(dot(a, a));
  return n > 0 ? Vec3{{a[0] / n, a[1] / n, a[2] / n}} : Vec3{{0, 0, 0}};
}

// The colour of part k in the hitops tool (golden-ratio hues, alternating value and saturation).
Rgb palette(std::size_t k)
{
  const double h = std::fmod(0.13 + 0.618033988749895 * double(k), 1.) * 6.;
  const double s = (k % 3 == 2) ? 0.55 : 0.8, v = (k % 2) ? 0.8 : 0.95;
  const int i = int(h);
  const double f = h - i, p = v * (1 - s), q = v * (1 - s * f), t = v * (1 - s * (1 - f));
  double r, g, b;
  switch(i % 6)
  {
    case 0: r = v; g = t; b = p; break;
    case 1: r = q; g = v; b = p; break;
    case 2: r = p; g = v; b = t; break;
    case 3: r = p; g = q; b = v; break;
    case 4: r = t; g = p; b = v; break;
    default: r = v; g = p; b = q; break;
  }
  return {{std::uint8_t(std::lround(255 * r)), std::uint8_t(std::lround(255 * g)), std::uint8_t(std::lround(255 * b))}};
}

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

struct Image
{
  int width = 0, height = 0;
  std::vector<Rgb> pixels;
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

struct Triangle
{
  std::array<Vec3, 3> p;
  Rgb color;
};

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
// Camera and rasterization

struct Camera
{
  Vec3 right, up, forward; // forward points from the camera into the scene
  double cx = 0, cy = 0, scale = 1; // image centre of the framed box (camera coordinates), pixels per unit
  double depth_span = 1;
};

Vec3 axis_vector(const std::string& s)
{
  const double sign = s[0] == '-' ? -1. : 1.;
  const char a = s.back();
  Vec3 v{{0, 0, 0}};
  v[std::size_t(a == 'x' ? 0 : a == 'y' ? 1 : 2)] = sign;
  return v;
}

// Camera axes from azimuth/elevation around the up axis.
void orient(Camera& cam, const Vec3& world_up, double azimuth_deg, double elevation_deg)
{
  // a reference horizontal frame: e1, e2 orthogonal to up
  Vec3 e1 = std::abs(world_up[2]) < 0.9 ? Vec3{{0, 0, 1}} : Vec3{{1, 0, 0}};
  e1 = normalized(sub(e1, Vec3{{world_up[0] * dot(e1, world_up), world_up[1] * dot(e1, world_up), world_up[2] * dot(e1, world_up)}}));
  const Vec3 e2 = cross(world_up, e1);
  const double az = azimuth_deg * M_PI / 180., el = elevation_deg * M_PI / 180.;
  // direction from the scene to the camera
  Vec3 to_cam;
  for(int i = 0; i < 3; ++i)
    to_cam[std::size_t(i)] = std::cos(el) * (std::cos(az) * e1[std::size_t(i)] + std::sin(az) * e2[std::size_t(i)]) +
                             std::sin(el) * world_up[std::size_t(i)];
  cam.forward = {{-to_cam[0], -to_cam[1], -to_cam[2]}};
  cam.right = normalized(cross(cam.forward, world_up));
  cam.up = cross(cam.right, cam.forward);
}

struct Bounds
{
  double lo[3] = {std::numeric_limits<double>::infinity(), std::numeric_limits<double>::infinity(),
                  std::numeric_limits<double>::infinity()};
  double hi[3] = {-std::numeric_limits<double>::infinity(), -std::numeric_limits<double>::infinity(),
                  -std::numeric_limits<double>::infinity()};
  void add(double x, double y, double z)
  {
    const double v[3] = {x, y, z};
    for(int i = 0; i < 3; ++i)
    {
      lo[i] = std::min(lo[i], v[i]);
      hi[i] = std::max(hi[i], v[i]);
    }
  }
  bool empty() const { return !(lo[0] <= hi[0]); }
};

// The bounds of a panel in camera coordinates (right, up, forward).
Bounds camera_bounds(const Panel& panel, const Camera& cam)
{
  Bounds b;
  for(const Layer& l : panel.layers)
    for(const Triangle& t : l.triangles)
      for(const Vec3& p : t.p) b.add(dot(p, cam.right), dot(p, cam.up), dot(p, cam.forward));
  return b;
}

void frame(Camera& cam, const Bounds& b, int width, int height, double zoom)
{
  cam.cx = (b.lo[0] + b.hi[0]) / 2;
  cam.cy = (b.lo[1] + b.hi[1]) / 2;
  const double w = std::max(b.hi[0] - b.lo[0], 1e-12), h = std::max(b.hi[1] - b.lo[1], 1e-12);
  cam.scale = zoom * 0.92 * std::min(width / w, height / h);
  cam.depth_span = std::max(b.hi[2] - b.lo[2], 1e-12);
}

struct Canvas
{
  int width, height;
  std::vector<double> depth;
  std::vector<Vec3> color; // linear [0,1]
  std::vector<std::uint8_t> covered; // drawn by an opaque or a translucent triangle
  Canvas(int w, int h, const Vec3& background)
    : width(w), height(h), depth(std::size_t(w) * std::size_t(h), std::numeric_limits<double>::infinity()),
      color(std::size_t(w) * std::size_t(h), background), covered(std::size_t(w) * std::size_t(h), 0)
  {}
};

Vec3 shade(const Triangle& t, const Camera& cam)
{
  Vec3 n = normalized(cross(sub(t.p[1], t.p[0]), sub(t.p[2], t.p[0])));
  // two-sided: open meshes and inward components are lit like their outside
  if(dot(n, cam.forward) > 0) n = {{-n[0], -n[1], -n[2]}};
  // a key light from the upper left of the camera and a weaker fill light from the right
  const Vec3 key = normalized(Vec3{{-0.45 * cam.right[0] + 0.6 * cam.up[0] - cam.forward[0],
                                    -0.45 * cam.right[1] + 0.6 * cam.up[1] - cam.forward[1],
                                    -0.45 * cam.right[2] + 0.6 * cam.up[2] - cam.forward[2]}});
  const Vec3 fill = normalized(Vec3{{0.8 * cam.right[0] - 0.2 * cam.up[0] - cam.forward[0],
                                     0.8 * cam.right[1] - 0.2 * cam.up[1] - cam.forward[1],
                                     0.8 * cam.right[2] - 0.2 * cam.up[2] - cam.forward[2]}});
  const double light = 0.32 + 0.58 * std::max(0., dot(n, key)) + 0.18 * std::max(0., dot(n, fill));
  Vec3 c;
  for(int i = 0; i < 3; ++i) c[std::size_t(i)] = std::min(1., light * t.color[std::size_t(i)] / 255.);
  return c;
}

void rasterize(Canvas& cv, const Triangle& t, const Camera& cam, int ox, int oy, double alpha)
{
  double x[3], y[3], z[3];
  for(int k = 0; k < 3; ++k)
  {
    const Vec3& p = t.p[std::size_t(k)];
    x[k] = ox + (dot(p, cam.right) - cam.cx) * cam.scale;
    y[k] = oy - (dot(p, cam.up) - cam.cy) * cam.scale; // image rows grow downwards
    z[k] = dot(p, cam.forward);
  }
  const double area = (x[1] - x[0]) * (y[2] - y[0]) - (x[2] - x[0]) * (y[1] - y[0]);
  if(std::abs(area) < 1e-12) return;
  const Vec3 c = shade(t, cam);
  const int x0 = std::max(0, int(std::floor(std::min({x[0], x[1], x[2]})))),
            x1 = std::min(cv.width - 1, int(std::ceil(std::max({x[0], x[1], x[2]})))),
            y0 = std::max(0, int(std::floor(std::min({y[0], y[1], y[2]})))),
            y1 = std::min(cv.height - 1, int(std::ceil(std::max({y[0], y[1], y[2]}))));
  for(int py = y0; py <= y1; ++py)
    for(int px = x0; px <= x1; ++px)
    {
      const double sx = px + 0.5, sy = py + 0.5;
      const double w0 = ((x[1] - sx) * (y[2] - sy) - (x[2] - sx) * (y[1] - sy)) / area;
      const double w1 = ((x[2] - sx) * (y[0] - sy) - (x[0] - sx) * (y[2] - sy)) / area;
      const double w2 = 1. - w0 - w1;
      if(w0 < 0 || w1 < 0 || w2 < 0) continue;
      const double d = w0 * z[0] + w1 * z[1] + w2 * z[2];
      const std::size_t i = std::size_t(py) * std::size_t(cv.width) + std::size_t(px);
      if(d >= cv.depth[i]) continue;
      cv.covered[i] = 1;
      if(alpha >= 1.)
      {
        cv.depth[i] = d;
        cv.color[i] = c;
      }
      else
        for(int ch = 0; ch < 3; ++ch)
          cv.color[i][std::size_t(ch)] = alpha * c[std::size_t(ch)] + (1 - alpha) * cv.color[i][std::size_t(ch)];
    }
}

// Darkens the pixels at depth discontinuities: silhouettes and occluding contours.
void outline(Canvas& cv, const std::vector<std::uint8_t>& mask, double threshold)
{
  std::vector<Vec3> out = cv.color;
  for(int y = 0; y < cv.height; ++y)
    for(int x = 0; x < cv.width; ++x)
    {
      const std::size_t i = std::size_t(y) * std::size_t(cv.width) + std::size_t(x);
      if(!mask[i]) continue;
      const double d = cv.depth[i];
      bool edge = false;
      for(int k = 0; k < 4 && !edge; ++k)
      {
        const int nx = x + (k == 0) - (k == 1), ny = y + (k == 2) - (k == 3);
        if(nx < 0 || ny < 0 || nx >= cv.width || ny >= cv.height) continue;
        const double e = cv.depth[std::size_t(ny) * std::size_t(cv.width) + std::size_t(nx)];
        edge = !std::isfinite(e) ? true : e - d > threshold;
      }
      if(edge)
        for(double& c : out[i]) c *= 0.35;
    }
  cv.color.swap(out);
}

// ------------------------------------------------------------------------------------------
// PNG output: zlib stream of fixed-Huffman deflate blocks with LZ77 matches.

class Bit_writer
{
public:
  std::vector<std::uint8_t> bytes;
  void bits(std::uint32_t value, int count) // LSB first
  {
    for(int i = 0; i < count; ++i)
    {
      m_acc |= ((value >> i) & 1u) << m_n;
      if(++m_n == 8) flush_byte();
    }
  }
  void huffman(std::uint32_t code, int length) // MSB of the code first
  {
    for(int i = length - 1; i >= 0; --i)
    {
      m_acc |= ((code >> i) & 1u) << m_n;
      if(++m_n == 8) flush_byte();
    }
  }
  void align()
  {
    if(m_n > 0) flush_byte();
  }

private:
  void flush_byte()
  {
    bytes.push_back(std::uint8_t(m_acc));
    m_acc = 0;
    m_n = 0;
  }
  std::uint32_t m_acc = 0;
  int m_n = 0;
};

void literal_code(Bit_writer& w, int sym)
{
  if(sym < 144) w.huffman(std::uint32_t(0x30 + sym), 8);
  else if(sym < 256) w.huffman(std::uint32_t(0x190 + sym - 144), 9);
  else if(sym < 280) w.huffman(std::uint32_t(sym - 256), 7);
  else w.huffman(std::uint32_t(0xC0 + sym - 280), 8);
}

void write_match(Bit_writer& w, int length, int distance)
{
  static const int len_base[29] = {3, 4, 5, 6, 7, 8, 9, 10, 11, 13, 15, 17, 19, 23, 27, 31,
                                   35, 43, 51, 59, 67, 83, 99, 115, 131, 163, 195, 227, 258};
  static const int len_extra[29] = {0, 0, 0, 0, 0, 0, 0, 0, 1, 1, 1, 1, 2, 2, 2, 2, 3, 3, 3, 3, 4, 4, 4, 4, 5, 5, 5, 5, 0};
  static const int dist_base[30] = {1, 2, 3, 4, 5, 7, 9, 13, 17, 25, 33, 49, 65, 97, 129, 193, 257, 385, 513, 769,
                                    1025, 1537, 2049, 3073, 4097, 6145, 8193, 12289, 16385, 24577};
  static const int dist_extra[30] = {0, 0, 0, 0, 1, 1, 2, 2, 3, 3, 4, 4, 5, 5, 6, 6, 7, 7, 8, 8, 9, 9, 10, 10, 11, 11, 12, 12, 13, 13};
  int l = 28;
  while(len_base[l] > length) --l;
  literal_code(w, 257 + l);
  w.bits(std::uint32_t(length - len_base[l]), len_extra[l]);
  int d = 29;
  while(dist_base[d] > distance) --d;
  w.huffman(std::uint32_t(d), 5);
  w.bits(std::uint32_t(distance - dist_base[d]), dist_extra[d]);
}

std::vector<std::uint8_t> zlib_compress(const std::vector<std::uint8_t>& data)
{
  Bit_writer w;
  w.bits(0x78, 8);
  w.bits(0x01, 8);
  const std::size_t n = data.size();
  const int hash_bits = 15, window = 32768, max_chain = 48;
  std::vector<int> head(std::size_t(1) << hash_bits, -1), prev(n, -1);
  auto hash = [&](std::size_t i) {
    return ((std::uint32_t(data[i]) << 10) ^ (std::uint32_t(data[i + 1]) << 5) ^ data[i + 2]) & ((1u << hash_bits) - 1);
  };
  auto insert = [&](std::size_t i) {
    if(i + 2 >= n) return;
    const std::uint32_t h = hash(i);
    prev[i] = head[h];
    head[h] = int(i);
  };
  // one final block with fixed codes
  w.bits(1, 1);
  w.bits(1, 2);
  std::size_t i = 0;
  while(i < n)
  {
    int best_len = 0, best_dist = 0;
    if(i + 2 < n)
    {
      int cand = head[hash(i)];
      int chain = 0;
      const std::size_t max_len = std::min<std::size_t>(258, n - i);
      while(cand >= 0 && int(i) - cand <= window - 1 && chain++ < max_chain)
      {
        std::size_t l = 0;
        while(l < max_len && data[std::size_t(cand) + l] == data[i + l]) ++l;
        if(int(l) > best_len)
        {
          best_len = int(l);
          best_dist = int(i) - cand;
          if(l == max_len) break;
        }
        cand = prev[std::size_t(cand)];
      }
    }
    if(best_len >= 3)
    {
      write_match(w, best_len, best_dist);
      for(int k = 0; k < best_len; ++k) insert(i + std::size_t(k));
      i += std::size_t(best_len);
    }
    else
    {
      literal_code(w, data[i]);
      insert(i);
      ++i;
    }
  }
  literal_code(w, 256);
  w.align();
  std::uint32_t a = 1, b = 0;
  for(std::uint8_t c : data)
  {
    a = (a + c) % 65521;
    b = (b + a) % 65521;
  }
  const std::uint32_t adler = (b << 16) | a;
  for(int s = 24; s >= 0; s -= 8) w.bytes.push_back(std::uint8_t(adler >> s));
  return w.bytes;
}

std::uint32_t crc32(const std::uint8_t* p, std::size_t n, std::uint32_t crc = 0)
{
  static std::uint32_t table[256];
  static bool init = false;
  if(!init)
  {
    for(std::uint32_t k = 0; k < 256; ++k)
    {
      std::uint32_t c = k;
      for(int j = 0; j < 8; ++j) c = (c & 1) ? 0xEDB88320u ^ (c >> 1) : c >> 1;
      table[k] = c;
    }
    init = true;
  }
  crc = ~crc;
  for(std::size_t i = 0; i < n; ++i) crc = table[(crc ^ p[i]) & 0xFF] ^ (crc >> 8);
  return ~crc;
}

void write_chunk(std::ofstream& out, const char* type, const std::vector<std::uint8_t>& payload)
{
  const std::uint32_t len = std::uint32_t(payload.size());
  const std::uint8_t l[4] = {std::uint8_t(len >> 24), std::uint8_t(len >> 16), std::uint8_t(len >> 8), std::uint8_t(len)};
  out.write(reinterpret_cast<const char*>(l), 4);
  std::vector<std::uint8_t> body(type, type + 4);
  body.insert(body.end(), payload.begin(), payload.end());
  out.write(reinterpret_cast<const char*>(body.data()), std::streamsize(body.size()));
  const std::uint32_t c = crc32(body.data(), body.size());
  const std::uint8_t cb[4] = {std::uint8_t(c >> 24), std::uint8_t(c >> 16), std::uint8_t(c >> 8), std::uint8_t(c)};
  out.write(reinterpret_cast<const char*>(cb), 4);
}

void write_png(const std::string& file, int width, int height, const std::vector<Rgb>& pixels)
{
  // Each row with the filter (none, sub, up, paeth) of smallest absolute sum, the usual heuristic.
  std::vector<std::uint8_t> raw;
  const std::size_t stride = std::size_t(width) * 3;
  std::vector<std::uint8_t> zero(stride, 0), candidate(stride);
  for(int y = 0; y < height; ++y)
  {
    const std::uint8_t* cur = &pixels[std::size_t(y) * std::size_t(width)][0];
    const std::uint8_t* up = y > 0 ? &pixels[std::size_t(y - 1) * std::size_t(width)][0] : zero.data();
    int best = 0;
    long best_sum = std::numeric_limits<long>::max();
    std::vector<std::uint8_t> best_row;
    for(int f = 0; f < 4; ++f)
    {
      long sum = 0;
      for(std::size_t i = 0; i < stride; ++i)
      {
        const int a = i >= 3 ? cur[i - 3] : 0, b = up[i], c = i >= 3 ? up[i - 3] : 0;
        int pred = 0;
        if(f == 1) pred = a;
        else if(f == 2) pred = b;
        else if(f == 3)
        {
          const int p = a + b - c, pa = std::abs(p - a), pb = std::abs(p - b), pc = std::abs(p - c);
          pred = (pa <= pb && pa <= pc) ? a : (pb <= pc ? b : c);
        }
        candidate[i] = std::uint8_t(cur[i] - pred);
        sum += std::min<int>(candidate[i], 256 - candidate[i]);
      }
      if(sum < best_sum)
      {
        best_sum = sum;
        best = f;
        best_row = candidate;
      }
    }
    raw.push_back(std::uint8_t(best == 3 ? 4 : best));
    raw.insert(raw.end(), best_row.begin(), best_row.end());
  }
  std::ofstream out(file, std::ios::binary);
  if(!out) throw std::runtime_error("cannot write " + file);
  const std::uint8_t signature[8] = {137, 80, 78, 71, 13, 10, 26, 10};
  out.write(reinterpret_cast<const char*>(signature), 8);
  std::vector<std::uint8_t> ihdr;
  for(std::uint32_t v : {std::uint32_t(width), std::uint32_t(height)})
    for(int s = 24; s >= 0; s -= 8) ihdr.push_back(std::uint8_t(v >> s));
  ihdr.insert(ihdr.end(), {8, 2, 0, 0, 0}); // 8-bit RGB, deflate, adaptive filters, no interlace
  write_chunk(out, "IHDR", ihdr);
  write_chunk(out, "IDAT", zlib_compress(raw));
  write_chunk(out, "IEND", {});
  if(!out) throw std::runtime_error("cannot write " + file);
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
  std::vector<std::uint8_t> local_mask(local.depth.size(), 0);
  for(std::size_t i = 0; i < local.depth.size(); ++i) local_mask[i] = std::isfinite(local.depth[i]);
  outline(local, local_mask, 0.04 * pc.depth_span);
  for(int y = 0; y < ph; ++y)
    for(int x = 0; x < pw; ++x)
    {
      const std::size_t li = std::size_t(y) * std::size_t(pw) + std::size_t(x);
      if(local.covered[li]) cv.color[std::size_t(py + y) * std::size_t(cv.width) + std::size_t(px + x)] = local.color[li];
    }
}

// Averages the s x s blocks of the canvas.
std::vector<Rgb> downsample(const Canvas& cv, int s, int W, int H)
{
  std::vector<Rgb> pixels(std::size_t(W) * std::size_t(H));
  for(int y = 0; y < H; ++y)
    for(int x = 0; x < W; ++x)
    {
      Vec3 acc{{0, 0, 0}};
      for(int dy = 0; dy < s; ++dy)
        for(int dx = 0; dx < s; ++dx)
        {
          const Vec3& c = cv.color[std::size_t(y * s + dy) * std::size_t(cv.width) + std::size_t(x * s + dx)];
          for(int ch = 0; ch < 3; ++ch) acc[std::size_t(ch)] += c[std::size_t(ch)];
        }
      Rgb& p = pixels[std::size_t(y) * std::size_t(W) + std::size_t(x)];
      for(int ch = 0; ch < 3; ++ch)
        p[std::size_t(ch)] = std::uint8_t(std::lround(std::min(1., acc[std::size_t(ch)] / (s * s)) * 255.));
    }
  return pixels;
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
    write_png(o.output, W, H, downsample(cv, s, W, H));
    std::cout << "wrote " << o.output << " (" << W << "x" << H << ", " << n << " panels)" << std::endl;
  }
  catch(const std::exception& e)
  {
    std::cerr << "render_mesh: " << e.what() << std::endl;
    return EXIT_FAILURE;
  }
  return EXIT_SUCCESS;
}
