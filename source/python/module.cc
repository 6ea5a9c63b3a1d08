// fiberbridge._core: the typed API of the scene items for Python (issue 41). The package
// (fiberbridge/__init__.py) turns keyword arguments with units into the sections' settings and
// wraps these dicts in result classes. MPI is started once per interpreter, as main() starts it
// (source/app/cli/main.cc), and finalized when the interpreter exits.
#include "bindings.h"

#include "fiberbridge/core/error.h"
#include "fiberbridge/core/output_guard.h"

#include <deal.II/base/mpi.h>

#include <cstdlib>
#include <iostream>

namespace fiberbridge::python {

py::object python_of_json_text(const std::string& json_text) {
  return py::module_::import("json").attr("loads")(json_text);
}

std::function<void(const std::string&)> progress_lines(const py::object& progress) {
  // A borrowed handle, not a py::object: the models copy their callback (DcbModel keeps one)
  // while the GIL is released, and copying an object would touch its reference count without it.
  // The caller's argument keeps the callable alive for the call.
  const py::handle callable = progress;
  return [callable](const std::string& line) {
    py::gil_scoped_acquire hold;
    if (PyErr_CheckSignals() != 0)
      throw py::error_already_set();
    if (!callable.is_none())
      callable(line);
  };
}

SceneProgress::SceneProgress(const py::object& progress, bool echo)
    : lines_(progress_lines(progress)), echo_(echo && progress.is_none()) {}

std::function<void(const std::string&)> SceneProgress::sink() {
  return [this](const std::string& line) {
    try {
      lines_(line);
    } catch (py::error_already_set& e) {
      py::gil_scoped_acquire hold;
      kept_ = std::make_shared<py::error_already_set>(std::move(e));
      throw RunInterrupted{};
    }
    if (echo_)
      std::cerr << line << '\n';
  };
}

void SceneProgress::raise_kept(const std::string& where) {
  if (kept_)
    throw py::error_already_set(std::move(*kept_));
  throw ComputationError(where + ": the run was stopped");
}

namespace {

dealii::Utilities::MPI::MPI_InitFinalize* mpi = nullptr;

/// MPI (and p4est) once per interpreter, unless the host already started MPI (mpi4py).
void start_mpi() {
  int started = 0;
  MPI_Initialized(&started);
  if (started)
    return;
  // The same singleton start as main() (no orted daemon for one process).
  setenv("OMPI_MCA_ess_singleton_isolated", "1", /*overwrite=*/0);
  static int argc = 1;
  static char name[] = "fiberbridge";
  static char* args[] = {name, nullptr};
  static char** argv = args;
  mpi = new dealii::Utilities::MPI::MPI_InitFinalize(argc, argv, 1);
  py::module_::import("atexit").attr("register")(py::cpp_function([] {
    delete mpi;
    mpi = nullptr;
  }));
}

} // namespace

} // namespace fiberbridge::python

PYBIND11_MODULE(_core, m) {
  namespace py = pybind11;
  using namespace fiberbridge::python;
  m.doc() = "fiberbridge's typed API (use the fiberbridge package, not this module)";
  // Bad input is a ValueError whose message is the command line's one line; a computation that
  // cannot resolve its case a RuntimeError.
  py::register_exception<fiberbridge::InputError>(m, "InputError", PyExc_ValueError);
  py::register_exception<fiberbridge::ComputationError>(m, "ComputationError", PyExc_RuntimeError);
  start_mpi();
  fiberbridge::set_output_enabled(true);
  bind_records(m);
  bind_law(m);
  bind_simulate(m);
  bind_dic(m);
  bind_campaign(m);
  bind_identify(m);
}
