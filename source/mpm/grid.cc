#include "fiberbridge/mpm/grid.h"

#include "fiberbridge/core/error.h"

#include <string>

namespace fiberbridge::mpm {

Grid::Grid(double x_min, double y_min, double cell, int nx, int ny)
    : x_min_(x_min), y_min_(y_min), cell_(cell), nx_(nx), ny_(ny) {
  if (!(cell > 0) || nx < 2 || ny < 2)
    throw InputError("MPM grid: need a positive cell size and at least 2 x 2 nodes, got " +
                     std::to_string(nx) + " x " + std::to_string(ny));
  fields_.resize(2 * static_cast<std::size_t>(nx) * ny);
}

void Grid::reset() {
  for (auto& f : fields_)
    f = NodeField{};
}

} // namespace fiberbridge::mpm

#include "fiberbridge/mpm/shape_function.h"

namespace fiberbridge::mpm {

bool interpolate_field_velocity(const Grid& grid, int side, double x, double y, double& vx,
                                double& vy) {
  const AxisWeights wx = linear_weights(x, grid.x_min(), grid.cell());
  const AxisWeights wy = linear_weights(y, grid.y_min(), grid.cell());
  double sum = 0, sx = 0, sy = 0;
  for (int a = 0; a < 2; ++a)
    for (int b = 0; b < 2; ++b) {
      const int i = wx.first + a, j = wy.first + b;
      if (i < 0 || j < 0 || i >= grid.nx() || j >= grid.ny())
        continue;
      const NodeField& f = grid.field(grid.node(i, j), side);
      if (f.mass <= 0)
        continue;
      const double S = wx.S[a] * wy.S[b];
      sum += S;
      sx += S * f.vx_new;
      sy += S * f.vy_new;
    }
  if (sum <= 0)
    return false;
  vx = sx / sum;
  vy = sy / sum;
  return true;
}

} // namespace fiberbridge::mpm
