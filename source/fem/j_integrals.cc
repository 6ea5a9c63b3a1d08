// The bulk part of the domain J integral (j_integrals.h; docs/design.md section 2).
#include "j_integrals.h"

#include "fiberbridge/fem/finite_strain.h"

#include <deal.II/base/quadrature_lib.h>
#include <deal.II/fe/fe_values.h>
#include <deal.II/fe/mapping_q.h>
#include <deal.II/fe/mapping_q1.h>

#include <Epetra_BlockMap.h>
#include <Epetra_MultiVector.h>

#include <algorithm>
#include <limits>
#include <map>
#include <memory>
#include <string>
#include <tuple>
#include <typeinfo>
#include <utility>

namespace fiberbridge::fem {

using namespace dealii;

namespace {

/// The strain energy density W at a displacement gradient (`finite`: St Venant-Kirchhoff).
template <int dim>
double energy_density(const SymmetricTensor<4, dim>& C, const Tensor<2, dim>& grad, bool finite) {
  if (finite)
    return SvkPoint<dim>(C, grad).W;
  const SymmetricTensor<2, dim> eps = symmetrize(grad);
  return 0.5 * ((C * eps) * eps);
}

/// The domain integrand sigma_i1 u_i,1 - W (`finite`: P_i1 u_i,1 - W, the Eshelby form).
template <int dim>
double domain_integrand(const SymmetricTensor<4, dim>& C, const Tensor<2, dim>& grad, bool finite) {
  double t = 0;
  if (finite) {
    const SvkPoint<dim> s(C, grad);
    t = -s.W;
    for (unsigned i = 0; i < dim; ++i)
      t += s.P[i][0] * grad[i][0];
  } else {
    const SymmetricTensor<2, dim> eps = symmetrize(grad);
    const SymmetricTensor<2, dim> sigma = C * eps;
    t = -0.5 * (sigma * eps);
    for (unsigned i = 0; i < dim; ++i)
      t += sigma[i][0] * grad[i][0];
  }
  return t;
}

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
    term += energy_density(C, grad[k], finite) * n1 * qk * face_values.JxW(k);
  }
  return term;
}

/// Whether a (straight) face's normal has an x component: faces of the generated mesh do not,
/// so the free-face term costs them nothing. In 3D the normal is the cross product of the edges
/// from vertex 0 (to vertices 1 and 2 in deal.II's numbering).
template <typename Iterator>
std::pair<double, double> x_range(const Iterator& it) {
  double xa = it->vertex(0)[0], xb = xa;
  for (const unsigned v : it->vertex_indices()) {
    xa = std::min(xa, it->vertex(v)[0]);
    xb = std::max(xb, it->vertex(v)[0]);
  }
  return {xa, xb};
}

template <int dim, typename Face>
bool normal_has_x(const Face& face) {
  const auto a = face->vertex(1) - face->vertex(0);
  if constexpr (dim == 2) {
    return a[1] != 0;
  } else {
    const auto b = face->vertex(2) - face->vertex(0);
    return a[1] * b[2] - a[2] * b[1] != 0;
  }
}

/// The same where the face lies (partly) where q is not zero.
template <int dim, typename Face>
bool normal_has_x(const Face& face, const Ramp& q) {
  const auto [xa, xb] = x_range(face);
  if (xb <= q.x0 || xa >= q.x3)
    return false;
  return normal_has_x<dim>(face);
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
    const auto [xa, xb] = x_range(cell);
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
      J += domain_integrand(C, grad[k], finite) * dq * fe_values.JxW(k);
    }
  }
  return J;
}

// ---------------------------------------------------------------------------------------------
// DomainJIntegral

namespace {

/// Gradients at n_points points of the cell's field from the dof values u and the flat shape
/// gradients: the sum of FEValuesViews::Vector::get_function_gradients, in its order (by shape
/// function, zero dof values skipped), so the same bits from the same shape gradients.
template <int dim>
void gather_gradients(const std::vector<double>& u, const std::vector<unsigned>& component,
                      const double* shape_grad, unsigned n_points,
                      std::vector<Tensor<2, dim>>& grad) {
  const unsigned n = u.size();
  for (unsigned k = 0; k < n_points; ++k)
    grad[k] = 0;
  for (unsigned i = 0; i < n; ++i) {
    const double value = u[i];
    if (value == 0)
      continue;
    const unsigned c = component[i];
    for (unsigned k = 0; k < n_points; ++k) {
      const double* g = shape_grad + (std::size_t(k) * n + i) * dim;
      for (unsigned d = 0; d < dim; ++d)
        grad[k][c][d] += value * g[d];
    }
  }
}

} // namespace

