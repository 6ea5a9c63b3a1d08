#pragma once
// `chain study` (item_chain_study.cc): virtual tests through the measuring chain (issue 39 item 1).
// Declared apart from items.h so that registering it (items/scene_items.cc) touches no other item.
#include "fiberbridge/app/scene/scene_context.h"

namespace fiberbridge::app {

void declare_chain_study_section(dealii::ParameterHandler& prm);
void parse_chain_study_section(dealii::ParameterHandler& prm, SceneParameters& out);
void check_chain_study_item(SceneContext& ctx);
ItemOutcome run_chain_study_item(const SceneContext& ctx);

} // namespace fiberbridge::app

namespace fiberbridge::app {

/// `programme study` (item_programme_study.cc): the seed's programme of 20 groups simulated as DIC
/// sets through the campaign (issue 39 item 5).
void declare_programme_study_section(dealii::ParameterHandler& prm);
void parse_programme_study_section(dealii::ParameterHandler& prm, SceneParameters& out);
void check_programme_study_item(SceneContext& ctx);
ItemOutcome run_programme_study_item(const SceneContext& ctx);

} // namespace fiberbridge::app
