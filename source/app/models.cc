// The registry of simulation models (models.h): the one place that lists them.
#include "fiberbridge/app/models.h"

#include "fiberbridge/app/items.h"
#ifdef FIBERBRIDGE_HAVE_FEM
#include "fiberbridge/fem/dcb_simulation.h"
#endif

#include <algorithm>

namespace fiberbridge::app {

namespace {

#ifdef FIBERBRIDGE_HAVE_FEM
/// A FEM that is one big run over all ranks by request: 3D, or the distributed engine chosen.
bool fem_needs_all_ranks(const SceneParameters& p) {
  // FEM/Engine is deprecated and kept only in the parse's notes: its value as set.
  return p.section<fem::FemParameters>("FEM").mesh.dimension == 3 ||
         p.entry("FEM/Engine") == "distributed";
}
#endif

} // namespace

const std::vector<SimulationModel>& simulation_models(){
    static const std::vector<SimulationModel> models = {
        {"fem", "FEM",
#ifdef FIBERBRIDGE_HAVE_FEM
         true, &declare_fem_section, &parse_fem_section, &check_fem_item, &run_fem_item, 10.0, true,
         &fem_needs_all_ranks,
#else
         false, nullptr, nullptr, nullptr, nullptr, 10.0, true, nullptr,
#endif
         "", "As Beam ladder, keys of the FEM section.", "Target error",
#ifdef FIBERBRIDGE_HAVE_FEM
         &simulate_fem_law,
#else
         nullptr,
#endif
#if defined(FIBERBRIDGE_HAVE_FEM) && defined(FIBERBRIDGE_HAVE_IDENTIFY)
         &identify_forward_fem},
#else
         nullptr},
#endif
        {"mpm", "MPM",
#ifdef FIBERBRIDGE_HAVE_MPM
         true, &declare_mpm_section, &parse_mpm_section, &check_mpm_item, &run_mpm_item,
#else
         false, nullptr, nullptr, nullptr, nullptr,
#endif
         100.0, false, nullptr, "", "As Beam ladder, keys of the MPM section.", "MPM target error",
#ifdef FIBERBRIDGE_HAVE_MPM
         &simulate_mpm_law, nullptr},
#else
         nullptr, nullptr},
#endif
        {"beam", "Beam",
#ifdef FIBERBRIDGE_HAVE_BEAM
         true, &declare_beam_section, &parse_beam_section, &check_beam_item, &run_beam_item,
#else
         false, nullptr, nullptr, nullptr, nullptr,
#endif
         1.0, false, nullptr, "Number of elements = 50, 100, 200, 400",
         "'Key = v1, v2, ...' (keys of the Beam section; several keys separated by ';' vary "
         "together).",
         "Target error",
#ifdef FIBERBRIDGE_HAVE_BEAM
         &simulate_beam_law, nullptr},
#else
         nullptr, nullptr},
#endif
    };
return models;
} // namespace fiberbridge::app

std::vector<const SimulationModel*> built_models() {
  std::vector<const SimulationModel*> out;
  for (const auto& m : simulation_models())
    if (m.built)
      out.push_back(&m);
  std::stable_sort(out.begin(), out.end(), [](const SimulationModel* a, const SimulationModel* b) {
    return a->cost < b->cost;
  });
  return out;
}

const SimulationModel* find_model(const std::string& name) {
  for (const auto& m : simulation_models())
    if (name == m.name)
      return &m;
  return nullptr;
}

const SimulationModel* built_model(const std::string& name) {
  const SimulationModel* m = find_model(name);
  return m && m->built ? m : nullptr;
}

std::string model_names() {
  std::string names;
  for (const auto& m : simulation_models())
    names += (names.empty() ? "" : ", ") + std::string(m.name);
  return names;
}

} // namespace fiberbridge::app