template <int dim>
void DomainJIntegral<dim>::build(const DoFHandler<dim>& dof_handler, const Mapping<dim>& mapping,
                                 unsigned degree) {
  dof_handler_ = &dof_handler;
  mapping_ = &mapping;
  degree_ = degree;
  n_dofs_ = dof_handler.n_dofs();
  n_cells_ = dof_handler.get_triangulation().n_active_cells();
  cells_.clear();
  dofs_.clear();
  shapes_.clear();
  faces_.clear();
  lid_map_.reset();
  // A cell of MappingQ1 is fixed by its vertices, so cells whose vertices are translates of one
  // another share gradients and JxW. Other mappings may bend cells (manifolds) or move them
  // (MappingQEulerian, MappingQCache: derived from MappingQ, hence the exact type): the plain
  // path.
  const bool q1 = typeid(mapping) == typeid(MappingQ1<dim>) ||
                  (typeid(mapping) == typeid(MappingQ<dim>) &&
                   static_cast<const MappingQ<dim>&>(mapping).get_degree() == 1);
  fallback_ = !q1;
  if (fallback_)
    return;
  const auto& fe = dof_handler.get_fe();
  n_cell_dofs_ = fe.n_dofs_per_cell();
  component_.resize(n_cell_dofs_);
  for (unsigned i = 0; i < n_cell_dofs_; ++i)
    component_[i] = fe.system_to_component_index(i).first;
  const QGauss<dim> quadrature(degree + 1);
  const QGauss<dim - 1> face_quadrature(degree + 1);
  n_q_ = quadrature.size();
  n_face_q_ = face_quadrature.size();
  FEValues<dim> fe_values(mapping, fe, quadrature,
                          update_gradients | update_JxW_values | update_quadrature_points);
  FEFaceValues<dim> face_values(mapping, fe, face_quadrature,
                                update_gradients | update_JxW_values | update_quadrature_points |
                                    update_normal_vectors);
  // Shape keys: vertex offsets from vertex 0 in units of 1e-12 of the mesh's extent. Translated
  // cells of a generated mesh differ by the round-off of their coordinates (1e-16 relative);
  // two cells that round to different keys only cost a second shape.
  double extent = 0;
  for (const auto& cell : dof_handler.active_cell_iterators())
    if (cell->is_locally_owned())
      for (const unsigned v : cell->vertex_indices())
        for (unsigned d = 0; d < dim; ++d)
          extent = std::max(extent, std::abs(cell->vertex(v)[d]));
  const double tol = 1e-12 * std::max(extent, std::numeric_limits<double>::min());
  std::map<std::vector<long long>, unsigned> shape_of;
  std::vector<types::global_dof_index> dofs(n_cell_dofs_);
  for (const auto& cell : dof_handler.active_cell_iterators()) {
    if (!cell->is_locally_owned())
      continue;
    const auto [xa, xb] = x_range(cell);
    Cell c{xa, xb, cell->vertex(0)[0], 0, unsigned(faces_.size()), unsigned(faces_.size())};
    cell->get_dof_indices(dofs);
    dofs_.insert(dofs_.end(), dofs.begin(), dofs.end());
    std::vector<long long> key;
    for (unsigned v = 1; v < cell->n_vertices(); ++v)
      for (unsigned d = 0; d < dim; ++d)
        key.push_back(std::llround((cell->vertex(v)[d] - cell->vertex(0)[d]) / tol));
    const auto found = shape_of.find(key);
    if (found != shape_of.end())
      c.shape = found->second;
    else {
      fe_values.reinit(cell);
      Shape shape;
      shape.grad.resize(std::size_t(n_q_) * n_cell_dofs_ * dim);
      for (unsigned k = 0; k < n_q_; ++k) {
        shape.JxW.push_back(fe_values.JxW(k));
        shape.dx.push_back(fe_values.quadrature_point(k)[0] - c.x_vertex0);
        for (unsigned i = 0; i < n_cell_dofs_; ++i)
          for (unsigned d = 0; d < dim; ++d)
            shape.grad[(std::size_t(k) * n_cell_dofs_ + i) * dim + d] =
                fe_values.shape_grad(i, k)[d];
      }
      c.shape = shapes_.size();
      shape_of.emplace(std::move(key), c.shape);
      shapes_.push_back(std::move(shape));
    }
    // The free faces with n_1 != 0 (bulk_domain_j_local): a few (tapered arms, end blocks), each
    // with its own data.
    if (cell->at_boundary())
      for (const unsigned f : cell->face_indices())
        if (cell->face(f)->at_boundary() && normal_has_x<dim>(cell->face(f))) {
          face_values.reinit(cell, f);
          Face face;
          std::tie(face.xa, face.xb) = x_range(cell->face(f));
          face.grad.resize(std::size_t(n_face_q_) * n_cell_dofs_ * dim);
          for (unsigned k = 0; k < n_face_q_; ++k) {
            face.n1.push_back(face_values.normal_vector(k)[0]);
            face.JxW.push_back(face_values.JxW(k));
            face.x.push_back(face_values.quadrature_point(k)[0]);
            for (unsigned i = 0; i < n_cell_dofs_; ++i)
              for (unsigned d = 0; d < dim; ++d)
                face.grad[(std::size_t(k) * n_cell_dofs_ + i) * dim + d] =
                    face_values.shape_grad(i, k)[d];
          }
          faces_.push_back(std::move(face));
          c.end_face = faces_.size();
        }
    cells_.push_back(c);
  }
}

