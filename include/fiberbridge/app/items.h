#pragma once
// Scene items: each declares its section and runs. The declare_*_section functions enter the
// registry (scene.cc); each declares a step-44 section struct (section.h). The simulation items
// live beside their libraries' owners (item_fem.cc, item_mpm.cc, item_beam.cc).
#include "fiberbridge/app/models.h"
#include "fiberbridge/app/scene_context.h"
#ifdef FIBERBRIDGE_HAVE_BEAM
#include "fiberbridge/beam/dcb_beam.h"
#endif
#ifdef FIBERBRIDGE_HAVE_MPM
#include "fiberbridge/mpm/parameters.h"
#endif

namespace fiberbridge::app {

void declare_data_section(dealii::ParameterHandler& prm);
void declare_fit_section(dealii::ParameterHandler& prm);
void declare_rank_section(dealii::ParameterHandler& prm);
void declare_bridging_section(dealii::ParameterHandler& prm);
void declare_law_section(dealii::ParameterHandler& prm);
void declare_specimen_sections(dealii::ParameterHandler& prm);
/// Cohesive law, Specimen and Material parsed into the scene's parameters (SceneParameters::law,
/// specimen, material).
void parse_shared_sections(dealii::ParameterHandler& prm, SceneParameters& out);

// parse_*: the item's sections parsed once when the scene is read (SceneItem::parse).
void parse_data_section(dealii::ParameterHandler& prm, SceneParameters& out);
void parse_fit_section(dealii::ParameterHandler& prm, SceneParameters& out);
void parse_rank_section(dealii::ParameterHandler& prm, SceneParameters& out);
void parse_bridging_section(dealii::ParameterHandler& prm, SceneParameters& out);
void parse_campaign_section(dealii::ParameterHandler& prm, SceneParameters& out);
void parse_compare_section(dealii::ParameterHandler& prm, SceneParameters& out);
void parse_study_section(dealii::ParameterHandler& prm, SceneParameters& out);
void parse_dic_section(dealii::ParameterHandler& prm, SceneParameters& out);
void parse_test_section(dealii::ParameterHandler& prm, SceneParameters& out);

// check_*: the item's sections read and validated before the first item runs (SceneItem::check).
void check_extract_item(SceneContext& ctx);
void run_extract_item(SceneContext& ctx);
void check_fit_item(SceneContext& ctx);
void run_fit_item(SceneContext& ctx);
void check_rank_item(SceneContext& ctx);
void run_rank_item(SceneContext& ctx);
void check_bridging_item(SceneContext& ctx);
void run_bridging_item(SceneContext& ctx);
void declare_campaign_section(dealii::ParameterHandler& prm);
void check_campaign_item(SceneContext& ctx);
void run_campaign_item(SceneContext& ctx);
void declare_compare_section(dealii::ParameterHandler& prm);
void check_compare_item(SceneContext& ctx);
void run_compare_item(SceneContext& ctx);
void declare_study_section(dealii::ParameterHandler& prm);
void check_study_item(SceneContext& ctx);
void run_study_item(SceneContext& ctx);
void declare_dic_section(dealii::ParameterHandler& prm);
void check_dic_item(SceneContext& ctx);
void run_dic_item(SceneContext& ctx);
void declare_test_section(dealii::ParameterHandler& prm);
void check_reduce_item(SceneContext& ctx);
void run_reduce_item(SceneContext& ctx);

#ifdef FIBERBRIDGE_HAVE_IDENTIFY
void declare_identify_section(dealii::ParameterHandler& prm);
void parse_identify_section(dealii::ParameterHandler& prm, SceneParameters& out);
void check_identify_item(SceneContext& ctx);
void run_identify_item(SceneContext& ctx);
/// For compare: the identified law's simulations against the first record (identify_check).
void check_identified_against_simulations(SceneContext& ctx);
/// After extract, when identify ran in the same scene (records with delta_root): the three
/// routes to the law side by side (law_routes.csv, summary block law_routes, law_routes.png).
void report_law_routes(SceneContext& ctx);
#endif
#ifdef FIBERBRIDGE_HAVE_BEAM
void declare_beam_section(dealii::ParameterHandler& prm);
void parse_beam_section(dealii::ParameterHandler& prm, SceneParameters& out);
/// The Beam section read and validated, with the notes on deprecated keys it met (the item reads it
/// so; tests/app/section_tests.cc).
beam::BeamParameters read_beam_section(dealii::ParameterHandler& prm);
void check_beam_item(SceneContext& ctx);
void run_beam_item(SceneContext& ctx);
/// The beam with this law and J_tip on ctx's specimen set-up and Beam section (models.h).
result::SimulationResult simulate_beam_law(SceneContext& ctx, const law::TractionLaw& law,
                                           double j_tip);
#endif
#ifdef FIBERBRIDGE_HAVE_FEM
void declare_fem_section(dealii::ParameterHandler& prm);
void parse_fem_section(dealii::ParameterHandler& prm, SceneParameters& out);
void check_fem_item(SceneContext& ctx);
void run_fem_item(SceneContext& ctx);
/// The FEM with this law and J_tip on ctx's specimen set-up and FEM section, on this rank alone
/// (MPI_COMM_SELF), no files (models.h).
result::SimulationResult simulate_fem_law(SceneContext& ctx, const law::TractionLaw& law,
                                          double j_tip);
#ifdef FIBERBRIDGE_HAVE_IDENTIFY
/// The FEM section as identify's forward model (models.h, app/fem_forward_model.h).
identify::ForwardModel identify_forward_fem(SceneContext& ctx);
#endif
#endif
#ifdef FIBERBRIDGE_HAVE_MPM
void declare_mpm_section(dealii::ParameterHandler& prm);
void parse_mpm_section(dealii::ParameterHandler& prm, SceneParameters& out);
/// The MPM section read and validated, with the notes on deprecated keys it met.
mpm::MpmParameters read_mpm_section(dealii::ParameterHandler& prm);
void check_mpm_item(SceneContext& ctx);
void run_mpm_item(SceneContext& ctx);
/// The MPM with this law and J_tip on ctx's specimen set-up and MPM section, no files (models.h).
result::SimulationResult simulate_mpm_law(SceneContext& ctx, const law::TractionLaw& law,
                                          double j_tip);
#endif

} // namespace fiberbridge::app
