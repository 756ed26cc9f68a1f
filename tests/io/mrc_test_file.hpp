#pragma once
// Hand-made MRC2014 maps for the volume tests (reader and CLI): header words set explicitly,
// data in the given file order.
#include <algorithm>
#include <array>
#include <cstdint>
#include <cstring>
#include <string>
#include <vector>

namespace molmesh::test {

struct MrcSpec {
  std::array<std::int32_t, 3> n{1, 1, 1};
  std::int32_t mode = 2;
  std::array<std::int32_t, 3> start{0, 0, 0};
  std::array<std::int32_t, 3> m{1, 1, 1};
  std::array<float, 3> cell{1, 1, 1};
  std::array<std::int32_t, 3> axes{1, 2, 3};
  std::array<float, 3> origin{0, 0, 0};
  std::int32_t nsymbt = 0;
  bool big_endian = false;
};

inline std::string make_mrc(const MrcSpec& s, const std::vector<double>& file_order_values) {
  std::string b(1024 + static_cast<std::size_t>(s.nsymbt), '\0');
  auto put = [&](int word, const void* v) {
    char raw[4];
    std::memcpy(raw, v, 4);
    if (s.big_endian) std::reverse(raw, raw + 4);
    std::memcpy(b.data() + 4 * (word - 1), raw, 4);
  };
  for (int k = 0; k < 3; ++k) {
    put(1 + k, &s.n[k]);
    put(5 + k, &s.start[k]);
    put(8 + k, &s.m[k]);
    put(11 + k, &s.cell[k]);
    put(17 + k, &s.axes[k]);
    put(50 + k, &s.origin[k]);
  }
  put(4, &s.mode);
  put(24, &s.nsymbt);
  std::memcpy(b.data() + 208, "MAP ", 4);
  const unsigned char stamp = s.big_endian ? 0x11 : 0x44;
  std::memset(b.data() + 212, stamp, 2);
  for (double v : file_order_values) {
    char raw[4];
    std::size_t n = 4;
    if (s.mode == 0) {
      raw[0] = static_cast<char>(static_cast<signed char>(v));
      n = 1;
    } else if (s.mode == 1) {
      const auto x = static_cast<std::int16_t>(v);
      std::memcpy(raw, &x, 2);
      n = 2;
    } else if (s.mode == 6) {
      const auto x = static_cast<std::uint16_t>(v);
      std::memcpy(raw, &x, 2);
      n = 2;
    } else {
      const auto x = static_cast<float>(v);
      std::memcpy(raw, &x, 4);
    }
    if (s.big_endian) std::reverse(raw, raw + n);
    b.append(raw, n);
  }
  return b;
}

}  // namespace molmesh::test
