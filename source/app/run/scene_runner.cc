// Running a scene: the scene read, every listed item's sections checked before anything is
// written, then the items run in the registry's order (scene_context.h, scene_items()), with
// --resume and the MPI task hand-out, and the run's summary and report written last.
#include "fiberbridge/app/run/scene_runner.h"

#include "fiberbridge/app/outputs/run_directory.h"
#include "fiberbridge/app/outputs/text_report.h"
#include "fiberbridge/app/run/resume_store.h"
#include "fiberbridge/app/run/simulation_tasks.h"
#include "fiberbridge/app/scene/scene_context.h"
#include "fiberbridge/app/scene/scene_parameters.h"
#include "fiberbridge/app/scene/scene_reader.h"
#include "fiberbridge/core/csv.h"
#include "fiberbridge/core/output_guard.h"

#include <chrono>
#include <iostream>
#include <set>

namespace fiberbridge::app {

void merge_outcome(SceneContext& ctx, const std::string& item, ItemOutcome outcome) {
  if (outcome.records)
    ctx.records = std::move(outcome.records);
  if (outcome.reduced)
    ctx.reduced = std::move(outcome.reduced);
  if (outcome.rdelta_root)
    ctx.rdelta_root = std::move(outcome.rdelta_root);
  if (outcome.extraction)
    ctx.extraction = std::move(outcome.extraction);
  if (outcome.identification)
    ctx.identification = std::move(outcome.identification);
  if (outcome.law)
    ctx.handed_law = std::move(outcome.law);
  if (outcome.specimen)
    ctx.handed_specimen = std::move(outcome.specimen);
  if (outcome.records_from_dic)
    ctx.records_from_dic = std::move(*outcome.records_from_dic);
  if (outcome.simulation)
    ctx.results[item] = std::move(*outcome.simulation);
  add_report_to_summary(outcome.report, ctx.summary);
}

void check_scene(SceneContext& ctx) {
  for (const auto& item : scene_items())
    if (ctx.run_items.count(item.name))
      item.check(ctx);
}

std::string run_scene(const std::string& prm_file, const std::vector<std::string>& overrides,
                      bool resume, const std::function<void(const std::string&)>& progress) {
  const auto t0 = std::chrono::steady_clock::now();
  SceneContext ctx;
  ctx.params = read_scene_parameters(prm_file, overrides);
  const auto& wanted = ctx.parameters().run;
  std::set<std::string> wanted_set(wanted.begin(), wanted.end());
  ctx.scene_file = prm_file;
  ctx.progress_sink = progress;
  ctx.run_items = wanted_set;
  // Every section the run will use is read and validated before anything is written: a bad value
  // in the section of the last item must not surface after the first item's minutes of work.
  check_scene(ctx);
  ctx.output_dir = ctx.parameters().output_directory;
  // Under mpirun only rank 0 writes (core/output_guard.h); the others must not remove the
  // summary rank 0 is about to write either.
  const bool writer = output_enabled();
  ctx.resume = resume;
  ensure_directory(ctx.output_dir);
  if (writer)
    remove_stale_summary(ctx.output_dir);
  // A fresh run must not later resume into an earlier run's records and checkpoints.
  if (!resume)
    clear_resume_state(ctx.output_dir);
  ctx.summary["scene"] = prm_file;
  ctx.summary["run"] = wanted;
  ctx.summary["plots"] = Json::array();
  if (resume)
    ctx.summary["resumed"] = true;
  for (const auto& item : scene_items()) {
    // Under mpirun the scene's simulations may run as tasks across the ranks (simulation_tasks.h).
    if (!wanted_set.count(item.name) || ran_as_simulation_task(ctx, item.name, wanted_set))
      continue;
    if (writer)
      ctx.progress("fiberbridge: running " + item.name);
    const auto ti = std::chrono::steady_clock::now();
    // A simulation is a unit of work that --resume restores once finished (resume_store.h).
    merge_outcome(ctx, item.name,
                  is_simulation_item(item.name) ? run_or_restore_simulation_item(ctx, item)
                                                : item.run(ctx));
    ctx.summary["item_wall_time_s"][item.name] =
        std::chrono::duration<double>(std::chrono::steady_clock::now() - ti).count();
  }
  ctx.summary["wall_time_s"] =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  write_file_atomically(ctx.out("parameters_used.prm"), ctx.parameters().listing);
  const std::string report = text_report(ctx.summary);
  write_file_atomically(ctx.out("report.txt"), report);
  write_run_summary(ctx.output_dir, ctx.summary);
  if (writer)
    std::cout << report;
  return ctx.output_dir;
}

} // namespace fiberbridge::app
