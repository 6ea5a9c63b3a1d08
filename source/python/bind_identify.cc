// fiberbridge.identify: the law from load, opening and crack readings without delta_root
// (identify/identify.h), the scene's joint fit of its records on this process with the Identify
// section's settings (app/items/item_identify.h, identify_scene_records). Nothing is written.
#include "arrays.h"
#include "bindings.h"
#include "python_scene.h"
#include "record_input.h"

#include "fiberbridge/core/error.h"
#include "fiberbridge/core/units.h"

#ifdef FIBERBRIDGE_HAVE_IDENTIFY
#include "fiberbridge/app/items/item_identify.h"
#include "fiberbridge/identify/identify.h"
#endif

#include <pybind11/stl.h>

namespace fiberbridge::python {

#ifdef FIBERBRIDGE_HAVE_IDENTIFY
namespace {

using units::kPa;
using units::mm;

py::dict record_fit_dict(const identify::RecordFit& r, const py::object& owner) {
  py::dict d;
  d["name"] = r.name;
  d["initial_crack_mm"] = r.initial_crack / mm;
  d["E_L_MPa"] = r.E_L / 1e6;
  d["peak_load_N"] = r.peak_load;
  d["load_rms_rel"] = r.load_rms_rel;
  d["crack_rms_mm"] = r.crack_rms / mm;
  d["opening_mm"] = scaled_array(r.opening, mm);
  d["load_N"] = viewed_array(r.load, owner);
  d["crack_length_mm"] = scaled_array(r.crack_length, mm);
  d["model_load_N"] = viewed_array(r.model_load, owner);
  d["model_crack_length_mm"] = scaled_array(r.model_crack_length, mm);
  return d;
}

} // namespace
#endif

void bind_identify(py::module_& m) {
  m.def(
      "identify",
      [](const py::list& items, const std::vector<std::string>& settings,
         const py::object& progress) -> py::dict {
#ifdef FIBERBRIDGE_HAVE_IDENTIFY
        std::vector<RecordIn> in = records_in(items);
        const auto lines = progress_lines(progress);
        identify::Identification id;
        std::shared_ptr<const std::vector<analysis::TestRecord>> records;
        {
          py::gil_scoped_release free;
          app::SceneContext ctx = call_context("fiberbridge.identify", settings, "identify");
          if (in.empty())
            throw InputError("fiberbridge.identify: no records given");
          // The records read (or cleaned) as reduce reads them: identify fits these.
          ctx.records = std::make_shared<const std::vector<analysis::TestRecord>>(
              read_records_in(std::move(in), ctx.record_chain().read));
          id = app::identify_scene_records(ctx, lines, records);
        }
        py::dict d;
        d["delta1_mm"] = id.law.d1 / mm;
        d["sigma1_kPa"] = id.law.s1 / kPa;
        d["delta2_mm"] = id.law.d2 / mm;
        d["sigma2_kPa"] = id.law.s2 / kPa;
        d["delta_c_mm"] = id.law.dc / mm;
        d["J_tip_J_m2"] = id.j_tip;
        d["G_ss_J_m2"] = id.g_ss;
        d["J_c_std_error_J_m2"] = id.j_c_std_error;
        d["load_rms_rel"] = id.load_rms_rel;
        d["crack_rms_mm"] = id.crack_rms / mm;
        d["chi2"] = id.chi2;
        d["evaluations"] = id.evaluations;
        d["forward_runs"] = id.forward_runs;
        d["wall_time_s"] = id.wall_time_s;
        py::dict estimates;
        for (const auto& p : id.parameters)
          estimates[py::str(p.name)] = py::make_tuple(p.value, p.std_error);
        d["estimates"] = estimates;
        py::list recs;
        const auto kept =
            std::make_shared<const std::vector<identify::RecordFit>>(std::move(id.records));
        const py::object owner = keeper_of(kept);
        for (const auto& r : *kept)
          recs.append(record_fit_dict(r, owner));
        d["records"] = recs;
        d["band_delta_mm"] = scaled_array(id.band_delta, mm);
        d["band_sigma_kPa"] = scaled_array(id.band_sigma, kPa);
        d["band_lo_kPa"] = scaled_array(id.band_lo, kPa);
        d["band_hi_kPa"] = scaled_array(id.band_hi, kPa);
        d["notes"] = id.notes;
        d["law_si"] = std::vector<double>{id.law.d1, id.law.s1, id.law.d2, id.law.s2, id.law.dc};
        return d;
#else
        (void)items;
        (void)settings;
        (void)progress;
        throw InputError("fiberbridge.identify: identify is not available in this build");
#endif
      },
      py::arg("records"), py::arg("settings"), py::arg("progress") = py::none(),
      "identify's joint fit of the records (files, or records as arrays) with the Identify "
      "section (writes nothing).");
}

} // namespace fiberbridge::python
