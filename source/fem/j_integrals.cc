// The bulk part of the domain J integral (j_integrals.h; docs/design.md section 2).
#include "j_integrals.h"

#include "fiberbridge/fem/finite_strain.h"

#include <deal.II/base/quadrature_lib.h>
#include <deal.II/fe/fe_values.h>

namespace fiberbridge::fem {

using namespace dealii;

template <int dim>
double bulk_domain_j_local(const DoFHandler<dim>& dof_handler, const Mapping<dim>& mapping,
                           unsigned degree, const SymmetricTensor<4, dim>& C, const Vec& u_ghost,
                           const Ramp& q, bool finite) {
  const QGauss<dim> quadrature(degree + 1);
  FEValues<dim> fe_values(mapping, dof_handler.get_fe(), quadrature,
                          update_gradients | update_JxW_values | update_quadrature_points);
  const FEValuesExtractors::Vector displacement(0);
  std::vector<Tensor<2, dim>> grad(quadrature.size());
  double J = 0;
  for (const auto& cell : dof_handler.active_cell_iterators()) {
    if (!cell->is_locally_owned())
      continue;
    // Only cells where q varies contribute (q depends on x only, kinks on mesh lines).
    const double xa = cell->vertex(0)[0], xb = cell->vertex(1)[0];
    if (xb <= q.x0 || xa >= q.x3 || (xa >= q.x1 && xb <= q.x2))
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
