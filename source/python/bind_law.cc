// fiberbridge.extract and fiberbridge.fit_trilinear: the paper's Eq. 5/6 law beside sigma = R',
// the steady state, and the trilinear fit (analysis/law_extraction.h), with the Data and Fit
// sections' settings read as a scene reads them. Nothing is written.
#include "arrays.h"
#include "bindings.h"
#include "python_scene.h"

#include "fiberbridge/analysis/law_extraction.h"
#include "fiberbridge/analysis/rdelta_data.h"
#include "fiberbridge/analysis/record_reduction.h"
#include "fiberbridge/app/scene/step_outcomes.h"
#ifdef FIBERBRIDGE_HAVE_IDENTIFY
#include "fiberbridge/app/items/fit_correction_step.h"
#endif
#include "fiberbridge/core/error.h"
#include "fiberbridge/core/units.h"

#include <pybind11/stl.h>

#include <memory>

namespace fiberbridge::python {

namespace {

using units::kPa;
using units::mm;

py::dict extraction_dict(const std::shared_ptr<const analysis::ExtractionOutcome>& e) {
  py::dict d;
  d["delta_mm"] = scaled_array(e->laws.delta, mm);
  d["sigma_eq5_kPa"] = scaled_array(e->laws.sigma_eq6, kPa);
  d["sigma_dRdd_kPa"] = scaled_array(e->laws.sigma_dRdd, kPa);
  d["area_eq5_J_m2"] = e->laws.area_eq6;
  d["area_dRdd_J_m2"] = e->laws.area_dRdd;
  d["curve_delta_mm"] = scaled_array(e->curve.delta, mm);
  const py::object owner = py::cast(e);
  d["curve_R_J_m2"] = viewed_array(e->curve.R, owner);
  d["curve_R_std_J_m2"] = viewed_array(e->curve.R_std, owner);
  d["replicates"] = e->curve.n_replicates;
  d["J_tip_J_m2"] = e->steady.j_tip;
  d["G_ss_J_m2"] = e->steady.G_ss;
  d["delta_c_mm"] = e->steady.delta_c / mm;
  d["delta_c_automatic"] = e->steady.delta_c_automatic;
  d["J_tip_automatic"] = e->steady.j_tip_automatic;
  d["end_effect"] = e->steady.end_effect;
  d["criterion"] = e->steady.criterion;
  d["averaging"] = e->curve.report;
  d["outcome"] = owner;
  return d;
}

/// Extraction from the Data section's settings; `data` in memory (reduce's R(delta_root)) when
/// given, else Data/File.
std::shared_ptr<const analysis::ExtractionOutcome>
extract_with(const std::vector<std::string>& settings,
             std::shared_ptr<const analysis::RDeltaData> data) {
  const app::SceneContext ctx = call_context("fiberbridge.extract", settings, "extract");
  analysis::ExtractionOptions o = ctx.parameters().section<analysis::ExtractionOptions>("Data");
  if (data) {
    o.data = data;
    o.data_file = data->source;
  } else if (o.data_file.empty())
    throw InputError("fiberbridge.extract: no data: give an R(delta) CSV file or a reduction "
                     "whose records all measured delta_root");
  return std::make_shared<const analysis::ExtractionOutcome>(analysis::extract_law(o));
}

} // namespace

void bind_law(py::module_& m) {
  py::class_<analysis::ExtractionOutcome, std::shared_ptr<analysis::ExtractionOutcome>>(
      m, "ExtractionOutcome", "What extract found, handed to fit_trilinear (opaque).");

  m.def(
      "extract_file",
      [](const std::vector<std::string>& settings) {
        std::shared_ptr<const analysis::ExtractionOutcome> e;
        {
          py::gil_scoped_release free;
          e = extract_with(settings, nullptr);
        }
        return extraction_dict(e);
      },
      py::arg("settings"), "Eq. 5/6 and sigma = R' from Data/File with the Data section's keys.");

  m.def(
      "extract_columns",
      [](const ColumnIn& delta_mm, const ColumnIn& R_J_m2, const ColumnIn& a_mm,
         const ColumnIn& time_s, std::vector<std::string> replicate,
         const std::vector<std::string>& settings) {
        // One copy from the contiguous float64 buffers into the typed table (not a Python float
        // per element, as a list conversion would make).
        analysis::RDeltaColumns c{vector_of(delta_mm), vector_of(R_J_m2), vector_of(a_mm),
                                  vector_of(time_s), std::move(replicate)};
        std::shared_ptr<const analysis::ExtractionOutcome> e;
        {
          py::gil_scoped_release free;
          e = extract_with(settings,
                           std::make_shared<const analysis::RDeltaData>(
                               analysis::rdelta_from_columns("fiberbridge.extract (arrays)", c)));
        }
        return extraction_dict(e);
      },
      py::arg("delta_mm"), py::arg("R_J_m2"), py::arg("a_mm"), py::arg("time_s"),
      py::arg("replicate"), py::arg("settings"),
      "Eq. 5/6 and sigma = R' from R(delta) columns in memory, checked as a file's are.");

  m.def(
      "extract_reduced",
      [](const std::shared_ptr<app::ReduceOutcome>& r, const std::vector<std::string>& settings) {
        std::shared_ptr<const analysis::ExtractionOutcome> e;
        {
          py::gil_scoped_release free;
          for (const auto& rec : r->reduced)
            if (rec.delta_root.empty())
              throw InputError("fiberbridge.extract: record '" + rec.name +
                               "' has no delta_root_mm: R(delta_root) needs the notch-root "
                               "opening on every record");
          auto data = std::make_shared<const analysis::RDeltaData>(
              analysis::to_rdelta(r->reduced, "the reduction's R(delta_root)"));
          e = extract_with(settings, data);
        }
        return extraction_dict(e);
      },
      py::arg("reduction"), py::arg("settings"),
      "Eq. 5/6 and sigma = R' from a reduction's R(delta_root) (every record measured it).");

  m.def(
      "fit_trilinear",
      [](const std::shared_ptr<analysis::ExtractionOutcome>& e,
         const std::vector<std::string>& settings) {
        analysis::TrilinearFit fit;
        {
          py::gil_scoped_release free;
          const app::SceneContext ctx = call_context("fiberbridge.fit_trilinear", settings, "fit");
          fit = analysis::fit_extracted_law(*e,
                                            ctx.parameters().section<analysis::FitOptions>("Fit"));
        }
        const auto& t = fit.law;
        py::dict d;
        d["delta1_mm"] = t.d1 / mm;
        d["sigma1_kPa"] = t.s1 / kPa;
        d["delta2_mm"] = t.d2 / mm;
        d["sigma2_kPa"] = t.s2 / kPa;
        d["delta_c_mm"] = t.dc / mm;
        d["J1_J_m2"] = t.j1();
        d["J2_J_m2"] = t.j2();
        d["J_tip_J_m2"] = e->steady.j_tip;
        d["rms_residual_kPa"] = fit.rms_residual / kPa;
        d["max_residual_kPa"] = fit.max_residual / kPa;
        d["breakpoints"] = fit.d1_d2_free ? "free (variable projection)" : "fixed";
        // The law in SI as fitted, for simulate: not the mm and kPa above converted back, which
        // may differ in the last bit.
        d["law_si"] = std::vector<double>{t.d1, t.s1, t.d2, t.s2, t.dc};
        return d;
      },
      py::arg("extraction"), py::arg("settings"),
      "The trilinear fit of the Eq. 6 law, area G_ss - J_tip, with the Fit section's keys.");

#ifdef FIBERBRIDGE_HAVE_IDENTIFY
  m.def(
      "correct_fit",
      [](const std::shared_ptr<analysis::ExtractionOutcome>& e,
         const std::shared_ptr<app::ReduceOutcome>& reduction, const std::vector<double>& law_si,
         const std::vector<std::string>& settings) {
        identify::ChainCorrection c;
        {
          py::gil_scoped_release free;
          // The reduction's, extraction's and fit's settings together: the chain as the scene
          // runs it (reduce, extract, fit), with the reduction's records handed on as reduce does.
          app::SceneContext ctx = call_context("fiberbridge.fit_trilinear", settings, "fit");
          ctx.reduced = reduction;
          analysis::TrilinearFit fit;
          fit.law = {law_si.at(0), law_si.at(1), law_si.at(2), law_si.at(3), law_si.at(4)};
          c = app::correct_fit_by_simulation(ctx, *e,
                                             ctx.parameters().section<analysis::FitOptions>("Fit"),
                                             fit, app::fit_correction_settings(ctx));
        }
        py::dict d;
        d["converged"] = c.converged;
        d["simulations"] = c.steps.size();
        d["forward_time_s"] = c.forward_time_s;
        d["notes"] = c.notes;
        if (c.converged) {
          const auto& t = c.corrected.law;
          d["law_si"] = std::vector<double>{t.d1, t.s1, t.d2, t.s2, t.dc};
          d["J_tip_J_m2"] = c.corrected.j_tip;
          d["delta1_mm"] = t.d1 / mm;
          d["sigma1_kPa"] = t.s1 / kPa;
          d["delta2_mm"] = t.d2 / mm;
          d["sigma2_kPa"] = t.s2 / kPa;
          d["delta_c_mm"] = t.dc / mm;
        }
        return d;
      },
      py::arg("extraction"), py::arg("reduction"), py::arg("law_si"), py::arg("settings"),
      "The fit corrected by simulation (Fit/Model correction): the beam runs the reduction's "
      "records with the law until the same chain gives back what it gave on them.");
#endif
}

} // namespace fiberbridge::python
