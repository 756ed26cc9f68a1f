#include "molmesh/io/volume_mrc.hpp"

#include <algorithm>
#include <array>
#include <bit>
#include <cmath>
#include <cstdint>
#include <cstring>

#include "molmesh/core/error.hpp"
#include "molmesh/io/text_input.hpp"

namespace molmesh {
namespace {

constexpr std::size_t kHeaderBytes = 1024;

template <class T>
T load(const char* p, bool swap) {
  unsigned char raw[sizeof(T)];
  std::memcpy(raw, p, sizeof(T));
  if (swap) std::reverse(raw, raw + sizeof(T));
  T value;
  std::memcpy(&value, raw, sizeof(T));
  return value;
}

// Header word w (1-based, as the MRC2014 specification numbers them).
std::int32_t word_int(const std::string& b, int w, bool swap) {
  return load<std::int32_t>(b.data() + 4 * (w - 1), swap);
}
float word_float(const std::string& b, int w, bool swap) {
  return load<float>(b.data() + 4 * (w - 1), swap);
}

bool plausible_mode(std::int32_t mode) { return mode >= 0 && mode <= 16; }

}  // namespace

Grid parse_mrc(const std::string& bytes, const std::string& name) {
  if (bytes.size() < kHeaderBytes)
    throw InputError(name, "too short for an MRC/CCP4 map (" + std::to_string(bytes.size()) +
                               " bytes; the header alone is 1024)");
  // MACHST (word 54): 0x44 0x4? little endian, 0x11 0x11 big endian. Older writers leave it
  // zero; then the byte order that gives a sensible MODE wins.
  const auto stamp = static_cast<unsigned char>(bytes[4 * 53]);
  const bool native_little = std::endian::native == std::endian::little;
  bool file_little = true;
  if (stamp == 0x44) {
    file_little = true;
  } else if (stamp == 0x11) {
    file_little = false;
  } else {
    file_little = plausible_mode(load<std::int32_t>(bytes.data() + 12, !native_little)) ||
                  !plausible_mode(load<std::int32_t>(bytes.data() + 12, native_little));
  }
  const bool swap = file_little != native_little;

  const std::array<std::int32_t, 3> n{word_int(bytes, 1, swap), word_int(bytes, 2, swap),
                                      word_int(bytes, 3, swap)};
  const std::int32_t mode = word_int(bytes, 4, swap);
  const std::array<std::int32_t, 3> start{word_int(bytes, 5, swap), word_int(bytes, 6, swap),
                                          word_int(bytes, 7, swap)};
  const std::array<std::int32_t, 3> m{word_int(bytes, 8, swap), word_int(bytes, 9, swap),
                                      word_int(bytes, 10, swap)};
  const std::array<float, 3> cell{word_float(bytes, 11, swap), word_float(bytes, 12, swap),
                                  word_float(bytes, 13, swap)};
  std::array<std::int32_t, 3> axis{word_int(bytes, 17, swap), word_int(bytes, 18, swap),
                                   word_int(bytes, 19, swap)};
  const std::int32_t nsymbt = word_int(bytes, 24, swap);
  const std::array<float, 3> origin{word_float(bytes, 50, swap), word_float(bytes, 51, swap),
                                    word_float(bytes, 52, swap)};

  for (int k = 0; k < 3; ++k)
    if (n[static_cast<std::size_t>(k)] < 1)
      throw InputError(name, "header: NC/NR/NS must be positive, found " + std::to_string(n[0]) +
                                 " " + std::to_string(n[1]) + " " + std::to_string(n[2]));
  // Some writers leave MAPC/MAPR/MAPS zero; the standard order is then meant.
  if (axis == std::array<std::int32_t, 3>{0, 0, 0}) axis = {1, 2, 3};
  {
    auto sorted = axis;
    std::sort(sorted.begin(), sorted.end());
    if (sorted != std::array<std::int32_t, 3>{1, 2, 3})
      throw InputError(name, "header: MAPC/MAPR/MAPS must be a permutation of 1 2 3, found " +
                                 std::to_string(axis[0]) + " " + std::to_string(axis[1]) + " " +
                                 std::to_string(axis[2]));
  }
  std::size_t value_bytes = 0;
  switch (mode) {
    case 0:
      value_bytes = 1;
      break;
    case 1:
    case 6:
      value_bytes = 2;
      break;
    case 2:
      value_bytes = 4;
      break;
    default:
      throw InputError(name, "header: MRC mode " + std::to_string(mode) +
                                 " is not supported (modes 0, 1, 2 and 6 are: real-valued maps)");
  }
  if (nsymbt < 0) throw InputError(name, "header: negative extended header size NSYMBT");
  // Checked arithmetic: 2^22 x 2^21 x 2^21 samples wrap a plain product to 0, which
  // would pass the size check and leave the grid empty.
  const std::size_t data_start = kHeaderBytes + static_cast<std::size_t>(nsymbt);
  const auto count =
      io_detail::checked_product({static_cast<std::size_t>(n[0]), static_cast<std::size_t>(n[1]),
                                  static_cast<std::size_t>(n[2])});
  const std::optional<std::size_t> data_bytes =
      count ? io_detail::checked_product({*count, value_bytes}) : std::nullopt;
  const std::string shape = std::to_string(n[0]) + "x" + std::to_string(n[1]) + "x" +
                            std::to_string(n[2]) + " values of " + std::to_string(value_bytes) +
                            " bytes";
  // value_or, not *: gcc 12 -O2 sees the optional's payload as maybe uninitialised.
  const std::size_t needed = data_bytes.value_or(0);
  if (!data_bytes.has_value() || bytes.size() < data_start || bytes.size() - data_start < needed)
    throw InputError(name, "file has " + std::to_string(bytes.size()) + " bytes but the header (" +
                               shape + ", after " + std::to_string(data_start) +
                               " header bytes) needs " +
                               (data_bytes.has_value() ? std::to_string(data_start + needed)
                                                       : std::string("more than 2^64")) +
                               " (truncated file or corrupt header?)");
  // Bytes after the data mean the header does not describe this file: a wrong NSYMBT
  // shifts every value, a wrong NX/NY/NZ or MODE reads a different grid, and which one is
  // wrong cannot be told. They used to be ignored (docs/inputs.md, "Volumes match their
  // headers exactly").
  if (const std::size_t extra = bytes.size() - data_start - needed; extra != 0)
    throw InputError(name, "file has " + std::to_string(bytes.size()) + " bytes but the header (" +
                               shape + ", after " + std::to_string(data_start) +
                               " header bytes) accounts for " +
                               std::to_string(data_start + needed) + ": " + std::to_string(extra) +
                               (extra == 1 ? " byte" : " bytes") +
                               " after the data (wrong NX/NY/NZ, MODE or NSYMBT?)");

  // File axis f (0 = columns, fastest) runs along space axis axis[f]-1.
  Grid grid;
  std::array<int, 3> space_of{};
  for (int f = 0; f < 3; ++f) {
    const int s = axis[static_cast<std::size_t>(f)] - 1;
    space_of[static_cast<std::size_t>(f)] = s;
    grid.dims[static_cast<std::size_t>(s)] = n[static_cast<std::size_t>(f)];
  }
  for (int s = 0; s < 3; ++s) {
    const auto si = static_cast<std::size_t>(s);
    if (!(cell[si] > 0.0f) || m[si] < 1 || !std::isfinite(cell[si]))
      throw InputError(name, "header: voxel size undefined along axis " + std::string(1, "XYZ"[s]) +
                                 " (cell length " + std::to_string(cell[si]) + ", sampling " +
                                 std::to_string(m[si]) + ")");
    grid.spacing[s] = static_cast<double>(cell[si]) / m[si];
  }
  const bool origin_set = origin[0] != 0.0f || origin[1] != 0.0f || origin[2] != 0.0f;
  if (origin_set) {
    for (int s = 0; s < 3; ++s) {
      if (!std::isfinite(origin[static_cast<std::size_t>(s)]))
        throw InputError(name, "header: origin is not finite");
      grid.origin[s] = origin[static_cast<std::size_t>(s)];
    }
  } else {
    // CCP4 convention: the first sample sits at index N*START along each file axis.
    for (int f = 0; f < 3; ++f) {
      const int s = space_of[static_cast<std::size_t>(f)];
      grid.origin[s] = start[static_cast<std::size_t>(f)] * grid.spacing[s];
    }
  }

  grid.values.assign(*count, 0.0);
  const char* data = bytes.data() + data_start;
  std::array<int, 3> idx{};
  std::size_t r = 0;
  for (int s2 = 0; s2 < n[2]; ++s2)
    for (int s1 = 0; s1 < n[1]; ++s1)
      for (int s0 = 0; s0 < n[0]; ++s0, ++r) {
        const char* p = data + r * value_bytes;
        double v = 0.0;
        switch (mode) {
          case 0:
            v = static_cast<signed char>(*p);
            break;
          case 1:
            v = load<std::int16_t>(p, swap);
            break;
          case 6:
            v = load<std::uint16_t>(p, swap);
            break;
          default:
            v = static_cast<double>(load<float>(p, swap));
            break;
        }
        if (!std::isfinite(v))
          throw InputError(name, "value " + std::to_string(r) + " is not finite");
        idx[static_cast<std::size_t>(space_of[0])] = s0;
        idx[static_cast<std::size_t>(space_of[1])] = s1;
        idx[static_cast<std::size_t>(space_of[2])] = s2;
        grid.at(idx[0], idx[1], idx[2]) = v;
      }
  return grid;
}

void write_mrc(std::ostream& out, const Grid& grid) {
  static_assert(std::endian::native == std::endian::little, "writer assumes a little-endian host");
  std::array<char, kHeaderBytes> header{};
  auto put_int = [&header](int w, std::int32_t v) {
    std::memcpy(header.data() + 4 * (w - 1), &v, 4);
  };
  auto put_float = [&header](int w, float v) { std::memcpy(header.data() + 4 * (w - 1), &v, 4); };
  double lo = 0.0, hi = 0.0, sum = 0.0;
  if (!grid.values.empty()) {
    lo = *std::min_element(grid.values.begin(), grid.values.end());
    hi = *std::max_element(grid.values.begin(), grid.values.end());
    for (double v : grid.values) sum += v;
  }
  const double mean = grid.values.empty() ? 0.0 : sum / static_cast<double>(grid.values.size());
  double squares = 0.0;
  for (double v : grid.values) squares += (v - mean) * (v - mean);
  const double rms =
      grid.values.empty() ? 0.0 : std::sqrt(squares / static_cast<double>(grid.values.size()));

  for (int k = 0; k < 3; ++k) {
    put_int(1 + k, grid.dims[static_cast<std::size_t>(k)]);
    put_int(5 + k, 0);                                       // NXSTART...: origin is in words 50-52
    put_int(8 + k, grid.dims[static_cast<std::size_t>(k)]);  // MX = NX: one voxel per sample
    put_float(11 + k, static_cast<float>(grid.spacing[k] * grid.dims[static_cast<std::size_t>(k)]));
    put_float(14 + k, 90.0f);
    put_int(17 + k, k + 1);
    put_float(50 + k, static_cast<float>(grid.origin[k]));
  }
  put_int(4, 2);
  put_float(20, static_cast<float>(lo));
  put_float(21, static_cast<float>(hi));
  put_float(22, static_cast<float>(mean));
  put_int(23, 1);  // ISPG 1: a single volume (MRC2014)
  put_int(24, 0);
  put_int(28, 20140);
  std::memcpy(header.data() + 4 * 52, "MAP ", 4);
  const unsigned char stamp[4] = {0x44, 0x44, 0x00, 0x00};
  std::memcpy(header.data() + 4 * 53, stamp, 4);
  put_float(55, static_cast<float>(rms));
  put_int(56, 1);
  const char label[] = "written by molmesh";
  std::memcpy(header.data() + 4 * 56, label, sizeof label - 1);
  out.write(header.data(), static_cast<std::streamsize>(header.size()));

  std::vector<float> buffer;
  buffer.reserve(1 << 18);
  for (double v : grid.values) {
    buffer.push_back(static_cast<float>(v));
    if (buffer.size() == buffer.capacity()) {
      out.write(reinterpret_cast<const char*>(buffer.data()),
                static_cast<std::streamsize>(buffer.size() * 4));
      buffer.clear();
    }
  }
  out.write(reinterpret_cast<const char*>(buffer.data()),
            static_cast<std::streamsize>(buffer.size() * 4));
}

}  // namespace molmesh