template <int dim>
double DomainJIntegral<dim>::bulk_local(const DoFHandler<dim>& dof_handler,
                                        const Mapping<dim>& mapping, unsigned degree,
                                        const SymmetricTensor<4, dim>& C, const Vec& u_ghost,
                                        const Ramp& q, bool finite) {
  if (dof_handler_ != &dof_handler || mapping_ != &mapping || degree_ != degree ||
      n_dofs_ != dof_handler.n_dofs() ||
      n_cells_ != dof_handler.get_triangulation().n_active_cells())
    build(dof_handler, mapping, degree);
  if (fallback_)
    return bulk_domain_j_local(dof_handler, mapping, degree, C, u_ghost, q, finite);
  // bulk_domain_j_local's loop on the cached data: the same cells, faces and points in the
  // same order. The cells' dof values straight from the Epetra vector by local index, as
  // TrilinosWrappers::MPI::Vector::operator() reads them (it looks each one up in the map):
  // the local indices are kept while the vector has the same map (a copy holds it alive).
  const Epetra_MultiVector& values = u_ghost.trilinos_vector();
  if (!lid_map_ || lid_map_->DataPtr() != values.Map().DataPtr()) {
    lid_map_ = std::make_unique<Epetra_BlockMap>(values.Map());
    lids_.resize(dofs_.size());
    for (std::size_t i = 0; i < dofs_.size(); ++i) {
      lids_[i] = values.Map().LID(TrilinosWrappers::types::int_type(dofs_[i]));
      AssertThrow(lids_[i] >= 0, ExcMessage("DomainJIntegral: a locally owned cell's dof " +
                                            std::to_string(dofs_[i]) +
                                            " is not in the vector (not a ghosted vector?)"));
    }
  }
  const double* local = values[0];
  std::vector<double> u(n_cell_dofs_);
  std::vector<Tensor<2, dim>> grad(std::max(n_q_, n_face_q_));
  double J = 0;
  for (std::size_t c = 0; c < cells_.size(); ++c) {
    const Cell& cell = cells_[c];
    if (cell.xb <= q.x0 || cell.xa >= q.x3)
      continue;
    const bool domain = !(cell.xa >= q.x1 && cell.xb <= q.x2);
    if (!domain && cell.first_face == cell.end_face)
      continue;
    for (unsigned i = 0; i < n_cell_dofs_; ++i)
      u[i] = local[lids_[c * n_cell_dofs_ + i]];
    for (unsigned f = cell.first_face; f < cell.end_face; ++f) {
      const Face& face = faces_[f];
      if (face.xb <= q.x0 || face.xa >= q.x3)
        continue;
      gather_gradients<dim>(u, component_, face.grad.data(), n_face_q_, grad);
      double term = 0;
      for (unsigned k = 0; k < n_face_q_; ++k) {
        const double n1 = face.n1[k];
        const double qk = q.value(face.x[k]);
        if (n1 == 0 || qk == 0)
          continue;
        term += energy_density(C, grad[k], finite) * n1 * qk * face.JxW[k];
      }
      J += term;
    }
    if (!domain)
      continue;
    const Shape& shape = shapes_[cell.shape];
    gather_gradients<dim>(u, component_, shape.grad.data(), n_q_, grad);
    for (unsigned k = 0; k < n_q_; ++k) {
      const double dq = q.slope(cell.x_vertex0 + shape.dx[k]);
      if (dq == 0)
        continue;
      J += domain_integrand(C, grad[k], finite) * dq * shape.JxW[k];
    }
  }
  return J;
}

template class DomainJIntegral<2>;
template class DomainJIntegral<3>;

template double bulk_domain_j_local<2>(const DoFHandler<2>&, const Mapping<2>&, unsigned,
                                       const SymmetricTensor<4, 2>&, const Vec&, const Ramp&, bool);
template double bulk_domain_j_local<3>(const DoFHandler<3>&, const Mapping<3>&, unsigned,
                                       const SymmetricTensor<4, 3>&, const Vec&, const Ramp&, bool);

} // namespace fiberbridge::fem
