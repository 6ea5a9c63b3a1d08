#pragma once
// The campaign's laws back in the specimen (issue 33 item 5, the paper's Fig. 10): each group's
// trilinear law and J_tip simulated on the group's specimen (the manifest rows' geometry where
// they give it, else the scene's Specimen; campaign_group_specimen) and the Material by a model
// chosen by key, the simulated R(delta_root) against the group's measured curve and its scatter,
// and the misfit. Any built model with a `simulate` entry in the registry (models.h): the FEM by
// default (auto), the beam or the MPM by name.
#include "fiberbridge/analysis/campaign_run.h"
#include "fiberbridge/app/scene_context.h"
#include "fiberbridge/specimen/specimen.h"

#include <string>
#include <vector>

namespace fiberbridge::app {

struct GroupSimulation {
  std::string material, model;
  double cycles = 0;
  bool ran = false;
  std::string failure;
  std::vector<double> delta_root, R; ///< simulated, R_energy (R_J where absent) [m], [J/m^2]
  double G_ss = NAN;                 ///< simulated plateau [J/m^2]
  /// RMS of simulated minus measured R over the measured delta range (up to the simulation's
  /// last delta_root), relative to the group's G_B = G_ss - J_tip.
  double misfit_rel = NAN;
  /// Fraction of those points where the simulation lies within 2 standard deviations of the
  /// measured replicates (the specimens' scatter).
  double within_scatter = NAN;
  double wall_time_s = NAN;
  specimen::Specimen specimen; ///< the geometry simulated (campaign_group_specimen)
  std::string geometry_note;   ///< non-empty when the group's rows differ in geometry
  double a_start = NAN;        ///< the simulation's first crack length [m] (its a0)
};

/// The specimen a group's law is simulated on: the scene's Specimen with each member's manifest
/// geometry (width_mm, arm_thickness_mm, a0_mm, length_mm) where its row gives it. When every
/// member comes to the same geometry, that one; when they differ, the median of each dimension
/// over the members (one simulation per group: the misfit is against the group's averaged
/// curve) and `note` says so with the ranges.
specimen::Specimen campaign_group_specimen(const specimen::Specimen& scene,
                                           const analysis::CampaignGroup& group,
                                           const std::vector<analysis::CampaignSpecimen>& specimens,
                                           std::string& note);

/// The models this build can put the laws back into, the FEM first (auto takes the first);
/// empty: none.
std::vector<std::string> campaign_simulation_models();

/// Every group with a law, simulated by `model` on its specimen (campaign_group_specimen), ctx's
/// Material and the model's section. Groups are independent; on N ranks they run as tasks
/// (task_distributor.h). With ctx.resume, a group simulated by an earlier run into the same
/// output directory is restored (campaign_resume.h); each is kept as it finishes.
std::vector<GroupSimulation> simulate_campaign_laws(SceneContext& ctx,
                                                    const analysis::CampaignResult& r,
                                                    const std::string& model);

/// Writes campaign_fig10_<material>_c<cycles>.csv per simulated group and a PNG per material
/// (every cycle count: measured with +-2 std, simulated); returns the PNGs made.
std::vector<std::string> write_campaign_simulation_files(const analysis::CampaignResult& r,
                                                         const std::vector<GroupSimulation>& sims,
                                                         const std::string& out_dir);
/// campaign.groups[i].simulation in the summary (after write_campaign_outputs made the block).
void add_campaign_simulation_summary(const analysis::CampaignResult& r,
                                     const std::vector<GroupSimulation>& sims, Json& summary);

} // namespace fiberbridge::app
