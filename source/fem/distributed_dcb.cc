// The entry points of the FEM engine and its dimension dispatch (light translation unit; the
// engine itself is DcbModel<dim>, dcb_model.h, instantiated in dcb_model_2d.cc and
// dcb_model_3d.cc). One engine (docs/design.md section 2): on one rank (MPI_COMM_SELF) it is the
// serial program, as in deal.II's step-40.
#include "fiberbridge/fem/distributed_dcb.h"

#include "fiberbridge/core/error.h"
#include "fiberbridge/core/units.h"
#include "fiberbridge/fem/auto_mesh.h"
#include "fiberbridge/fem/dcb_common.h"
#include "fiberbridge/result/numerical_fault.h"

namespace fiberbridge::fem {

template <int dim>
result::SimulationResult run_dcb_model(const specimen::Specimen&, const specimen::Material&,
                                       const law::TractionLaw&, double, const FemParameters&,
                                       const std::string&,
                                       const std::function<void(const std::string&)>&, MPI_Comm,
                                       DistributedRunInfo&, FemRunDetails&);

result::SimulationResult
simulate_dcb(const specimen::Specimen& specimen, const specimen::Material& material,
             const law::TractionLaw& law, double j_tip, const FemParameters& parameters,
             const std::string& output_dir, const std::function<void(const std::string&)>& progress,
             MPI_Comm comm, DistributedRunInfo* info, FemRunDetails* details) {
  fiberbridge::begin_fault_context("fem");
  DistributedRunInfo local_info;
  FemRunDetails local_details;
  DistributedRunInfo& i = info ? *info : local_info;
  FemRunDetails& d = details ? *details : local_details;
  // FEM/Element size = auto is resolved here, before the mesh is built (issue 34): the engine
  // only ever sees a number. Plain arithmetic on the scene's values: every rank chooses the same.
  const MeshChoice mesh = choose_mesh(specimen, material, law, j_tip, parameters);
  const FemParameters resolved = with_mesh(parameters, mesh);
  result::SimulationResult r;
  if (parameters.mesh.dimension == 3)
    r = run_dcb_model<3>(specimen, material, law, j_tip, resolved, output_dir, progress, comm, i,
                         d);
  else if (parameters.mesh.dimension == 2)
    r = run_dcb_model<2>(specimen, material, law, j_tip, resolved, output_dir, progress, comm, i,
                         d);
  else
    throw InputError("FEM/Dimension: must be 2 or 3");
  i.mesh = mesh;
  i.element_size = crack_plane_step(specimen, resolved); // the step the mesh was built with
  r.method.push_back("mesh: " + fmt(i.element_size / units::mm, 4) + " mm crack-plane elements" +
                     (mesh.layers_per_arm > 0
                          ? ", " + std::to_string(mesh.layers_per_arm) + " layers per arm"
                          : std::string(" (FEM/Mesh file)")) +
                     "; " + mesh.reason);
  return r;
}

result::SimulationResult simulate_dcb(const specimen::Specimen& specimen,
                                      const specimen::Material& material,
                                      const law::TractionLaw& law, double j_tip,
                                      const FemParameters& parameters,
                                      const std::string& output_dir,
                                      const std::function<void(const std::string&)>& progress) {
  return simulate_dcb(specimen, material, law, j_tip, parameters, output_dir, progress,
                      MPI_COMM_SELF);
}

result::SimulationResult
simulate_dcb(const specimen::Specimen& specimen, const specimen::Material& material,
             const law::TractionLaw& law, double j_tip, const FemParameters& parameters,
             const std::string& output_dir, const std::function<void(const std::string&)>& progress,
             FemRunDetails& details) {
  return simulate_dcb(specimen, material, law, j_tip, parameters, output_dir, progress,
                      MPI_COMM_SELF, nullptr, &details);
}

} // namespace fiberbridge::fem
