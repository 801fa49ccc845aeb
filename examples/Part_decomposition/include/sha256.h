// Copyright (c) 2026 The Part_decomposition authors.
// All rights reserved.
//
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Author(s)     : The Part_decomposition authors

#ifndef PART_DECOMPOSITION_TOOLS_SHA256_H
#define PART_DECOMPOSITION_TOOLS_SHA256_H

// SHA-256 (FIPS 180-4), to identify the input files of a batch; written here because neither
// CGAL nor its dependencies (Boost, Eigen, TBB) provide it.

#include <algorithm>
#include <array>
#include <cstddef>
#include <cstdint>
#include <filesystem>
#include <fstream>
#include <string>
#include <system_error>

namespace Part_decomposition_tools {

class Sha256
{
public:
  // appends `size` bytes to the message
  void update(const void* data, std::size_t size)
  {
    const unsigned char* p = static_cast<const unsigned char*>(data);
    m_length += size;
    while(size > 0)
    {
      if(m_buffered == 0 && size >= 64)
      {
        // whole blocks straight from the data
        compress(p);
        p += 64;
        size -= 64;
        continue;
      }
      const std::size_t n = (std::min)(size, std::size_t(64) - m_buffered);
      for(std::size_t i = 0; i < n; ++i) m_block[m_buffered + i] = p[i];
      m_buffered += n;
      p += n;
      size -= n;
      if(m_buffered == 64)
      {
        compress(m_block.data());
        m_buffered = 0;
      }
    }
  }

  // the digest of the message as 64 lower-case hexadecimal digits; ends the message
  std::string hex_digest()
  {
    // padding: a 1 bit, zeros up to 56 bytes modulo 64, the length in bits as 64-bit big endian
    const std::uint64_t bits = std::uint64_t(m_length) * 8;
    const unsigned char one = 0x80, zero = 0;
    update(&one, 1);
    while(m_buffered != 56) update(&zero, 1);
    unsigned char length[8];
    for(int i = 0; i < 8; ++i) length[i] = (unsigned char)(bits >> (56 - 8 * i));
    update(length, 8);
    static const char* const digits = "0123456789abcdef";
    std::string hex;
    for(std::uint32_t h : m_state)
      for(int shift = 28; shift >= 0; shift -= 4) hex += digits[(h >> shift) & 0xf];
    return hex;
  }

private:
  std::array<std::uint32_t, 8> m_state = {{0x6a09e667, 0xbb67ae85, 0x3c6ef372, 0xa54ff53a, 0x510e527f, 0x9b05688c,
                                           0x1f83d9ab, 0x5be0cd19}};
  std::array<unsigned char, 64> m_block = {};
  std::size_t m_buffered = 0;
  std::uint64_t m_length = 0; // bytes

  static std::uint32_t rotr(std::uint32_t x, int n) { return (x >> n) | (x << (32 - n)); }

  // the compression function on one 64-byte block (FIPS 180-4, 6.2.2)
  void compress(const unsigned char* block)
  {
    static const std::uint32_t k[64] = {
      0x428a2f98, 0x71374491, 0xb5c0fbcf, 0xe9b5dba5, 0x3956c25b, 0x59f111f1, 0x923f82a4, 0xab1c5ed5,
      0xd807aa98, 0x12835b01, 0x243185be, 0x550c7dc3, 0x72be5d74, 0x80deb1fe, 0x9bdc06a7, 0xc19bf174,
      0xe49b69c1, 0xefbe4786, 0x0fc19dc6, 0x240ca1cc, 0x2de92c6f, 0x4a7484aa, 0x5cb0a9dc, 0x76f988da,
      0x983e5152, 0xa831c66d, 0xb00327c8, 0xbf597fc7, 0xc6e00bf3, 0xd5a79147, 0x06ca6351, 0x14292967,
      0x27b70a85, 0x2e1b2138, 0x4d2c6dfc, 0x53380d13, 0x650a7354, 0x766a0abb, 0x81c2c92e, 0x92722c85,
      0xa2bfe8a1, 0xa81a664b, 0xc24b8b70, 0xc76c51a3, 0xd192e819, 0xd6990624, 0xf40e3585, 0x106aa070,
      0x19a4c116, 0x1e376c08, 0x2748774c, 0x34b0bcb5, 0x391c0cb3, 0x4ed8aa4a, 0x5b9cca4f, 0x682e6ff3,
      0x748f82ee, 0x78a5636f, 0x84c87814, 0x8cc70208, 0x90befffa, 0xa4506ceb, 0xbef9a3f7, 0xc67178f2};
    std::uint32_t w[64];
    for(int t = 0; t < 16; ++t)
      w[t] = (std::uint32_t(block[4 * t]) << 24) | (std::uint32_t(block[4 * t + 1]) << 16) |
             (std::uint32_t(block[4 * t + 2]) << 8) | std::uint32_t(block[4 * t + 3]);
    for(int t = 16; t < 64; ++t)
    {
      const std::uint32_t s0 = rotr(w[t - 15], 7) ^ rotr(w[t - 15], 18) ^ (w[t - 15] >> 3);
      const std::uint32_t s1 = rotr(w[t - 2], 17) ^ rotr(w[t - 2], 19) ^ (w[t - 2] >> 10);
      w[t] = w[t - 16] + s0 + w[t - 7] + s1;
    }
    std::uint32_t a = m_state[0], b = m_state[1], c = m_state[2], d = m_state[3], e = m_state[4], f = m_state[5],
                  g = m_state[6], h = m_state[7];
    for(int t = 0; t < 64; ++t)
    {
      const std::uint32_t t1 = h + (rotr(e, 6) ^ rotr(e, 11) ^ rotr(e, 25)) + ((e & f) ^ (~e & g)) + k[t] + w[t];
      const std::uint32_t t2 = (rotr(a, 2) ^ rotr(a, 13) ^ rotr(a, 22)) + ((a & b) ^ (a & c) ^ (b & c));
      h = g;
      g = f;
      f = e;
      e = d + t1;
      d = c;
      c = b;
      b = a;
      a = t1 + t2;
    }
    m_state[0] += a;
    m_state[1] += b;
    m_state[2] += c;
    m_state[3] += d;
    m_state[4] += e;
    m_state[5] += f;
    m_state[6] += g;
    m_state[7] += h;
  }
};

// The SHA-256 of the bytes of `s`, in hexadecimal.
inline std::string sha256_hex(const std::string& s)
{
  Sha256 h;
  h.update(s.data(), s.size());
  return h.hex_digest();
}

// The SHA-256 of the file at `path`, in hexadecimal, read in chunks; false if it cannot be read.
inline bool sha256_of_file(const std::string& path, std::string& hex)
{
  std::error_code ec;
  if(std::filesystem::is_directory(path, ec)) return false; // opens, and reads as empty
  std::ifstream in(path, std::ios::binary);
  if(!in) return false;
  Sha256 h;
  char chunk[1 << 16];
  while(in)
  {
    in.read(chunk, sizeof(chunk));
    h.update(chunk, std::size_t(in.gcount()));
  }
  if(in.bad()) return false;
  hex = h.hex_digest();
  return true;
}

} // namespace Part_decomposition_tools

#endif // PART_DECOMPOSITION_TOOLS_SHA256_H
