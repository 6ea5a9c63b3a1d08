#include "fiberbridge/mpm/particles.h"

#include "fiberbridge/core/error.h"

namespace fiberbridge::mpm {

Particles Particles::rectangle(double x0, double y0, double width, double height, int n_x, int n_y,
                               double density, double thickness) {
  if (n_x < 1 || n_y < 1 || !(width > 0) || !(height > 0))
    throw InputError("MPM particles: the body needs a positive size and at least one particle "
                     "per axis");
  Particles p;
  p.lattice_nx = n_x;
  p.lattice_ny = n_y;
  p.spacing_x = width / n_x;
  p.spacing_y = height / n_y;
  p.x0 = x0;
  p.y0 = y0;
  const std::size_t n = static_cast<std::size_t>(n_x) * n_y;
  const double v = p.spacing_x * p.spacing_y * thickness;
  p.X.resize(n);
  p.Y.resize(n);
  for (int i = 0; i < n_x; ++i)
    for (int j = 0; j < n_y; ++j) {
      const int k = p.index(i, j);
      p.X[k] = x0 + (i + 0.5) * p.spacing_x;
      p.Y[k] = y0 + (j + 0.5) * p.spacing_y;
    }
  p.x = p.X;
  p.y = p.Y;
  p.vx.assign(n, 0.0);
  p.vy.assign(n, 0.0);
  p.mass.assign(n, density * v);
  p.volume.assign(n, v);
  p.F.assign(n, {1.0, 0.0, 0.0, 1.0});
  p.strain.assign(n, {0.0, 0.0, 0.0});
  p.stress.assign(n, {0.0, 0.0, 0.0});
  return p;
}

} // namespace fiberbridge::mpm
