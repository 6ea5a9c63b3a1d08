#pragma once
// The FEM's side of the virtual test (result/virtual_dic.h; docs/design.md section 2, "Virtual
// DIC test"): the displacement of the FE field at the DIC grid's reference points, and the truth
// of each recorded state. The points are located once on the undeformed mesh (the reference
// configuration never moves) and each sample is a sum over one cell's dofs.
//
// The crack plane carries duplicated nodes (the slit mesh of dcb_geometry.h): a point is looked
// up only in the cells of its own arm (material id 0 above the plane, 1 below), and the grid's
// rows sit half a spacing off the plane. The two truth points at the initial notch root lie on
// the plane, one per arm, so their difference is the opening there (delta_root).
//
// 2D and one MPI rank only: the FEM refuses the option otherwise (parameters.cc, and the model's
// run for several ranks). Rank 0 writes.
#include "mpi_algebra.h"

#include "fiberbridge/fem/dcb_simulation.h"
#include "fiberbridge/result/virtual_dic.h"
#include "fiberbridge/specimen/specimen.h"

#include <deal.II/dofs/dof_handler.h>
#include <deal.II/fe/mapping.h>

#include <array>
#include <string>
#include <vector>

namespace fiberbridge::fem {

/// The FE displacement at fixed reference points, each on a given arm.
template <int dim>
class PointSampler {
public:
  /// `top`: by point, whether it belongs to the upper arm (material id 0). A point on no cell
  /// of its arm is off the body (on_body() false, sampled as 0).
  PointSampler(const dealii::DoFHandler<dim>& dof_handler, const dealii::Mapping<dim>& mapping,
               const std::vector<std::array<double, 2>>& points, const std::vector<char>& top);
  /// u_x and u_y at every point from the ghosted solution.
  void sample(const Vec& u_ghost, std::vector<double>& ux, std::vector<double>& uy) const;
  const std::vector<char>& on_body() const { return on_body_; }

private:
  struct Term {
    dealii::types::global_dof_index dof;
    unsigned component;
    double weight;
  };
  std::vector<std::vector<Term>> terms_;
  std::vector<char> on_body_;
};

/// Records the run's states and writes the virtual test at the end.
template <int dim>
class VirtualTestRecorder {
public:
  /// Throws InputError for 3D or several ranks. Records the unloaded state.
  VirtualTestRecorder(const result::VirtualDicSettings& settings,
                      const specimen::Specimen& specimen, const specimen::Material& material,
                      const dealii::DoFHandler<dim>& dof_handler,
                      const dealii::Mapping<dim>& mapping, MPI_Comm comm);
  /// One equilibrium state: the field, the load [N], the load-point opening [m], the
  /// traction-free crack tip and the cohesive zone's front [m].
  void record(const Vec& u_ghost, double opening, double load, double crack_tip, double zone_front);
  /// Writes <output_dir>/virtual_test (see result::VirtualDicTest::write).
  result::VirtualTestFiles write(const std::string& output_dir) const;

private:
  result::VirtualDicSettings settings_;
  specimen::Specimen specimen_;
  specimen::Material material_;
  result::DicGrid grid_;
  PointSampler<dim> grid_sampler_, root_sampler_;
  result::VirtualDicTest test_;
};

} // namespace fiberbridge::fem
