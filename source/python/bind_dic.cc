// fiberbridge.dic: the paper's DIC step (crack tip by the 1 % strain rule, notch-root opening by a
// virtual extensometer) on a set of frames matched by time to the machine record, as a scene's
// `dic` computes it (app/items/dic_step.h, match_dic_frames), with the DIC, Test and Specimen
// sections' settings. Nothing is written.
#include "arrays.h"
#include "bindings.h"
#include "python_scene.h"

#include "fiberbridge/app/items/dic_step.h"
#include "fiberbridge/core/units.h"

#include <pybind11/stl.h>

#include <chrono>

namespace fiberbridge::python {

using units::mm;

void bind_dic(py::module_& m) {
  m.def(
      "dic",
      [](const std::vector<std::string>& settings) {
        app::DicMatch match;
        double compute_s = 0;
        {
          py::gil_scoped_release free;
          const app::SceneContext ctx = call_context("fiberbridge.dic", settings, "dic");
          const app::DicStepOptions o = app::dic_step_options(ctx);
          const auto t0 = std::chrono::steady_clock::now();
          match = app::match_dic_frames(o);
          compute_s = seconds_since(t0);
        }
        py::dict d;
        // The test record dic_record.csv holds, row per used frame in the machine's time span.
        d["time_s"] = member_array(match.rows, &dic::DicRecordRow::time, 1);
        d["opening_mm"] = member_array(match.rows, &dic::DicRecordRow::opening, mm);
        d["load_N"] = member_array(match.rows, &dic::DicRecordRow::load, 1);
        d["a_mm"] = member_array(match.rows, &dic::DicRecordRow::a, mm);
        d["a_sd_mm"] = member_array(match.rows, &dic::DicRecordRow::a_sd, mm);
        d["delta_root_mm"] = member_array(match.rows, &dic::DicRecordRow::delta_root, mm);
        d["delta_root_sd_mm"] = member_array(match.rows, &dic::DicRecordRow::delta_root_sd, mm);
        std::vector<std::size_t> frame;
        for (const auto& r : match.rows)
          frame.push_back(r.frame);
        d["frame"] = frame;
        // Every frame read, used or not, with its own notes.
        const auto& frames = match.analysis.frames;
        d["frame_time_s"] = member_array(frames, &dic::FrameResult::time, 1);
        d["frame_tip_mm"] = member_array(frames, &dic::FrameResult::s_tip, mm);
        std::vector<bool> used;
        std::vector<std::size_t> points, failed;
        py::list frame_notes, files;
        for (const auto& f : frames) {
          used.push_back(f.used);
          points.push_back(f.n_points);
          failed.push_back(f.n_failed);
          frame_notes.append(py::cast(f.notes));
          files.append(f.file.path);
        }
        d["frame_used"] = used;
        d["frame_points"] = points;
        d["frame_failed_points"] = failed;
        d["frame_notes"] = frame_notes;
        d["frame_files"] = files;
        d["frames_used"] = match.analysis.frames_used;
        d["point_spacing_mm"] = match.analysis.spacing / mm;
        d["notes"] = match.notes;
        d["compute_s"] = compute_s;
        return d;
      },
      py::arg("settings"),
      "a(t) and delta_root(t) from DIC frames and the machine record, as a scene's dic finds "
      "them (nothing written).");
}

} // namespace fiberbridge::python
