// Scene item "fem": the deal.II DCB model (DESIGN.md section 2). Reads the FEM section, runs the
// simulation with the scene's specimen, material, law and J_tip, and reports through the common
// simulation writer.
#include "fiberbridge/app/scene_context.h"
#include "fiberbridge/fem/dcb_simulation.h"

#include <deal.II/base/parameter_handler.h>

#include <iostream>

namespace fiberbridge::app {

void declare_fem_section(dealii::ParameterHandler& prm) {
  prm.enter_subsection("FEM");
  fem::FemParameters::declare_parameters(prm);
  prm.leave_subsection();
}

void run_fem_item(SceneContext& ctx) {
  fem::FemParameters params;
  ctx.prm->enter_subsection("FEM");
  params.parse_parameters(*ctx.prm);
  ctx.prm->leave_subsection();
  auto result =
      fem::simulate_dcb(ctx.specimen(), ctx.material(), *ctx.law(), ctx.j_tip(), params,
                        ctx.output_dir, [](const std::string& line) { std::cerr << line << '\n'; });
  report_simulation(ctx, std::move(result), "n_dofs");
}

} // namespace fiberbridge::app
