// fiberbridge.read_records and fiberbridge.reduce: the records as a scene's `reduce` reads them
// (the Test section's read options, analysis/record_chain.h) and their reduction to R(a)
// (app/items/reduce_step.h), with numpy arrays out. Nothing is written.
#include "arrays.h"
#include "bindings.h"
#include "python_scene.h"
#include "record_input.h"

#include "fiberbridge/analysis/record_chain.h"
#include "fiberbridge/app/items/reduce_step.h"
#include "fiberbridge/app/scene/step_outcomes.h"
#include "fiberbridge/app/scene/test_section.h"
#include "fiberbridge/core/error.h"
#include "fiberbridge/core/units.h"

#include <pybind11/stl.h>

#include <chrono>
#include <memory>

namespace fiberbridge::python {

namespace {

using units::mm;

py::dict record_dict(analysis::TestRecord r) {
  py::dict d;
  d["name"] = r.name;
  d["source"] = r.source;
  d["time_s"] = moved_array(std::move(r.time));
  d["opening_mm"] = scaled_array(r.opening, mm);
  d["load_N"] = moved_array(std::move(r.load));
  d["a_mm"] = scaled_array(r.crack_length, mm);
  d["delta_root_mm"] = scaled_array(r.delta_root, mm);
  d["line"] = r.line;
  d["cleaning"] = r.cleaning;
  return d;
}

py::dict method_dict(const analysis::MethodSummary& s) {
  py::dict d;
  d["initiation_J_m2"] = s.initiation;
  d["plateau_J_m2"] = s.plateau;
  d["plateau_std_J_m2"] = s.plateau_std;
  return d;
}

/// Initiation and plateau by each method, keyed as summary.json keys them (a record's or the
/// mean's: both carry energy, mbt, cc, mcc and cbbm).
template <class Reduced>
py::dict methods_dict(const Reduced& r) {
  py::dict methods;
  methods["energy"] = method_dict(r.energy);
  methods["MBT"] = method_dict(r.mbt);
  methods["CC"] = method_dict(r.cc);
  methods["MCC"] = method_dict(r.mcc);
  methods["CBBM"] = method_dict(r.cbbm);
  return methods;
}

py::dict reduced_dict(const analysis::ReducedRecord& r, const py::object& owner) {
  py::dict d;
  d["name"] = r.name;
  d["source"] = r.source;
  d["crack"] = r.crack;
  d["a_mm"] = scaled_array(r.a, mm);
  d["da_mm"] = scaled_array(r.da, mm);
  d["load_N"] = viewed_array(r.load, owner);
  d["opening_mm"] = scaled_array(r.opening, mm);
  d["R_energy_J_m2"] = viewed_array(r.R_energy, owner);
  d["R_energy_lo_J_m2"] = viewed_array(r.R_energy_lo, owner);
  d["R_energy_hi_J_m2"] = viewed_array(r.R_energy_hi, owner);
  d["R_MBT_J_m2"] = viewed_array(r.R_MBT, owner);
  d["R_CC_J_m2"] = viewed_array(r.R_CC, owner);
  d["R_MCC_J_m2"] = viewed_array(r.R_MCC, owner);
  d["delta_root_mm"] = scaled_array(r.delta_root, mm);
  d["a_eq_mm"] = scaled_array(r.a_eq, mm);
  d["R_CBBM_J_m2"] = viewed_array(r.R_CBBM, owner);
  d["a0_mm"] = r.a0 / mm;
  d["window_mm"] = r.window / mm;
  d["methods"] = methods_dict(r);
  d["notes"] = r.notes;
  d["cleaning"] = r.cleaning;
  return d;
}

py::dict mean_dict(const analysis::ReducedMean& m, const py::object& owner) {
  py::dict d;
  d["n_records"] = m.n_records;
  d["da_mm"] = scaled_array(m.da, mm);
  d["R_energy_J_m2"] = viewed_array(m.R_energy, owner);
  d["R_energy_std_J_m2"] = viewed_array(m.R_energy_std, owner);
  d["R_MBT_J_m2"] = viewed_array(m.R_MBT, owner);
  d["R_CC_J_m2"] = viewed_array(m.R_CC, owner);
  d["R_MCC_J_m2"] = viewed_array(m.R_MCC, owner);
  d["R_CBBM_J_m2"] = viewed_array(m.R_CBBM, owner);
  d["methods"] = methods_dict(m);
  return d;
}

/// The Test, Specimen and Material sections' read and reduce settings, as reduce_options of the
/// scene item (items/item_reduce.cc) makes them; the records are the call's own.
app::ReduceStepOptions reduce_options_of(const std::vector<std::string>& settings,
                                         const std::string& where) {
  const app::SceneContext ctx = call_context(where, settings, "reduce");
  app::ReduceStepOptions o;
  static_cast<analysis::RecordChainOptions&>(o) = ctx.record_chain();
  o.where = where + ": Specimen";
  return o;
}

} // namespace

void bind_records(py::module_& m) {
  py::class_<app::ReduceOutcome, std::shared_ptr<app::ReduceOutcome>>(
      m, "ReduceOutcome", "What reduce found, handed to extract (opaque).");

  m.def(
      "read_records",
      [](const std::string& path, const std::vector<std::string>& settings) {
        std::vector<analysis::TestRecord> records;
        {
          py::gil_scoped_release free;
          const app::SceneContext ctx =
              call_context("fiberbridge.read_records", settings, "reduce");
          records = analysis::read_records({path}, ctx.record_chain().read);
        }
        py::list out;
        for (auto& r : records)
          out.append(record_dict(std::move(r)));
        return out;
      },
      py::arg("path"), py::arg("settings"),
      "The records of one file, read as a scene's reduce reads Test/Files with these settings.");

  m.def(
      "reduce",
      [](const py::list& items, const std::vector<std::string>& settings,
         const py::object& progress) {
        std::vector<RecordIn> in = records_in(items);
        const auto lines = progress_lines(progress);
        std::shared_ptr<app::ReduceOutcome> r;
        app::ReduceStepOptions o;
        double compute_s = 0;
        Json summary;
        {
          py::gil_scoped_release free;
          o = reduce_options_of(settings, "fiberbridge.reduce");
          if (in.empty())
            throw InputError("fiberbridge.reduce: no records given");
          o.specimen.check_test_geometry(o.where);
          const auto t0 = std::chrono::steady_clock::now();
          r = std::make_shared<app::ReduceOutcome>(
              app::reduce_records(o, read_records_in(std::move(in), o.read), lines));
          compute_s = seconds_since(t0);
          summary = app::reduce_summary_block(o, *r);
        }
        const py::object owner = py::cast(r);
        py::dict d;
        py::list records;
        for (const auto& rec : r->reduced)
          records.append(reduced_dict(rec, owner));
        d["records"] = records;
        d["mean"] = mean_dict(r->mean, owner);
        d["summary"] = python_of_json_text(summary.dump());
        d["outcome"] = owner;
        d["compute_s"] = compute_s; // the reduction alone, for the call-overhead benchmark
        return d;
      },
      py::arg("records"), py::arg("settings"), py::arg("progress") = py::none(),
      "R(a) of the records (files, or records as arrays) by every method, as a scene's reduce "
      "computes it (nothing written).");
}

} // namespace fiberbridge::python
