// The slit coarse mesh of the DCB (dcb_geometry.h; docs/design.md section 2).
#include "dcb_geometry.h"

#include "fiberbridge/core/error.h"
#include "fiberbridge/fem/dcb_common.h"
#include "specimen_mesh.h"

#include <deal.II/grid/tria_description.h>

#include <algorithm>
#include <cmath>

namespace fiberbridge::fem {

using namespace dealii;

template <int dim>
DcbGeometry make_dcb_mesh(const specimen::Specimen& specimen, const FemParameters& prm,
                          parallel::distributed::Triangulation<dim>& triangulation) {
  if (!prm.mesh.file.empty()) {
    if constexpr (dim == 2)
      return read_specimen_mesh(specimen, prm, triangulation);
    else
      throw InputError("FEM/Mesh file: reads 2D meshes only; set FEM/Dimension = 2");
  }
  // x and y lines from dcb_mesh_lines (one element per advance, graded heights).
  const DcbMeshLines lines = dcb_mesh_lines(specimen, prm);
  DcbGeometry g;
  g.dx = lines.dx;
  g.x_lines = lines.x;
  const std::vector<double>& y_lines = lines.y;
  g.z_lines = {0.0};
  if (dim == 3) {
    const unsigned nz = prm.mesh.width_elements > 0
                            ? prm.mesh.width_elements
                            : std::max(1u, unsigned(std::lround(specimen.width / g.dx)));
    for (unsigned k = 1; k <= nz; ++k)
      g.z_lines.push_back(specimen.width * k / nz);
  }

  const unsigned nx = g.x_lines.size() - 1, ny = y_lines.size() - 1;
  const unsigned nzl = dim == 3 ? g.z_lines.size() : 1; // vertex layers in z
  std::vector<Point<dim>> vertices;
  for (int side : {+1, -1}) // top arm, then the bottom arm with its own crack-plane vertices
    for (unsigned k = 0; k < nzl; ++k)
      for (unsigned j = 0; j <= ny; ++j)
        for (unsigned i = 0; i <= nx; ++i) {
          Point<dim> p;
          p[0] = g.x_lines[i];
          p[1] = side * y_lines[j];
          if (dim == 3)
            p[dim - 1] = g.z_lines[k];
          vertices.push_back(p);
        }
  auto index = [&](unsigned arm, unsigned i, unsigned j, unsigned k) {
    return arm * (nx + 1) * (ny + 1) * nzl + k * (nx + 1) * (ny + 1) + j * (nx + 1) + i;
  };
  std::vector<CellData<dim>> cells;
  for (unsigned arm = 0; arm < 2; ++arm)
    for (unsigned k = 0; k < (dim == 3 ? nzl - 1 : 1u); ++k) {
      for (unsigned j = 0; j < ny; ++j)
        for (unsigned i = 0; i < nx; ++i) {
          CellData<dim> c;
          // Lexicographic vertex order (x fastest, then y increasing, then z): the bottom arm
          // counts j downwards, so its "lower" row is j + 1.
          unsigned v = 0;
          for (unsigned dz = 0; dz < (dim == 3 ? 2u : 1u); ++dz)
            for (unsigned dy = 0; dy < 2; ++dy)
              for (unsigned di = 0; di < 2; ++di) {
                const unsigned jj = arm == 0 ? j + dy : j + 1 - dy;
                c.vertices[v++] = index(arm, i + di, jj, k + dz);
              }
          c.material_id = arm; // 0 top, 1 bottom
          cells.push_back(c);
        }
    }
  triangulation.create_triangulation(vertices, cells, SubCellData());
  return g;
}

template DcbGeometry make_dcb_mesh<2>(const specimen::Specimen&, const FemParameters&,
                                      parallel::distributed::Triangulation<2>&);
template DcbGeometry make_dcb_mesh<3>(const specimen::Specimen&, const FemParameters&,
                                      parallel::distributed::Triangulation<3>&);

} // namespace fiberbridge::fem
