#pragma once
// The fit corrected by simulation (identify/chain_correction.h) as a step of the scene's `fit`:
// the chain that measured the records, run again on records the beam simulates.
#include "fiberbridge/analysis/campaign.h"
#include "fiberbridge/analysis/law_extraction.h"
#include "fiberbridge/app/scene/scene_context.h"
#include "fiberbridge/identify/chain_correction.h"

namespace fiberbridge::app {

/// The scene's own reduce, extract and fit (the Test, Specimen, Data and Fit sections), with
/// `extraction` and `fit` what they gave on the records, repeated on simulated records until the
/// chain gives back the same (the beam with the scene's Beam section as forward model). Needs
/// the records reduce handed on (ctx.reduced).
identify::ChainCorrection correct_fit_by_simulation(const SceneContext& ctx,
                                                    const analysis::ExtractionOutcome& extraction,
                                                    const analysis::FitOptions& fit_options,
                                                    const analysis::TrilinearFit& fit,
                                                    const identify::ChainCorrectionSettings& s);

/// Fit/Model correction for a campaign's groups (analysis::CampaignOptions::correct_law): the
/// group's own chain (estimate_group on the members' simulated records, each reduced as its row
/// was) with `options` (whose correct_law is not used), the scene's Beam section and Material.
/// Empty when the scene asks for none (or the build has no identify); `where` names the keys.
std::function<analysis::LawCorrection(const std::vector<const analysis::CampaignSpecimen*>&,
                                      const law::TrilinearParameters&, double)>
group_law_correction(const SceneContext& ctx, const analysis::CampaignOptions& options);

/// The simulated test of the correction: the beam with the scene's Beam section, or, for
/// Fit/Model correction = fem, the FEM with its FEM section (it holds the specimen's far end,
/// which the beam does not: docs/design.md, "The fit corrected by simulation"). `auto` takes
/// the FEM, when built, for records whose R falls at the end (`end_effect`,
/// analysis::SteadyState), else the beam. Throws InputError for fem in a build without the FEM.
identify::ForwardModel correction_forward_model(const SceneContext& ctx, bool end_effect = false);

/// The scene's Fit/Model correction keys: the mode ("auto", "none", "beam", "fem") and the
/// settings.
std::string fit_correction_mode(const SceneContext& ctx);
identify::ChainCorrectionSettings fit_correction_settings(const SceneContext& ctx);

} // namespace fiberbridge::app
