#pragma once
// Running a .prm scene (docs/design.md section 5): read it (scene/scene_reader.h), check every
// listed item's sections, then run only the items listed in `Run`, in the registry's order.
#include <functional>
#include <string>
#include <vector>

namespace fiberbridge::app {

struct SceneContext; // scene/scene_context.h
struct ItemOutcome;  // scene/item_outcome.h

/// Runs the scene; returns the output directory. Throws InputError/ComputationError. With
/// `resume`, work an earlier run into the same output directory finished is restored and
/// checkpoints are continued (resume_store.h); without, that state is removed first.
/// `progress` takes the run's progress lines (SceneContext::progress_sink; empty: standard
/// error) and may throw RunInterrupted (core/error.h) to stop the run.
std::string run_scene(const std::string& prm_file, const std::vector<std::string>& overrides,
                      bool resume = false,
                      const std::function<void(const std::string&)>& progress = {});

/// What item `item` made entered into the scene's state, the one place where outcomes do: each
/// hand-over it holds set in the context (a simulation's result under ctx.results[item]), its
/// report's blocks and plots added to the summary.
void merge_outcome(SceneContext& ctx, const std::string& item, ItemOutcome outcome);

} // namespace fiberbridge::app
