#pragma once
// The domain J integrals of the FEM (docs/design.md section 2, "Tip criterion and J integrals"):
// the weights of tip J and J_ff, and the bulk part of J = int_A (sigma_i1 u_i,1 - W) q,1 dA. The
// crack-face term is the crack plane's (crack_plane.h), with the same weights.
#include "fiberbridge/fem/dcb_common.h"
#include "mpi_algebra.h"

#include <deal.II/base/symmetric_tensor.h>
#include <deal.II/dofs/dof_handler.h>
#include <deal.II/fe/mapping.h>

#include <Epetra_BlockMap.h>

#include <algorithm>
#include <cmath>
#include <memory>
#include <vector>

namespace fiberbridge::fem {

/// Tip J: a full-height strip of +-`elements` elements around the tip, q = 1 on the inner half
/// (the elements touching the tip carry the largest error of the singular field).
inline Ramp tip_j_weight(double x_tip, unsigned elements, double dx) {
  const double r = elements * dx;
  const double p = std::max(1u, elements / 2) * dx;
  return {x_tip - r, x_tip - p, x_tip + p, x_tip + r};
}

/// J_ff: q = 1 over the whole zone, ramps in the free arms between load line and notch and one
/// arm thickness ahead of the tip strip (so no crack-face term), kinks on mesh lines. The rising
/// ramp starts at 0.2 a0, or one arm thickness past `x_end_feature` (an end block's edge,
/// DcbGeometry): a free face there has a re-entrant corner whose singular energy density Gauss
/// quadrature of the face term would integrate poorly (docs/design.md section 2, "Specimen
/// meshes").
inline Ramp far_field_j_weight(double a0, double arm_thickness, double x_tip, unsigned elements,
                               double dx, double x_end, double x_end_feature = 0) {
  auto snap = [&](double x) { return std::round(x / dx) * dx; };
  const double x2 = x_tip + elements * dx;
  const double x0 =
      x_end_feature > 0
          ? std::max(snap(0.2 * a0), std::ceil((x_end_feature + arm_thickness) / dx - 1e-9) * dx)
          : snap(0.2 * a0);
  return {x0, snap(0.8 * a0), x2, std::min(snap(x2 + arm_thickness), x_end)};
}

/// This rank's part of int_V (sigma_i1 u_i,1 - W) q,1 dV over its owned cells (Moran & Shih;
/// q = q(x) across the whole width): sum over ranks and divide by the width for J. With
/// `finite`, the same integral in the reference configuration with the first Piola-Kirchhoff
/// stress P and the St Venant-Kirchhoff energy (fem/finite_strain.h): the energy-momentum
/// (Eshelby) form, path-independent at any rotation.
template <int dim>
double bulk_domain_j_local(const dealii::DoFHandler<dim>& dof_handler,
                           const dealii::Mapping<dim>& mapping, unsigned degree,
                           const dealii::SymmetricTensor<4, dim>& C, const Vec& u_ghost,
                           const Ramp& q, bool finite);

/// bulk_domain_j_local with the cell data it needs built once per mesh: each locally owned
/// cell's x range and dofs, the boundary faces whose normal has an x component (with their
/// shape gradients, quadrature points, n_1 and JxW), and the shape gradients, JxW and quadrature
/// point offsets of each distinct cell shape (the generated meshes have a few: a size per layer,
/// as DcbModel::assemble_bulk's shape_matrices_). A call then only reads the dof values of the
/// cells where q varies or with such a face inside the ramp: no FEValues reinit. Same sums in the
/// same order as bulk_domain_j_local, so the same J to round-off (cells of one shape share
/// gradients computed on one of them). Built on the first call, and again where it is called with
/// another DoFHandler, mapping or degree or the mesh's cell or dof counts changed; a mesh changed
/// in place with the same counts needs clear(). A mapping other than MappingQ1 (or MappingQ of
/// degree 1), whose cells are not fixed by their vertices alone, takes bulk_domain_j_local.
template <int dim>
class DomainJIntegral {
public:
  double bulk_local(const dealii::DoFHandler<dim>& dof_handler, const dealii::Mapping<dim>& mapping,
                    unsigned degree, const dealii::SymmetricTensor<4, dim>& C, const Vec& u_ghost,
                    const Ramp& q, bool finite);
  void clear() {
    dof_handler_ = nullptr;
    lid_map_.reset();
  }
  /// Distinct cell shapes of the cached mesh (0 before the first call or where the fallback
  /// applies): what the cache saves, for the tests.
  std::size_t n_shapes() const { return shapes_.size(); }

private:
  void build(const dealii::DoFHandler<dim>& dof_handler, const dealii::Mapping<dim>& mapping,
             unsigned degree);

  /// Gradients of the shape functions at the quadrature points, flat: grad[(k n + i) dim + d]
  /// is d phi_i / d x_d at point k (phi_i's one nonzero component is component_[i]).
  struct Shape {
    std::vector<double> grad, JxW, dx; ///< dx: x of the point minus x of the cell's vertex 0
  };
  struct Face {
    double xa, xb;                        ///< x range of its vertices
    std::vector<double> grad, n1, JxW, x; ///< as Shape; n_1, JxW and x at its points
  };
  struct Cell {
    double xa, xb, x_vertex0;
    unsigned shape;
    unsigned first_face, end_face; ///< its free faces in faces_
  };

  const dealii::DoFHandler<dim>* dof_handler_ = nullptr;
  const dealii::Mapping<dim>* mapping_ = nullptr;
  unsigned degree_ = 0;
  dealii::types::global_dof_index n_dofs_ = 0;
  unsigned n_cells_ = 0;
  bool fallback_ = false;
  unsigned n_cell_dofs_ = 0, n_q_ = 0, n_face_q_ = 0;
  std::vector<unsigned> component_;
  std::vector<Cell> cells_;                           ///< locally owned, in active cell order
  std::vector<dealii::types::global_dof_index> dofs_; ///< n_cell_dofs_ per cell of cells_
  std::vector<Shape> shapes_;
  std::vector<Face> faces_;
  /// Local indices of dofs_ in the map of the vector last read, and that map (a copy, which
  /// keeps its data alive so that a new map cannot take its address).
  std::unique_ptr<Epetra_BlockMap> lid_map_;
  std::vector<int> lids_;
};

} // namespace fiberbridge::fem
