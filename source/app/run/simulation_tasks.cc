#include "fiberbridge/app/run/simulation_tasks.h"

#include "fiberbridge/app/run/outcome_archive.h"
#include "fiberbridge/app/run/resume_store.h"
#include "fiberbridge/app/run/scene_runner.h"
#include "fiberbridge/app/run/task_distributor.h"
#include "fiberbridge/app/scene/models.h"
#include "fiberbridge/core/output_guard.h"

#include <chrono>
#include <functional>
#include <iostream>
#include <vector>

namespace fiberbridge::app {
namespace {

/// A task's bytes: the item's outcome (outcome_archive.h, the record --resume keeps) and how long
/// the task took.
const char* task_output_kind = "fiberbridge simulation task";

/// Relative cost, only to order the hand-out (the slowest model starts first); 0 for the items
/// that are not simulations.
double cost_of(const std::string& item) {
  const SimulationModel* m = built_model(item);
  return m ? m->cost : 0.0;
}

Json run_simulations(SceneContext& ctx, const std::set<std::string>& wanted, MPI_Comm comm) {
  std::vector<const SceneItem*> sims;
  for (const auto& item : scene_items())
    if (const SimulationModel* m = built_model(item.name);
        m && wanted.count(item.name) &&
        !(m->needs_all_ranks && m->needs_all_ranks(ctx.parameters())))
      sims.push_back(&item);
  int n_ranks = 1;
  MPI_Comm_size(comm, &n_ranks);
  Json block = {{"ranks", n_ranks}, {"items", Json::array()}};
  if (sims.empty() || (sims.size() == 1 && built_model(sims[0]->name)->uses_all_ranks))
    return block; // one collective run (the FEM) or none: the items run as they are

  std::vector<double> cost;
  std::string names;
  for (const auto* s : sims) {
    cost.push_back(cost_of(s->name));
    names += (names.empty() ? "" : ", ") + s->name;
  }
  if (output_enabled())
    std::cerr << "fiberbridge: running " << names << " as independent tasks on " << n_ranks
              << " ranks\n";
  const auto done = run_tasks_across_ranks(
      sims.size(),
      [&](std::size_t i) {
        const SceneItem& item = *sims[i];
        TaskOwnsItsFiles own; // its model's files only: rcurve_<model>.csv, fields, PNG
        const auto t0 = std::chrono::steady_clock::now();
        const ItemOutcome outcome = run_or_restore_simulation_item(ctx, item);
        const double t =
            std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
        BinaryWriter out(task_output_kind, 1);
        out.put(outcome);
        out.put(t);
        return out.finish();
      },
      comm, cost);
  // Back into the scene in item order, as a serial run would have left them.
  for (std::size_t i = 0; i < sims.size(); ++i) {
    const std::string& name = sims[i]->name;
    BinaryReader in(done.output[i], task_output_kind, 1, "simulation task " + name);
    ItemOutcome outcome = in.get<ItemOutcome>();
    const double wall_time_s = in.get<double>();
    in.expect_end();
    merge_outcome(ctx, name, std::move(outcome));
    ctx.summary["item_wall_time_s"][name] = wall_time_s;
    block["items"].push_back({{"item", name}, {"rank", done.rank[i]}});
  }
  return block;
}

} // namespace

bool ran_as_simulation_task(SceneContext& ctx, const std::string& item,
                            const std::set<std::string>& wanted) {
  const MPI_Comm comm = simulation_communicator();
  int n_ranks = 1;
  MPI_Comm_size(comm, &n_ranks);
  if (n_ranks == 1 || cost_of(item) == 0)
    return false;
  if (!ctx.summary.contains("simulation_tasks"))
    ctx.summary["simulation_tasks"] = run_simulations(ctx, wanted, comm);
  for (const auto& t : ctx.summary["simulation_tasks"]["items"])
    if (t["item"] == item)
      return true;
  return false;
}

} // namespace fiberbridge::app
