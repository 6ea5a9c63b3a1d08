// fiberbridge.campaign: a durability campaign (a manifest of specimens over materials and
// moisture cycles) reduced to the paper's Table 1 with intervals from the replicates, the
// degradation per property and the ranking with its confidence, as a scene's `campaign`
// computes it (app/items/items.h, analyse_scene_campaign) and summary.json states it. Nothing is
// written.
#include "bindings.h"
#include "python_scene.h"

#include "fiberbridge/app/items/items.h"
#include "fiberbridge/app/outputs/campaign_writers.h"
#include "fiberbridge/core/error.h"

#include <pybind11/stl.h>

#include <chrono>

namespace fiberbridge::python {

void bind_campaign(py::module_& m) {
  m.def(
      "campaign",
      [](const std::vector<std::string>& settings, const py::object& progress) {
        std::string block;
        double compute_s = 0;
        // The campaign's lines (one per group and per simulation) check for Ctrl-C; without a
        // callback they are not printed (a call writes nothing).
        SceneProgress lines(progress, /*echo=*/false);
        try {
          py::gil_scoped_release free;
          app::SceneContext ctx = call_context("fiberbridge.campaign", settings, "campaign");
          ctx.progress_sink = lines.sink();
          const auto t0 = std::chrono::steady_clock::now();
          const analysis::CampaignResult r = app::analyse_scene_campaign(ctx);
          compute_s = seconds_since(t0);
          app::CampaignWriteOptions w;
          w.seconds = compute_s;
          block = app::campaign_summary_block(r, w).dump();
        } catch (const RunInterrupted&) {
          lines.raise_kept("fiberbridge.campaign");
        }
        py::dict d = python_of_json_text(block);
        d["compute_s"] = compute_s;
        return d;
      },
      py::arg("settings"), py::arg("progress") = py::none(),
      "The campaign of Campaign/Manifest as summary.json's campaign block (nothing written).");
}

} // namespace fiberbridge::python
