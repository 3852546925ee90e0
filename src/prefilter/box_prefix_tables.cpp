#include "prefilter/box_prefix_tables.hpp"

#include <algorithm>

namespace glintlab {

BoxPrefixTables box_prefix_tables(const PrefilteredNdf& pyramid) {
  const int b = pyramid.settings.block_size, nb = pyramid.blocks_per_side(), r = pyramid.rank();
  BoxPrefixTables t;
  t.block_stride = 2 * r + 1;
  t.footprint_stride = nb * nb * t.block_stride;
  t.values.assign(pyramid.footprints.size() * static_cast<std::size_t>(t.footprint_stride), 0.0f);
  // Running sums in double, in bit order: Q over the blocks below and left (q[bx]: the column
  // sums below the current row, left of and including bx), U per column, L along the row.
  std::vector<double> column_below(static_cast<std::size_t>(nb)), u(static_cast<std::size_t>(nb * r));
  std::vector<double> l(static_cast<std::size_t>(r));
  for (std::uint32_t f = 0; f < pyramid.footprints.size(); ++f) {
    const PrefilteredNdf::AngularFactors af = pyramid.angular_factors(f);
    const float* a_total = af.sa + static_cast<std::size_t>(b * r);  // row B of the prefix sums
    const float* b_total = af.sb + static_cast<std::size_t>(b * r);
    std::fill(column_below.begin(), column_below.end(), 0.0);
    std::fill(u.begin(), u.end(), 0.0);
    for (int by = 0; by < nb; ++by) {
      std::fill(l.begin(), l.end(), 0.0);
      double q = 0.0;  // sum of column_below[0 .. bx - 1]
      for (int bx = 0; bx < nb; ++bx) {
        float* out = &t.values[static_cast<std::size_t>(f) * static_cast<std::size_t>(t.footprint_stride) +
                               static_cast<std::size_t>((by * nb + bx) * t.block_stride)];
        double* column = &u[static_cast<std::size_t>(bx * r)];
        out[0] = static_cast<float>(q);
        for (int k = 0; k < r; ++k) {
          out[1 + k] = static_cast<float>(column[k]);
          out[1 + r + k] = static_cast<float>(l[static_cast<std::size_t>(k)]);
        }
        q += column_below[static_cast<std::size_t>(bx)];
        if (const float* c = pyramid.block_factor(f, by * nb + bx))
          for (int k = 0; k < r; ++k) {
            column[k] += static_cast<double>(b_total[k]) * c[k];
            l[static_cast<std::size_t>(k)] += static_cast<double>(a_total[k]) * c[k];
          }
      }
      // The row done: each column's total below the next row.
      for (int bx = 0; bx < nb; ++bx) {
        double below = 0.0;
        const double* column = &u[static_cast<std::size_t>(bx * r)];
        for (int k = 0; k < r; ++k) below += a_total[k] * column[k];
        column_below[static_cast<std::size_t>(bx)] = below;
      }
    }
  }
  return t;
}

double box_prefix_range_sum(const PrefilteredNdf& pyramid, const BoxPrefixTables& tables, std::uint32_t footprint,
                            glm::dvec2 x0, glm::dvec2 x1) {
  const int b = pyramid.settings.block_size, nb = pyramid.blocks_per_side(), r = pyramid.rank();
  const PrefilteredNdf::AngularFactors af = pyramid.angular_factors(footprint);
  // A corner's block along one axis and its position inside it (x = N: the last block's end).
  const auto block_of = [&](double x) { return std::min(static_cast<int>(x) / b, nb - 1); };
  const auto prefix = [&](const float* sums, const float* m, double t, int k) {
    const int i = std::min(static_cast<int>(t), b - 1);
    return static_cast<double>(sums[i * r + k]) + (t - i) * m[i * r + k];
  };
  const int bx[2] = {block_of(x0.x), block_of(x1.x)}, by[2] = {block_of(x0.y), block_of(x1.y)};
  const double lx[2] = {x0.x - bx[0] * b, x1.x - bx[1] * b}, ly[2] = {x0.y - by[0] * b, x1.y - by[1] * b};
  // Corner (i, j): x_i, y_j; its table entries and its long factor (null: a dropped block).
  const float* t[2][2];
  const float* c[2][2];
  for (int i = 0; i < 2; ++i)
    for (int j = 0; j < 2; ++j) {
      t[i][j] = tables.block(footprint, by[j] * nb + bx[i]);
      c[i][j] = pyramid.block_factor(footprint, by[j] * nb + bx[i]);
    }
  const auto cv = [&](int i, int j, int k) { return c[i][j] ? static_cast<double>(c[i][j][k]) : 0.0; };
  double total = (static_cast<double>(t[1][1][0]) - t[0][1][0]) - (static_cast<double>(t[1][0][0]) - t[0][0][0]);
  for (int k = 0; k < r; ++k) {
    const double pa0 = prefix(af.sa, af.a, lx[0], k), pa1 = prefix(af.sa, af.a, lx[1], k);
    const double pb0 = prefix(af.sb, af.b, ly[0], k), pb1 = prefix(af.sb, af.b, ly[1], k);
    const auto u = [&](int i, int j) { return static_cast<double>(t[i][j][1 + k]); };
    const auto l = [&](int i, int j) { return static_cast<double>(t[i][j][1 + r + k]); };
    total += pa1 * pb1 * cv(1, 1, k) - pa0 * pb1 * cv(0, 1, k) - pa1 * pb0 * cv(1, 0, k) + pa0 * pb0 * cv(0, 0, k) +
             pa1 * (u(1, 1) - u(1, 0)) + pa0 * (u(0, 0) - u(0, 1)) + pb1 * (l(1, 1) - l(0, 1)) + pb0 * (l(0, 0) - l(1, 0));
  }
  return std::max(total, 0.0);
}

}  // namespace glintlab
