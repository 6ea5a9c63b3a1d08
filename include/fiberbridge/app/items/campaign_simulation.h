#pragma once
// The campaign's laws back in the specimen (issue 33 item 5, the paper's Fig. 10): each group's
// trilinear law and J_tip simulated on the group's specimen (the manifest rows' geometry where
// they give it, else the scene's Specimen; campaign_group_specimen) and the Material by a model
// chosen by key, the simulated R(delta_root) against the group's measured curve and its scatter,
// and the misfit. Any built model with a `simulate` entry in the registry (models.h): the FEM by
// default (auto), the beam or the MPM by name.
#include "fiberbridge/analysis/campaign_run.h"
#include "fiberbridge/app/scene/scene_context.h"
#include "fiberbridge/app/scene/step_outcomes.h"
#include "fiberbridge/specimen/specimen.h"

#include <string>
#include <vector>

namespace fiberbridge::app {

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
std::vector<GroupSimulation> simulate_campaign_laws(const SceneContext& ctx,
                                                    const analysis::CampaignResult& r,
                                                    const std::string& model);

} // namespace fiberbridge::app
