#pragma once
// Scene item "identify" (items/item_identify.cc), compiled when the identify library is built
// (FIBERBRIDGE_HAVE_IDENTIFY): its entry in the item registry, and what compare and extract ask of
// it when it ran in the same scene.
#include "fiberbridge/app/scene/scene_context.h"

#include <functional>
#include <memory>
#include <string>
#include <vector>

namespace dealii {
class ParameterHandler;
}

namespace fiberbridge::app {

void declare_identify_section(dealii::ParameterHandler& prm);
void parse_identify_section(dealii::ParameterHandler& prm, SceneParameters& out);
void check_identify_item(SceneContext& ctx);
ItemOutcome run_identify_item(const SceneContext& ctx);
/// identify's joint fit of the scene's records (Test/Files, read as the item reads them) with the
/// Identify section and its forward model, on this process, writing and keeping nothing: the
/// Python module's fiberbridge.identify. `progress` gets the fit's progress lines and may throw
/// to stop it. The records are returned in `records`.
identify::Identification
identify_scene_records(const SceneContext& ctx,
                       const std::function<void(const std::string&)>& progress,
                       std::shared_ptr<const std::vector<analysis::TestRecord>>& records);
/// For compare: the identified law's simulations against the first record (identify_check),
/// added to compare's report.
void check_identified_against_simulations(const SceneContext& ctx, ItemReport& report);
/// After extract, when identify ran in the same scene (records with delta_root): the three
/// routes to the law side by side (law_routes.csv, summary block law_routes, law_routes.png),
/// added to extract's report.
void report_law_routes(const ExtractionOutcome& e, const identify::Identification& id,
                       const std::string& out_dir, ItemReport& report);

} // namespace fiberbridge::app
