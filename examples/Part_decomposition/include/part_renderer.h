// Copyright (c) 2026 The Part_decomposition authors.
// All rights reserved.
//
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Author(s)     : The Part_decomposition authors

#ifndef PART_DECOMPOSITION_TOOLS_PART_RENDERER_H
#define PART_DECOMPOSITION_TOOLS_PART_RENDERER_H

// A small offscreen software rasterizer and PNG writer, shared by the hitops thumbnails and report,
// the Python module's render_parts() and the manual's figure tool render_mesh: flat shading,
// orthographic camera, z-buffer, dark silhouettes, supersampling. Only the standard library, so
// pictures can be drawn anywhere; the PNG encoder carries its own deflate coder.
//
//   render::Image image = render::render_input_and_parts(points, triangles, colours, options);
//   render::write_png("out.png", image);
//
// The part colours come from the caller (part_palette.h gives the package's palette).

#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <cstdlib>
#include <fstream>
#include <iterator>
#include <limits>
#include <stdexcept>
#include <string>
#include <vector>

namespace Part_decomposition_tools {
namespace render {

typedef std::array<double, 3> Vec3;
typedef std::array<std::uint8_t, 3> Rgb;

inline Vec3 sub(const Vec3& a, const Vec3& b) { return {{a[0] - b[0], a[1] - b[1], a[2] - b[2]}}; }
inline Vec3 cross(const Vec3& a, const Vec3& b)
{
  return {{a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]}};
}
inline double dot(const Vec3& a, const Vec3& b) { return a[0] * b[0] + a[1] * b[1] + a[2] * b[2]; }
inline Vec3 normalized(const Vec3& a)
{
  const double n = std::sqrt(dot(a, a));
  return n > 0 ? Vec3{{a[0] / n, a[1] / n, a[2] / n}} : Vec3{{0, 0, 0}};
}

// An 8-bit sRGB picture, rows from the top.
struct Image
{
  int width = 0, height = 0;
  std::vector<Rgb> pixels;
};

// A triangle to draw and its colour (before shading).
struct Triangle
{
  std::array<Vec3, 3> p;
  Rgb color;
};

// ------------------------------------------------------------------------------------------
// Camera and rasterization

struct Camera
{
  Vec3 right, up, forward; // forward points from the camera into the scene
  double cx = 0, cy = 0, scale = 1; // image centre of the framed box (camera coordinates), pixels per unit
  double depth_span = 1;
};

inline Vec3 axis_vector(const std::string& s)
{
  const double sign = s[0] == '-' ? -1. : 1.;
  const char a = s.back();
  Vec3 v{{0, 0, 0}};
  v[std::size_t(a == 'x' ? 0 : a == 'y' ? 1 : 2)] = sign;
  return v;
}

// Camera axes from azimuth/elevation around the up axis.
inline void orient(Camera& cam, const Vec3& world_up, double azimuth_deg, double elevation_deg)
{
  // a reference horizontal frame: e1, e2 orthogonal to up
  Vec3 e1 = std::abs(world_up[2]) < 0.9 ? Vec3{{0, 0, 1}} : Vec3{{1, 0, 0}};
  e1 = normalized(sub(e1, Vec3{{world_up[0] * dot(e1, world_up), world_up[1] * dot(e1, world_up), world_up[2] * dot(e1, world_up)}}));
  const Vec3 e2 = cross(world_up, e1);
  const double degree = 3.14159265358979323846 / 180.; // M_PI is not standard C++
  const double az = azimuth_deg * degree, el = elevation_deg * degree;
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

// Adds the triangles to the bounds in camera coordinates (right, up, forward).
inline void add_bounds(Bounds& b, const std::vector<Triangle>& triangles, const Camera& cam)
{
  for(const Triangle& t : triangles)
    for(const Vec3& p : t.p) b.add(dot(p, cam.right), dot(p, cam.up), dot(p, cam.forward));
}

// Centres the bounds in a width x height image, with a margin.
inline void frame(Camera& cam, const Bounds& b, int width, int height, double zoom)
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

// The brightness of a flat triangle: two-sided, a key light from the upper left of the camera and
// a weaker fill light from the right.
inline double light_of(const std::array<Vec3, 3>& p, const Camera& cam)
{
  Vec3 n = normalized(cross(sub(p[1], p[0]), sub(p[2], p[0])));
  // two-sided: open meshes and inward components are lit like their outside
  if(dot(n, cam.forward) > 0) n = {{-n[0], -n[1], -n[2]}};
  const Vec3 key = normalized(Vec3{{-0.45 * cam.right[0] + 0.6 * cam.up[0] - cam.forward[0],
                                    -0.45 * cam.right[1] + 0.6 * cam.up[1] - cam.forward[1],
                                    -0.45 * cam.right[2] + 0.6 * cam.up[2] - cam.forward[2]}});
  const Vec3 fill = normalized(Vec3{{0.8 * cam.right[0] - 0.2 * cam.up[0] - cam.forward[0],
                                     0.8 * cam.right[1] - 0.2 * cam.up[1] - cam.forward[1],
                                     0.8 * cam.right[2] - 0.2 * cam.up[2] - cam.forward[2]}});
  return 0.32 + 0.58 * std::max(0., dot(n, key)) + 0.18 * std::max(0., dot(n, fill));
}

// A colour lit with `light`, linear in [0, 1].
inline Vec3 lit(const Rgb& colour, double light)
{
  Vec3 c;
  for(int i = 0; i < 3; ++i) c[std::size_t(i)] = std::min(1., light * colour[std::size_t(i)] / 255.);
  return c;
}

inline Vec3 shade(const Triangle& t, const Camera& cam) { return lit(t.color, light_of(t.p, cam)); }

// Calls f(sample index, depth) for each sample of a width x height canvas whose centre the
// triangle covers, in the camera centred at (ox, oy); false for a degenerate triangle.
template <typename F>
bool for_each_sample(const std::array<Vec3, 3>& p, const Camera& cam, int ox, int oy, int width, int height, F f)
{
  double x[3], y[3], z[3];
  for(int k = 0; k < 3; ++k)
  {
    x[k] = ox + (dot(p[std::size_t(k)], cam.right) - cam.cx) * cam.scale;
    y[k] = oy - (dot(p[std::size_t(k)], cam.up) - cam.cy) * cam.scale; // image rows grow downwards
    z[k] = dot(p[std::size_t(k)], cam.forward);
  }
  const double area = (x[1] - x[0]) * (y[2] - y[0]) - (x[2] - x[0]) * (y[1] - y[0]);
  if(std::abs(area) < 1e-12) return false;
  const int x0 = std::max(0, int(std::floor(std::min({x[0], x[1], x[2]})))),
            x1 = std::min(width - 1, int(std::ceil(std::max({x[0], x[1], x[2]})))),
            y0 = std::max(0, int(std::floor(std::min({y[0], y[1], y[2]})))),
            y1 = std::min(height - 1, int(std::ceil(std::max({y[0], y[1], y[2]}))));
  for(int py = y0; py <= y1; ++py)
    for(int px = x0; px <= x1; ++px)
    {
      const double sx = px + 0.5, sy = py + 0.5;
      const double w0 = ((x[1] - sx) * (y[2] - sy) - (x[2] - sx) * (y[1] - sy)) / area;
      const double w1 = ((x[2] - sx) * (y[0] - sy) - (x[0] - sx) * (y[2] - sy)) / area;
      const double w2 = 1. - w0 - w1;
      if(w0 < 0 || w1 < 0 || w2 < 0) continue;
      f(std::size_t(py) * std::size_t(width) + std::size_t(px), w0 * z[0] + w1 * z[1] + w2 * z[2]);
    }
  return true;
}

// Draws a triangle, opaque (alpha 1, z-buffered) or blended over what is nearer than it is not.
inline void rasterize(Canvas& cv, const Triangle& t, const Camera& cam, int ox, int oy, double alpha)
{
  Vec3 c{{0, 0, 0}};
  bool shaded = false;
  for_each_sample(t.p, cam, ox, oy, cv.width, cv.height, [&](std::size_t i, double d) {
    if(d >= cv.depth[i]) return;
    if(!shaded) c = shade(t, cam); // only for a triangle that shows
    shaded = true;
    cv.covered[i] = 1;
    if(alpha >= 1.)
    {
      cv.depth[i] = d;
      cv.color[i] = c;
    }
    else
      for(int ch = 0; ch < 3; ++ch)
        cv.color[i][std::size_t(ch)] = alpha * c[std::size_t(ch)] + (1 - alpha) * cv.color[i][std::size_t(ch)];
  });
}

// Darkens the pixels at depth discontinuities: silhouettes and occluding contours.
inline void outline(Canvas& cv, const std::vector<std::uint8_t>& mask, double threshold)
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

// Outlines a panel drawn on its own canvas `local` and copies its covered pixels into `cv` at
// (px, py): a panel of its own keeps the silhouettes from spilling over its neighbours.
inline void outline_and_copy(Canvas& cv, Canvas& local, const Camera& cam, int px, int py)
{
  std::vector<std::uint8_t> mask(local.depth.size(), 0);
  for(std::size_t i = 0; i < local.depth.size(); ++i) mask[i] = std::isfinite(local.depth[i]);
  outline(local, mask, 0.04 * cam.depth_span);
  for(int y = 0; y < local.height; ++y)
    for(int x = 0; x < local.width; ++x)
    {
      const std::size_t li = std::size_t(y) * std::size_t(local.width) + std::size_t(x);
      if(local.covered[li]) cv.color[std::size_t(py + y) * std::size_t(cv.width) + std::size_t(px + x)] = local.color[li];
    }
}

// Averages the s x s blocks of the canvas.
inline std::vector<Rgb> downsample(const Canvas& cv, int s, int W, int H)
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

inline void literal_code(Bit_writer& w, int sym)
{
  if(sym < 144) w.huffman(std::uint32_t(0x30 + sym), 8);
  else if(sym < 256) w.huffman(std::uint32_t(0x190 + sym - 144), 9);
  else if(sym < 280) w.huffman(std::uint32_t(sym - 256), 7);
  else w.huffman(std::uint32_t(0xC0 + sym - 280), 8);
}

inline void write_match(Bit_writer& w, int length, int distance)
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

inline std::vector<std::uint8_t> zlib_compress(const std::vector<std::uint8_t>& data)
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

// The CRC-32 of PNG chunks (ISO 3309).
inline std::uint32_t crc32(const std::uint8_t* p, std::size_t n, std::uint32_t crc = 0)
{
  // a function-local static: initialized once, even from several threads
  static const std::array<std::uint32_t, 256> table = [] {
    std::array<std::uint32_t, 256> t{};
    for(std::uint32_t k = 0; k < 256; ++k)
    {
      std::uint32_t c = k;
      for(int j = 0; j < 8; ++j) c = (c & 1) ? 0xEDB88320u ^ (c >> 1) : c >> 1;
      t[k] = c;
    }
    return t;
  }();
  crc = ~crc;
  for(std::size_t i = 0; i < n; ++i) crc = table[(crc ^ p[i]) & 0xFF] ^ (crc >> 8);
  return ~crc;
}

inline void append_big_endian(std::vector<std::uint8_t>& out, std::uint32_t v)
{
  for(int s = 24; s >= 0; s -= 8) out.push_back(std::uint8_t(v >> s));
}

// Appends one chunk: length, type, payload, CRC of type and payload.
inline void append_chunk(std::vector<std::uint8_t>& out, const char* type, const std::vector<std::uint8_t>& payload)
{
  append_big_endian(out, std::uint32_t(payload.size()));
  const std::size_t start = out.size();
  out.insert(out.end(), type, type + 4);
  out.insert(out.end(), payload.begin(), payload.end());
  append_big_endian(out, crc32(out.data() + start, out.size() - start));
}

// The PNG file of an image: 8-bit RGB, one IDAT chunk.
inline std::vector<std::uint8_t> encode_png(const Image& image)
{
  const int width = image.width, height = image.height;
  const std::vector<Rgb>& pixels = image.pixels;
  if(width <= 0 || height <= 0 || pixels.size() != std::size_t(width) * std::size_t(height))
    throw std::invalid_argument("encode_png: the pixels do not match the size");
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
  std::vector<std::uint8_t> png = {137, 80, 78, 71, 13, 10, 26, 10};
  std::vector<std::uint8_t> ihdr;
  append_big_endian(ihdr, std::uint32_t(width));
  append_big_endian(ihdr, std::uint32_t(height));
  ihdr.insert(ihdr.end(), {8, 2, 0, 0, 0}); // 8-bit RGB, deflate, adaptive filters, no interlace
  append_chunk(png, "IHDR", ihdr);
  append_chunk(png, "IDAT", zlib_compress(raw));
  append_chunk(png, "IEND", {});
  return png;
}

// Writes the image as a PNG file; std::runtime_error if it cannot.
inline void write_png(const std::string& file, const Image& image)
{
  const std::vector<std::uint8_t> png = encode_png(image);
  std::ofstream out(file, std::ios::binary);
  out.write(reinterpret_cast<const char*>(png.data()), std::streamsize(png.size()));
  out.close();
  if(!out) throw std::runtime_error("cannot write " + file);
}

// ------------------------------------------------------------------------------------------
// The picture of a decomposition: the input in grey beside its parts in their colours.

struct Picture_options
{
  int width = 320, height = 160; // the whole picture, two panels side by side
  int supersampling = 2;         // samples per pixel along each axis (the figures use 3)
  double azimuth = 30, elevation = 20; // of the camera around the up axis, in degrees
  std::string up = "y";          // the axis that points up: x, y, z, -x, -y or -z
  Rgb background{{255, 255, 255}};
  Rgb input_colour{{200, 200, 200}};
};

// `points` (each p[0], p[1], p[2]) and `triangles` (each three indices into points) with one
// colour per triangle: the left half of the picture shows the mesh in options.input_colour, the
// right half in `colours`, both from the same camera and framing. std::invalid_argument for a
// size out of [2, 16384], an index out of range or a colour count that is not the triangles'.
template <typename PointRange, typename TriangleRange>
Image render_input_and_parts(const PointRange& points, const TriangleRange& triangles, const std::vector<Rgb>& colours,
                             const Picture_options& options = Picture_options())
{
  const int W = options.width, H = options.height, s = options.supersampling;
  if(W < 2 || H < 2 || W > 16384 || H > 16384) throw std::invalid_argument("picture size out of [2, 16384]");
  if(s < 1 || s > 8) throw std::invalid_argument("supersampling out of [1, 8]");
  if(colours.size() != std::size_t(std::distance(std::begin(triangles), std::end(triangles))))
    throw std::invalid_argument("one colour per triangle expected");
  std::vector<std::array<Vec3, 3> > corners;
  for(const auto& tri : triangles)
  {
    std::array<Vec3, 3> x;
    for(std::size_t k = 0; k < 3; ++k)
    {
      const std::size_t v = std::size_t(tri[k]);
      if(v >= std::size_t(std::size(points))) throw std::invalid_argument("a vertex index out of range");
      const auto& p = points[v];
      x[k] = {{double(p[0]), double(p[1]), double(p[2])}};
    }
    corners.push_back(x);
  }
  Camera cam;
  orient(cam, axis_vector(options.up), options.azimuth, options.elevation);
  Bounds bounds;
  for(const auto& x : corners)
    for(const Vec3& p : x) bounds.add(dot(p, cam.right), dot(p, cam.up), dot(p, cam.forward));
  const Vec3 bg{{options.background[0] / 255., options.background[1] / 255., options.background[2] / 255.}};
  Image image;
  image.width = W;
  image.height = H;
  image.pixels.assign(std::size_t(W) * std::size_t(H), options.background);
  if(bounds.empty()) return image;
  // the two panels differ only in colour: one pass finds the triangle that shows at each sample
  const int pw = (W / 2) * s, ph = H * s;
  frame(cam, bounds, pw, ph, 1.);
  Canvas local(pw, ph, bg);
  std::vector<std::size_t> shown(local.depth.size(), corners.size());
  for(std::size_t t = 0; t < corners.size(); ++t)
    for_each_sample(corners[t], cam, pw / 2, ph / 2, pw, ph, [&](std::size_t i, double d) {
      if(d >= local.depth[i]) return;
      local.depth[i] = d;
      shown[i] = t;
    });
  std::vector<std::uint8_t> mask(shown.size());
  for(std::size_t i = 0; i < shown.size(); ++i) mask[i] = shown[i] < corners.size();
  std::vector<double> light(corners.size(), -1.); // of the triangles that show
  for(int panel = 0; panel < 2; ++panel)
  {
    // each panel colours the same samples, so the previous panel's outline is overwritten
    for(std::size_t i = 0; i < shown.size(); ++i)
    {
      const std::size_t t = shown[i];
      if(!mask[i]) continue;
      if(light[t] < 0) light[t] = light_of(corners[t], cam);
      local.color[i] = lit(panel == 0 ? options.input_colour : colours[t], light[t]);
    }
    outline(local, mask, 0.04 * cam.depth_span);
    const std::vector<Rgb> pixels = downsample(local, s, pw / s, H);
    const std::size_t x0 = panel == 0 ? 0 : std::size_t(W - pw / s);
    for(int y = 0; y < H; ++y)
      std::copy(pixels.begin() + std::ptrdiff_t(y) * (pw / s), pixels.begin() + std::ptrdiff_t(y + 1) * (pw / s),
                image.pixels.begin() + std::ptrdiff_t(std::size_t(y) * std::size_t(W) + x0));
  }
  return image;
}

// The points of a `CGAL::Surface_mesh` by vertex index (the gaps of removed vertices unused) and
// its triangles in the iteration order of its faces: the arrays of render_input_and_parts().
template <typename SurfaceMesh>
void surface_mesh_arrays(const SurfaceMesh& mesh, std::vector<Vec3>& points,
                         std::vector<std::array<std::size_t, 3> >& triangles)
{
  points.assign(mesh.number_of_vertices() + mesh.number_of_removed_vertices(), Vec3{});
  for(auto v : vertices(mesh))
    points[std::size_t(v)] = {{double(mesh.point(v).x()), double(mesh.point(v).y()), double(mesh.point(v).z())}};
  triangles.clear();
  for(auto f : faces(mesh))
  {
    std::array<std::size_t, 3> t{};
    std::size_t k = 0;
    for(auto v : vertices_around_face(mesh.halfedge(f), mesh))
      if(k < 3) t[k++] = std::size_t(v);
    triangles.push_back(t);
  }
}

} // namespace render
} // namespace Part_decomposition_tools

#endif // PART_DECOMPOSITION_TOOLS_PART_RENDERER_H
