#pragma once
// The header of a NumPy .npy file (format version 1.0, or 2.0 when the header outgrows 64 KiB) for
// a one-dimensional structured array: one little-endian float64 field per channel, one record per
// row. np.load(path) then gives an array indexed by channel name, t["r_lvlh_x_m"], as
// np.genfromtxt(names=True) gives for the CSV. Format: numpy.org/doc/stable/reference/
// generated/numpy.lib.format.html.
#include <cstdint>
#include <string>
#include <vector>

namespace chaser::sim {

// The whole header (magic, version, length, dictionary, padding) for `rows` records, padded so
// that the data starts at a multiple of 64 bytes and the header is at least `min_bytes` long.
// A header written first with rows = 0 and rewritten at the end with the real count keeps its
// length (min_bytes = the first header's size): the count has room to grow in the padding.
std::string npy_header(const std::vector<std::string>& fields, std::int64_t rows, std::size_t min_bytes = 0);

}  // namespace chaser::sim
