#include "virtual_dic.h"

#include "fiberbridge/core/error.h"
#include "fiberbridge/core/format.h"
#include "fiberbridge/core/units.h"

#include <deal.II/base/bounding_box.h>
#include <deal.II/base/geometry_info.h>
#include <deal.II/base/mpi.h>
#include <deal.II/fe/fe.h>

#include <algorithm>
#include <numeric>

namespace fiberbridge::fem {

using namespace dealii;

template <int dim>
PointSampler<dim>::PointSampler(const DoFHandler<dim>& dof_handler, const Mapping<dim>& mapping,
                                const std::vector<std::array<double, 2>>& points,
                                const std::vector<char>& top) {
  const auto& fe = dof_handler.get_fe();
  const unsigned n = fe.n_dofs_per_cell();
  terms_.assign(points.size(), {});
  on_body_.assign(points.size(), 0);
  std::vector<types::global_dof_index> dofs(n);
  // The points by x, so that each cell visits only those within its x extent (10^4 points on
  // 10^4 cells would otherwise be 10^8 box tests).
  std::vector<std::size_t> order(points.size());
  std::iota(order.begin(), order.end(), std::size_t(0));
  std::sort(order.begin(), order.end(),
            [&](std::size_t a, std::size_t b) { return points[a][0] < points[b][0]; });
  std::vector<double> xs(points.size());
  for (std::size_t i = 0; i < order.size(); ++i)
    xs[i] = points[order[i]][0];
  for (const auto& cell : dof_handler.active_cell_iterators()) {
    if (!cell->is_locally_owned())
      continue;
    const bool cell_top = cell->material_id() == 0;
    const auto box = cell->bounding_box();
    const double tol = 1e-9 * cell->diameter();
    bool got_dofs = false;
    const auto first = std::lower_bound(xs.begin(), xs.end(), box.lower_bound(0) - tol),
               last = std::upper_bound(xs.begin(), xs.end(), box.upper_bound(0) + tol);
    for (auto it = first; it != last; ++it) {
      const std::size_t k = order[std::size_t(it - xs.begin())];
      // A point found on one cell keeps it (on a shared face either side gives the same value).
      if (on_body_[k] || bool(top[k]) != cell_top)
        continue;
      Point<dim> p;
      p[0] = points[k][0];
      p[1] = points[k][1];
      bool in_box = true;
      for (unsigned d = 0; d < 2; ++d)
        in_box = in_box && p[d] >= box.lower_bound(d) - tol && p[d] <= box.upper_bound(d) + tol;
      if (!in_box)
        continue;
      Point<dim> unit;
      try {
        unit = mapping.transform_real_to_unit_cell(cell, p);
      } catch (const typename Mapping<dim>::ExcTransformationFailed&) {
        continue;
      }
      if (!GeometryInfo<dim>::is_inside_unit_cell(unit, 1e-9))
        continue;
      if (!got_dofs) {
        cell->get_dof_indices(dofs);
        got_dofs = true;
      }
      for (unsigned i = 0; i < n; ++i) {
        const unsigned c = fe.system_to_component_index(i).first;
        const double w = fe.shape_value(i, unit);
        if (c < 2 && w != 0)
          terms_[k].push_back({dofs[i], c, w});
      }
      on_body_[k] = 1;
    }
  }
}

template <int dim>
void PointSampler<dim>::sample(const Vec& u_ghost, std::vector<double>& ux,
                               std::vector<double>& uy) const {
  ux.assign(terms_.size(), 0.0);
  uy.assign(terms_.size(), 0.0);
  for (std::size_t k = 0; k < terms_.size(); ++k)
    for (const auto& t : terms_[k])
      (t.component == 0 ? ux : uy)[k] += t.weight * u_ghost[t.dof];
}

namespace {

/// The settings, once the run is known to be one the virtual test can sample.
const result::VirtualDicSettings& checked(const result::VirtualDicSettings& s, int dim,
                                          MPI_Comm comm) {
  if (dim != 2)
    throw InputError("FEM/Virtual DIC/Enabled: the virtual test samples the 2D model only; set "
                     "FEM/Dimension = 2");
  if (Utilities::MPI::n_mpi_processes(comm) != 1)
    throw InputError("FEM/Virtual DIC/Enabled: the virtual test runs on one MPI rank (its "
                     "sampler reads the whole field); run this scene without mpirun");
  s.validate("FEM/Virtual DIC");
  return s;
}

std::vector<std::array<double, 2>> grid_points(const result::DicGrid& g) {
  std::vector<std::array<double, 2>> p(g.size());
  for (std::size_t k = 0; k < g.size(); ++k)
    p[k] = {{g.x(k), g.y(k)}};
  return p;
}

std::vector<char> above(const result::DicGrid& g) {
  std::vector<char> t(g.size());
  for (std::size_t k = 0; k < g.size(); ++k)
    t[k] = g.y(k) > 0;
  return t;
}

} // namespace

template <int dim>
VirtualTestRecorder<dim>::VirtualTestRecorder(const result::VirtualDicSettings& settings,
                                              const specimen::Specimen& specimen,
                                              const specimen::Material& material,
                                              const DoFHandler<dim>& dof_handler,
                                              const Mapping<dim>& mapping, MPI_Comm comm)
    : settings_(checked(settings, dim, comm)), specimen_(specimen), material_(material),
      grid_(result::make_dic_grid(settings_, specimen.length, specimen.arm_thickness())),
      grid_sampler_(dof_handler, mapping, grid_points(grid_), above(grid_)),
      root_sampler_(dof_handler, mapping,
                    {{{specimen.initial_crack, 0.0}}, {{specimen.initial_crack, 0.0}}}, {1, 0}),
      test_(settings_, grid_, grid_sampler_.on_body()) {
  if (!root_sampler_.on_body()[0] || !root_sampler_.on_body()[1])
    throw ComputationError(
        "FEM/Virtual DIC: the initial notch root (x = " + fmt(specimen.initial_crack / units::mm) +
        " mm, y = 0) lies on no cell of one of the arms");
  result::VirtualTestState s;
  s.crack_tip = s.zone_front = specimen.initial_crack;
  s.u.assign(grid_.size(), 0.0);
  s.v.assign(grid_.size(), 0.0);
  test_.add_state(std::move(s));
}

template <int dim>
void VirtualTestRecorder<dim>::record(const Vec& u_ghost, double opening, double load,
                                      double crack_tip, double zone_front) {
  result::VirtualTestState s;
  s.opening = opening;
  s.load = load;
  s.crack_tip = crack_tip;
  s.zone_front = zone_front;
  grid_sampler_.sample(u_ghost, s.u, s.v);
  std::vector<double> rx, ry;
  root_sampler_.sample(u_ghost, rx, ry);
  s.delta_root = ry[0] - ry[1];
  test_.add_state(std::move(s));
}

template <int dim>
result::VirtualTestFiles VirtualTestRecorder<dim>::write(const std::string& output_dir) const {
  using units::mm;
  using units::MPa;
  const auto& s = specimen_;
  const auto& m = material_;
  // The specimen and material of the run, so that reduce and extract see the test's own.
  const std::string sections =
      "subsection Specimen\n  set Length = " + fmt(s.length / mm, 10) +
      "\n  set Width = " + fmt(s.width / mm, 10) + "\n  set Height = " + fmt(s.height / mm, 10) +
      "\n  set Initial crack = " + fmt(s.initial_crack / mm, 10) +
      "\nend\n\nsubsection Material\n  set E_L = " + fmt(m.E_L / MPa, 10) +
      "\n  set E_T = " + fmt(m.E_T / MPa, 10) + "\n  set G_LT = " + fmt(m.G_LT / MPa, 10) +
      "\n  set nu_LT = " + fmt(m.nu_LT, 10) +
      "\n  set Plane = " + (m.plane_stress ? "stress" : "strain") + "\nend\n";
  return test_.write(output_dir + "/virtual_test", sections, s.initial_crack);
}

template class PointSampler<2>;
template class PointSampler<3>;
template class VirtualTestRecorder<2>;
template class VirtualTestRecorder<3>;

} // namespace fiberbridge::fem
