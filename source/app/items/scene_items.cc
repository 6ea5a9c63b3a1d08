// The registry of scene items (scene_context.h, scene_items()): every item the project has, in
// the order a scene runs them. It lives with the items because it names them; the reader and the
// runner below ask it through scene_items() and never include an item.
#include "items/chain_study_item.h"

#include "fiberbridge/app/items/analysis_steps.h"
#include "fiberbridge/app/items/item_identify.h"
#include "fiberbridge/app/items/items.h"
#include "fiberbridge/app/scene/models.h"
#include "fiberbridge/app/scene/scene_context.h"

namespace fiberbridge::app {

const std::vector<SceneItem>& scene_items() {
  // Order = execution order: analysis first (fit hands its law on), then the simulations
  // (models.h, cheapest first), then the items that compare them.
  static const std::vector<SceneItem> items = [] {
    std::vector<SceneItem> v = {
        {"dic", &declare_dic_section, &parse_dic_section, &check_dic_item, &run_dic_item},
        {"reduce", &declare_test_section, &parse_test_section, &check_reduce_item,
         &run_reduce_item},
#ifdef FIBERBRIDGE_HAVE_IDENTIFY
        {"identify", &declare_identify_section, &parse_identify_section, &check_identify_item,
         &run_identify_item},
#endif
        {"extract", &declare_data_section, &parse_data_section, &check_extract_item,
         &run_extract_item},
        {"fit", &declare_fit_section, &parse_fit_section, &check_fit_item, &run_fit_item},
        {"rank", &declare_rank_section, &parse_rank_section, &check_rank_item, &run_rank_item},
        {"bridging", &declare_bridging_section, &parse_bridging_section, &check_bridging_item,
         &run_bridging_item},
        {"campaign", &declare_campaign_section, &parse_campaign_section, &check_campaign_item,
         &run_campaign_item},
    };
    for (const SimulationModel* m : built_models())
      v.push_back(m->item());
    v.insert(v.end(), {
                          {"compare", &declare_compare_section, &parse_compare_section,
                           &check_compare_item, &run_compare_item},
                          {"study", &declare_study_section, &parse_study_section, &check_study_item,
                           &run_study_item},
                          {"chain study", &declare_chain_study_section, &parse_chain_study_section,
                           &check_chain_study_item, &run_chain_study_item},
                          {"programme study", &declare_programme_study_section,
                           &parse_programme_study_section, &check_programme_study_item,
                           &run_programme_study_item},
                      });
    return v;
  }();
  return items;
}

} // namespace fiberbridge::app
