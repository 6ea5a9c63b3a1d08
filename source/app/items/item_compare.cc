// Scene item `compare`: the simulations that ran, on shared axes, with pairwise differences, and
// the closed loop through the extraction method (what the paper's method recovers on its own
// specimen).
#include "fiberbridge/analysis/model_comparison.h"
#include "fiberbridge/app/items/item_identify.h"
#include "fiberbridge/app/items/items.h"
#include "fiberbridge/app/outputs/compare_writers.h"
#include "fiberbridge/app/scene/models.h"
#include "fiberbridge/app/scene/section.h"
#include "fiberbridge/core/csv.h"
#include "fiberbridge/core/error.h"
#include "fiberbridge/core/plot.h"
#include "fiberbridge/core/units.h"

#include <deal.II/base/patterns.h>

#include <algorithm>
#include <iostream>

namespace fiberbridge::app {

namespace {

/// Compare: the closed loop through the extraction method and its n, k.
struct CompareSection {
  bool closed_loop = true;
  int intervals = 40, half_width = 2;

  static void declare_parameters(dealii::ParameterHandler& prm) {
    prm.declare_entry("Closed loop", "true", dealii::Patterns::Bool(),
                      "Extract laws (Eq. 6 and dR/ddelta) back from each simulated "
                      "R(delta_root) and compare them with the input law.");
    prm.declare_entry("Intervals", "40", dealii::Patterns::Integer(4),
                      "n of Eq. 6 for the closed loop (the simulated R curve has one point per "
                      "tip advance, so n must stay below the number of advances in the zone).");
    prm.declare_entry("Smoothing half-width", "2", dealii::Patterns::Integer(1),
                      "k of the slope fits for the closed loop.");
  }
  void parse_parameters(dealii::ParameterHandler& prm) {
    closed_loop = prm.get_bool("Closed loop");
    intervals = prm.get_integer("Intervals");
    half_width = prm.get_integer("Smoothing half-width");
  }
};

} // namespace

void declare_compare_section(dealii::ParameterHandler& prm) {
  declare_section<CompareSection>(prm, "Compare");
}

void parse_compare_section(dealii::ParameterHandler& prm, SceneParameters& out) {
  parse_into<CompareSection>(prm, "Compare", out);
}

void check_compare_item(SceneContext& ctx) {
  ctx.parameters().section<CompareSection>("Compare");
  const auto models = built_models();
  if (std::none_of(models.begin(), models.end(),
                   [&](const SimulationModel* m) { return ctx.run_items.count(m->name); }))
    throw InputError("Run: 'compare' needs at least one simulation (" + model_names() +
                     ") in the same scene");
  ctx.law_known_before_run();
}

ItemOutcome run_compare_item(const SceneContext& ctx) {
  ItemOutcome out;
  if (ctx.results.empty())
    throw InputError("Run: 'compare' needs at least one simulation (" + model_names() +
                     ") in the same scene");
  const auto& o = ctx.parameters().section<CompareSection>("Compare");
  const auto law = ctx.law();
  const double j_tip = ctx.j_tip();
#ifdef FIBERBRIDGE_HAVE_IDENTIFY
  if (ctx.identification)
    check_identified_against_simulations(ctx, out.report);
#endif

  std::vector<const result::SimulationResult*> models;
  for (const auto& [name, r] : ctx.results)
    models.push_back(&r);
  const analysis::ModelComparison c =
      analysis::compare_simulations(models, *law, j_tip, o.closed_loop, o.intervals, o.half_width);
  write_comparison(c, models, *law, j_tip, ctx.output_dir, out.report);
  return out;
}

} // namespace fiberbridge::app
