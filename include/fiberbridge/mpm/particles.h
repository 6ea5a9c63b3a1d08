#pragma once
// Material points, structure of arrays. Particles are created on a regular lattice over a
// rectangle and keep their lattice order, so that the particles of a strip or a box of the
// reference configuration (J-integral domains) are found by index, without a search.
#include <array>
#include <vector>

namespace fiberbridge::mpm {

struct Particles {
  int lattice_nx = 0, lattice_ny = 0;  ///< particle index = ix * lattice_ny + iy
  double spacing_x = 0, spacing_y = 0; ///< lattice spacing; the uGIMP box is half of it
  double x0 = 0, y0 = 0;               ///< lower-left corner of the rectangle

  std::vector<double> X, Y;                  ///< reference position [m]
  std::vector<double> x, y;                  ///< current position [m]
  std::vector<double> vx, vy;                ///< velocity [m/s]
  std::vector<double> mass;                  ///< [kg] (for the whole specimen width)
  std::vector<double> volume;                ///< reference volume [m^3] (whole width)
  std::vector<std::array<double, 4>> F;      ///< deformation gradient F11 F12 F21 F22
  std::vector<std::array<double, 3>> strain; ///< material-frame strain xx yy xy (U - I)
  std::vector<std::array<double, 3>> stress; ///< Cauchy stress xx yy xy [Pa]

  std::size_t size() const { return X.size(); }
  int index(int ix, int iy) const { return ix * lattice_ny + iy; }

  /// Fills the rectangle [x0, x0 + width] x [y0, y0 + height] with a lattice of n_x by n_y
  /// particles of the given density and out-of-plane thickness, at rest and unstrained.
  static Particles rectangle(double x0, double y0, double width, double height, int n_x, int n_y,
                             double density, double thickness);
};

} // namespace fiberbridge::mpm
