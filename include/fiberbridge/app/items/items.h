#pragma once
// Scene items: each declares its section and runs. The declare_*_section functions enter the
// registry (items/scene_items.cc); each declares a step-44 section struct (section.h). The
// simulation models define their registry entries in their own item files (item_fem.cc,
// item_mpm.cc, item_beam.cc; scene/models.h), identify in item_identify.h.
#include "fiberbridge/analysis/campaign_run.h"
#include "fiberbridge/app/scene/models.h"
#include "fiberbridge/app/scene/scene_context.h"

namespace fiberbridge::app {

void declare_data_section(dealii::ParameterHandler& prm);
void declare_fit_section(dealii::ParameterHandler& prm);
void declare_rank_section(dealii::ParameterHandler& prm);
void declare_bridging_section(dealii::ParameterHandler& prm);

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
ItemOutcome run_extract_item(const SceneContext& ctx);
void check_fit_item(SceneContext& ctx);
ItemOutcome run_fit_item(const SceneContext& ctx);
void check_rank_item(SceneContext& ctx);
ItemOutcome run_rank_item(const SceneContext& ctx);
void check_bridging_item(SceneContext& ctx);
ItemOutcome run_bridging_item(const SceneContext& ctx);
void declare_campaign_section(dealii::ParameterHandler& prm);
void check_campaign_item(SceneContext& ctx);
ItemOutcome run_campaign_item(const SceneContext& ctx);
/// The Campaign section's campaign analysed on this process, writing nothing and resuming nothing
/// (the Python module's campaign; the item spreads the groups over ranks and keeps them for
/// --resume, with the same numbers).
analysis::CampaignResult analyse_scene_campaign(const SceneContext& ctx);
void declare_compare_section(dealii::ParameterHandler& prm);
void check_compare_item(SceneContext& ctx);
ItemOutcome run_compare_item(const SceneContext& ctx);
void declare_study_section(dealii::ParameterHandler& prm);
void check_study_item(SceneContext& ctx);
ItemOutcome run_study_item(const SceneContext& ctx);
void declare_dic_section(dealii::ParameterHandler& prm);
void check_dic_item(SceneContext& ctx);
ItemOutcome run_dic_item(const SceneContext& ctx);
void declare_test_section(dealii::ParameterHandler& prm);
void check_reduce_item(SceneContext& ctx);
ItemOutcome run_reduce_item(const SceneContext& ctx);

} // namespace fiberbridge::app
