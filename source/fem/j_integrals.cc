// The bulk part of the domain J integral (j_integrals.h; docs/design.md section 2).
#include "j_integrals.h"

#include "fiberbridge/fem/finite_strain.h"

#include <deal.II/base/quadrature_lib.h>
#include <deal.II/fe/fe_values.h>

#include <algorithm>

namespace fiberbridge::fem {

using namespace dealii;

namespace {

/// W n_1 q on one boundary face (`finite`: the St Venant-Kirchhoff energy, the reference normal).
template <int dim>
double free_face_term(FEFaceValues<dim>& face_values, const SymmetricTensor<4, dim>& C,
                      const Vec& u_ghost, const Ramp& q, bool finite,
                      std::vector<Tensor<2, dim>>& grad) {
  const FEValuesExtractors::Vector displacement(0);
  face_values[displacement].get_function_gradients(u_ghost, grad);
  double term = 0;
  for (unsigned k = 0; k < grad.size(); ++k) {
    const double n1 = face_values.normal_vector(k)[0];
    const double qk = q.value(face_values.quadrature_point(k)[0]);
    if (n1 == 0 || qk == 0)
      continue;
    double W;
    if (finite) {
      W = SvkPoint<dim>(C, grad[k]).W;
    } else {
      const SymmetricTensor<2, dim> eps = symmetrize(grad[k]);
      W = 0.5 * ((C * eps) * eps);
    }
    term += W * n1 * qk * face_values.JxW(k);
  }
  return term;
}

/// Whether a (straight) face's normal has an x component: faces of the generated mesh do not,
/// so the free-face term costs them nothing. In 3D the normal is the cross product of the edges
/// from vertex 0 (to vertices 1 and 2 in deal.II's numbering).
template <int dim, typename Face>
bool normal_has_x(const Face& face, const Ramp& q) {
  double xa = face->vertex(0)[0], xb = xa;
  for (const unsigned v : face->vertex_indices()) {
    xa = std::min(xa, face->vertex(v)[0]);
    xb = std::max(xb, face->vertex(v)[0]);
  }
  if (xb <= q.x0 || xa >= q.x3)
    return false;
  const auto a = face->vertex(1) - face->vertex(0);
  if constexpr (dim == 2) {
    return a[1] != 0;
  } else {
    const auto b = face->vertex(2) - face->vertex(0);
    return a[1] * b[2] - a[2] * b[1] != 0;
  }
}

} // namespace

template <int dim>
double bulk_domain_j_local(const DoFHandler<dim>& dof_handler, const Mapping<dim>& mapping,
                           unsigned degree, const SymmetricTensor<4, dim>& C, const Vec& u_ghost,
                           const Ramp& q, bool finite) {
  const QGauss<dim> quadrature(degree + 1);
  FEValues<dim> fe_values(mapping, dof_handler.get_fe(), quadrature,
                          update_gradients | update_JxW_values | update_quadrature_points);
  const QGauss<dim - 1> face_quadrature(degree + 1);
  FEFaceValues<dim> face_values(mapping, dof_handler.get_fe(), face_quadrature,
                                update_gradients | update_JxW_values | update_quadrature_points |
                                    update_normal_vectors);
  const FEValuesExtractors::Vector displacement(0);
  std::vector<Tensor<2, dim>> grad(quadrature.size()), face_grad(face_quadrature.size());
  double J = 0;
  for (const auto& cell : dof_handler.active_cell_iterators()) {
    if (!cell->is_locally_owned())
      continue;
    double xa = cell->vertex(0)[0], xb = xa;
    for (const unsigned v : cell->vertex_indices()) {
      xa = std::min(xa, cell->vertex(v)[0]);
      xb = std::max(xb, cell->vertex(v)[0]);
    }
    if (xb <= q.x0 || xa >= q.x3)
      continue;
    // Free faces not parallel to the crack plane (a tapered arm, an end block) close the domain
    // where q is not zero: the divergence theorem leaves int W n_1 q ds on them (t = 0 there).
    // The crack faces and the faces of a rectangle parallel to it have n_1 = 0, the load line
    // and the far end lie where q = 0 (docs/design.md section 2, "Specimen meshes").
    if (cell->at_boundary())
      for (const unsigned f : cell->face_indices())
        if (cell->face(f)->at_boundary() && normal_has_x<dim>(cell->face(f), q)) {
          face_values.reinit(cell, f);
          J += free_face_term(face_values, C, u_ghost, q, finite, face_grad);
        }
    // Only cells where q varies contribute to the domain part (q depends on x only).
    if (xa >= q.x1 && xb <= q.x2)
      continue;
    fe_values.reinit(cell);
    fe_values[displacement].get_function_gradients(u_ghost, grad);
    for (unsigned k = 0; k < quadrature.size(); ++k) {
      const double dq = q.slope(fe_values.quadrature_point(k)[0]);
      if (dq == 0)
        continue;
      double t = 0;
      if (finite) {
        const SvkPoint<dim> s(C, grad[k]);
        t = -s.W;
        for (unsigned i = 0; i < dim; ++i)
          t += s.P[i][0] * grad[k][i][0];
      } else {
        const SymmetricTensor<2, dim> eps = symmetrize(grad[k]);
        const SymmetricTensor<2, dim> sigma = C * eps;
        t = -0.5 * (sigma * eps);
        for (unsigned i = 0; i < dim; ++i)
          t += sigma[i][0] * grad[k][i][0];
      }
      J += t * dq * fe_values.JxW(k);
    }
  }
  return J;
}

template double bulk_domain_j_local<2>(const DoFHandler<2>&, const Mapping<2>&, unsigned,
                                       const SymmetricTensor<4, 2>&, const Vec&, const Ramp&, bool);
template double bulk_domain_j_local<3>(const DoFHandler<3>&, const Mapping<3>&, unsigned,
                                       const SymmetricTensor<4, 3>&, const Vec&, const Ramp&, bool);

} // namespace fiberbridge::fem
