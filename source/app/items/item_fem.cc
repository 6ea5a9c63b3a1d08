// Scene item "fem": the deal.II DCB model (docs/design.md section 2). Reads the FEM section, runs
// the simulation with the scene's specimen, material, law and J_tip, and reports through the common
// simulation writer.
//
// One engine (docs/design.md section 2): simulate_dcb on all ranks of
// simulation_communicator(): MPI_COMM_WORLD, or MPI_COMM_SELF when the run is one task of several
// spread over the ranks (task_distributor.h). Under mpirun every rank of that communicator runs
// this item (the engine is collective); only its rank 0 prints progress, and the file writers are
// switched off on the ranks that do not write (core/output_guard.h).
#include "fiberbridge/app/scene/models.h"

#ifdef FIBERBRIDGE_HAVE_FEM
#ifdef FIBERBRIDGE_HAVE_IDENTIFY
#include "fiberbridge/app/items/fem_forward_model.h"
#endif
#include "fiberbridge/app/outputs/report_simulation.h"
#include "fiberbridge/app/run/task_distributor.h"
#include "fiberbridge/app/scene/scene_context.h"
#include "fiberbridge/app/scene/scene_reader.h"
#include "fiberbridge/app/scene/section.h"
#include "fiberbridge/core/error.h"
#include "fiberbridge/core/units.h"
#include "fiberbridge/fem/dcb_simulation.h"
#include "fiberbridge/fem/distributed_dcb.h"
#include "fiberbridge/fem/input_check.h"

#include <deal.II/base/mpi.h>
#include <deal.II/base/parameter_handler.h>

#include <filesystem>
#endif

namespace fiberbridge::app {

#ifdef FIBERBRIDGE_HAVE_FEM
namespace {

/// The FEM section, with FEM/Mesh file resolved against the scene's folder (a scene and the
/// specimen mesh it names travel together, as mesh/ and prm/ do).
fem::FemParameters fem_parameters(const SceneContext& ctx) {
  auto params = ctx.parameters().section<fem::FemParameters>("FEM");
  if (!params.mesh.file.empty()) {
    const std::string path = resolve_scene_path(params.mesh.file, ctx.scene_file);
    if (!std::filesystem::is_regular_file(path))
      throw InputError(ctx.scene_file + ": FEM/Mesh file: file '" + params.mesh.file +
                       "' not found (looked for " + path + ")");
    params.mesh.file = path;
  }
  return params;
}

} // namespace

static void declare_fem_section(dealii::ParameterHandler& prm) {
  declare_section<fem::FemParameters>(prm, "FEM");
}

static void parse_fem_section(dealii::ParameterHandler& prm, SceneParameters& out) {
  parse_into<fem::FemParameters>(prm, "FEM", out);
}

static void check_fem_item(SceneContext& ctx) {
  const auto params = fem_parameters(ctx);
  if (ctx.specimen_from_section())
    fem::check_dcb_inputs(ctx.specimen(), ctx.material(), params);
}

static result::SimulationResult simulate_fem_law(const SceneContext& ctx,
                                                 const law::TractionLaw& law, double j_tip,
                                                 const ProgressLines& progress) {
  auto params = fem_parameters(ctx);
  // No files: a virtual DIC test writes only for the scene's own FEM run.
  params.virtual_dic.settings.enabled = false;
  return fem::simulate_dcb(ctx.specimen(), ctx.material(), law, j_tip, params, "", progress,
                           MPI_COMM_SELF);
}

#ifdef FIBERBRIDGE_HAVE_IDENTIFY
static identify::ForwardModel identify_forward_fem(const SceneContext& ctx) {
  return fem_forward_model(fem_parameters(ctx));
}
#endif

static ItemOutcome run_fem_item(const SceneContext& ctx) {
  const auto params = fem_parameters(ctx);
  const MPI_Comm comm = simulation_communicator();
  const unsigned n_ranks = dealii::Utilities::MPI::n_mpi_processes(comm);
  const bool rank0 = dealii::Utilities::MPI::this_mpi_process(comm) == 0;
  std::function<void(const std::string&)> progress;
  if (rank0)
    progress = [&ctx](const std::string& line) { ctx.progress(line); };
  fem::DistributedRunInfo info;
  result::SimulationResult result =
      fem::simulate_dcb(ctx.specimen(), ctx.material(), *ctx.law(), ctx.j_tip(), params,
                        ctx.output_dir, progress, comm, &info);
  ItemOutcome outcome = report_simulation(ctx, std::move(result), "n_dofs");
  auto& block = outcome.report["fem"];
  // summary.json keeps the keys of the time there were two engines: "engine" is "distributed",
  // the name the one engine had then (FEM/Engine is deprecated, parameters.cc).
  block["engine"] = "distributed";
  block["n_ranks"] = n_ranks;
  block["dimension"] = params.mesh.dimension;
  block["n_cells"] = info.n_cells;
  block["peak_memory_MB_all_ranks"] = info.peak_memory_MB_sum;
  block["peak_memory_MB_max_rank"] = info.peak_memory_MB_max;
  block["memory_MB_per_million_dofs"] =
      info.n_dofs > 0 ? info.peak_memory_MB_sum / (double(info.n_dofs) / 1e6) : 0.0;
  block["time_breakdown_s"] = {{"setup", info.t_setup},         {"assembly", info.t_assemble},
                               {"factorize", info.t_factorize}, {"solve", info.t_solve},
                               {"J_integrals", info.t_j},       {"output", info.t_output}};
  // The mesh and why (issue 34 item 1): FEM/Element size given, or chosen by auto from the
  // specimen and the law (fem/auto_mesh.h). layers_per_arm 0: a FEM/Mesh file decides.
  block["mesh"] = {{"element_size_mm", info.element_size / units::mm},
                   {"layers_per_arm", info.mesh.layers_per_arm},
                   {"automatic", info.mesh.automatic},
                   {"zone_estimate_mm", info.mesh.zone_estimate / units::mm},
                   {"reason", info.mesh.reason}};
  block["factorizations"] = info.n_factorizations;
  block["newton_iterations"] = info.n_newton;
  return outcome;
}

/// A FEM that is one big run over all ranks by request: 3D, or the distributed engine chosen.
static bool fem_needs_all_ranks(const SceneParameters& p) {
  // FEM/Engine is deprecated and kept only in the parse's notes: its value as set.
  return p.section<fem::FemParameters>("FEM").mesh.dimension == 3 ||
         p.entry("FEM/Engine") == "distributed";
}
#endif // FIBERBRIDGE_HAVE_FEM

/// The model's registry entry (items/models.cc): what every build knows of it, and, when its
/// library is built, what it does.
SimulationModel fem_model() {
  SimulationModel m;
  m.name = "fem";
  m.section = "FEM";
  m.cost = 10.0; // relative to the beam's 1: the 2D FEM's 0.18 s on the seed (models.h)
  m.uses_all_ranks = true;
  m.finite_elements = true;
  m.ladder_doc = "As Beam ladder, keys of the FEM section.";
#ifdef FIBERBRIDGE_HAVE_FEM
  m.built = true;
  m.declare = &declare_fem_section;
  m.parse = &parse_fem_section;
  m.check = &check_fem_item;
  m.run = &run_fem_item;
  m.needs_all_ranks = &fem_needs_all_ranks;
  m.simulate = &simulate_fem_law;
#ifdef FIBERBRIDGE_HAVE_IDENTIFY
  m.identify_forward = &identify_forward_fem;
#endif
#endif
  return m;
}

} // namespace fiberbridge::app
