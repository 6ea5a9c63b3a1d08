// fiberbridge.simulate and fiberbridge.run_scene: a model of the registry (app/scene/models.h)
// run with a law on the specimen of the call's sections, writing nothing; and a whole scene, as
// `fiberbridge run` runs it.
#include "arrays.h"
#include "bindings.h"
#include "python_scene.h"

#include "fiberbridge/app/run/scene_runner.h"
#include "fiberbridge/app/scene/models.h"
#include "fiberbridge/core/error.h"
#include "fiberbridge/core/units.h"
#include "fiberbridge/law/piecewise_linear_law.h"

#include <pybind11/stl.h>

#include <chrono>
#include <fstream>
#include <optional>
#include <sstream>

namespace fiberbridge::python {

namespace {

using units::mm;

/// The R curve's columns, as rcurve_<model>.csv names them.
py::dict rcurve_dict(const result::SimulationResult& r) {
  const auto column = [&](double result::RCurvePoint::*field, double unit) {
    return member_array(r.rcurve, field, unit);
  };
  py::dict d;
  d["a_mm"] = column(&result::RCurvePoint::a, mm);
  d["root_mm"] = column(&result::RCurvePoint::root, mm);
  d["delta_root_mm"] = column(&result::RCurvePoint::delta_root, mm);
  d["zone_length_mm"] = column(&result::RCurvePoint::zone_length, mm);
  d["R_energy_J_m2"] = column(&result::RCurvePoint::R_energy, 1);
  d["R_J_J_m2"] = column(&result::RCurvePoint::R_J, 1);
  d["R_eq2_J_m2"] = column(&result::RCurvePoint::R_eq2, 1);
  d["J_tip_J_m2"] = column(&result::RCurvePoint::J_tip, 1);
  d["load_N"] = column(&result::RCurvePoint::load, 1);
  d["opening_mm"] = column(&result::RCurvePoint::load_point_opening, mm);
  return d;
}

} // namespace

void bind_simulate(py::module_& m) {
  m.def(
      "simulate",
      [](const std::string& model, const std::vector<std::string>& settings,
         std::optional<std::vector<double>> trilinear_si, std::optional<double> j_tip,
         const py::object& progress) {
        const app::ProgressLines lines = progress_lines(progress);
        result::SimulationResult r;
        double compute_s = 0;
        std::string law_name;
        double law_j_tip = 0;
        {
          py::gil_scoped_release free;
          const std::string where = "fiberbridge.simulate";
          const app::SimulationModel* entry = app::find_model(model);
          if (!entry)
            throw InputError(where + ": unknown model '" + model + "', expected one of " +
                             app::model_names());
          if (!entry->built || !entry->simulate)
            throw InputError(where + ": model '" + model + "' is not available in this build");
          app::SceneContext ctx = call_context(where, settings, model);
          // The law handed on as a scene's fit hands it (LawSource::fit), else the Cohesive law
          // section of the settings.
          if (trilinear_si) {
            const auto& p = *trilinear_si;
            if (p.size() != 5)
              throw InputError(where + ": a trilinear law is (d1, s1, d2, s2, dc)");
            const law::TrilinearParameters t{p[0], p[1], p[2], p[3], p[4]};
            ctx.handed_law =
                app::CrackLaw{std::make_shared<law::PiecewiseLinearLaw>(law::make_trilinear(t)),
                              j_tip ? *j_tip : ctx.j_tip(), app::LawSource::fit};
          } else if (j_tip)
            throw InputError(where + ": j_tip_J_m2 goes with a law; with the Cohesive law "
                                     "section, set 'Cohesive law/J tip'");
          app::check_scene(ctx);
          law_name = ctx.law()->name();
          law_j_tip = ctx.j_tip();
          const auto t0 = std::chrono::steady_clock::now();
          r = entry->simulate(ctx, *ctx.law(), ctx.j_tip(), lines);
          compute_s = seconds_since(t0);
        }
        py::dict d = rcurve_dict(r);
        d["model"] = r.model;
        d["law"] = law_name;
        d["J_tip_law_J_m2"] = law_j_tip;
        d["G_ss_J_m2"] = r.G_ss;
        d["reached_steady_state"] = r.reached_steady_state;
        d["steady_state_status"] = result::to_string(r.steady_state_status);
        d["rdelta_rel_error_vs_eq2"] = r.rdelta_rel_error_vs_eq2;
        d["n_dofs_or_particles"] = r.n_dofs_or_particles;
        d["wall_time_s"] = r.wall_time_s;
        d["notes"] = r.notes;
        d["method"] = r.method;
        d["compute_s"] = compute_s; // the model's run alone, for the call-overhead benchmark
        return d;
      },
      py::arg("model"), py::arg("settings"), py::arg("trilinear_si") = py::none(),
      py::arg("j_tip") = py::none(), py::arg("progress") = py::none(),
      "One model's R curve with the call's law and specimen (writes nothing); progress(line) "
      "gets the model's progress lines.");

  m.def(
      "run_scene",
      [](const std::string& path, const std::vector<std::string>& settings, bool resume,
         const py::object& progress) {
        // Each progress line of the scene (every item's and model's, nested scenes' too) runs
        // Python's signal handlers, then the callback, or prints the line to stderr as the
        // command line does. A Python error there (Ctrl-C, or the callback's own) is kept and the
        // run stopped by RunInterrupted, which no item takes for a failed case (core/error.h);
        // the run directory keeps its incomplete marker, and the error is raised here.
        SceneProgress lines(progress, /*echo=*/true);
        std::string text;
        try {
          py::gil_scoped_release free;
          const std::string out = app::run_scene(path, settings, resume, lines.sink());
          std::ifstream in(out + "/summary.json");
          if (!in)
            throw ComputationError(out + "/summary.json: the scene ran but its summary cannot "
                                         "be read back");
          std::ostringstream s;
          s << in.rdbuf();
          text = s.str();
        } catch (const RunInterrupted&) {
          lines.raise_kept(path);
        }
        return python_of_json_text(text);
      },
      py::arg("path"), py::arg("settings"), py::arg("resume") = false,
      py::arg("progress") = py::none(),
      "Runs a scene as `fiberbridge run` does; returns its summary.json. progress(line) gets the "
      "run's progress lines (default: stderr); Ctrl-C stops the run at the next line.");
}

} // namespace fiberbridge::python
