#pragma once
// The module's parts (module.cc calls each): one file per part of the chain.
#include "fiberbridge/core/clock.h"

#include <pybind11/pybind11.h>

#include <chrono>
#include <functional>
#include <memory>
#include <string>

namespace fiberbridge::python {

namespace py = pybind11;

void bind_records(py::module_& m);  ///< read_records, reduce (bind_records.cc)
void bind_law(py::module_& m);      ///< extract, fit_trilinear (bind_law.cc)
void bind_simulate(py::module_& m); ///< simulate, run_scene (bind_simulate.cc)
void bind_dic(py::module_& m);      ///< dic (bind_dic.cc)
void bind_campaign(py::module_& m); ///< campaign (bind_campaign.cc)
void bind_identify(py::module_& m); ///< identify (bind_identify.cc)

/// The progress callback a long call hands its model: at each progress line, with the GIL held,
/// Python's signal handlers run (Ctrl-C raises KeyboardInterrupt there), then `progress(line)`
/// unless it is None. Either exception is thrown through the model, which unwinds and has written
/// nothing. (module.cc)
std::function<void(const std::string&)> progress_lines(const py::object& progress);

/// The progress sink of a scene's run for a call from Python (SceneContext::progress_sink): at
/// each line progress_lines' check and callback, or, without a callback and with `echo`, the line
/// on standard error as the command line prints it. A Python error there (Ctrl-C, the callback's
/// own) is kept and the run stopped with RunInterrupted (core/error.h), which no item takes for
/// a failed case; once the run has unwound, `raise_kept()` raises it. (module.cc)
class SceneProgress {
public:
  SceneProgress(const py::object& progress, bool echo);
  std::function<void(const std::string&)> sink();
  /// With the GIL held, after RunInterrupted reached the binding: the kept Python error.
  [[noreturn]] void raise_kept(const std::string& where);

private:
  std::function<void(const std::string&)> lines_;
  bool echo_;
  std::shared_ptr<py::error_already_set> kept_;
};

/// A summary.json block as the Python object json.loads makes of it.
py::object python_of_json_text(const std::string& json_text);

} // namespace fiberbridge::python
