// Scene item `identify` (section Identify): the trilinear law and J_tip for which the beam model
// reproduces the records of the Test section (include/fiberbridge/identify/identify.h). The
// identified law, J_tip and the effective specimen (first record's a0 and calibrated E_L) are
// handed to the simulations that follow, as `fit` hands its law.
#include "outputs/identify_writers.h"

#include "fiberbridge/app/items/item_identify.h"
#include "fiberbridge/app/items/items.h"
#include "fiberbridge/app/run/identify_resume.h"
#include "fiberbridge/app/run/task_distributor.h"
#include "fiberbridge/app/scene/models.h"
#include "fiberbridge/app/scene/scene_reader.h"
#include "fiberbridge/app/scene/section.h"
#include "fiberbridge/app/scene/test_section.h"
#include "fiberbridge/core/csv.h"
#include "fiberbridge/core/error.h"
#include "fiberbridge/core/format.h"
#include "fiberbridge/core/output_guard.h"
#include "fiberbridge/core/plot.h"
#include "fiberbridge/core/units.h"
#include "fiberbridge/identify/identify.h"

#include <deal.II/base/parameter_handler.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <iostream>
#include <optional>

namespace fiberbridge::app {

using dealii::Patterns::Bool;
using dealii::Patterns::Double;
using dealii::Patterns::Integer;
using dealii::Patterns::Selection;
using units::kPa;
using units::mm;

/// Identify: the bounds, weights and optimizer of the identification and its beam forward model.
struct IdentifySection : identify::IdentifySettings {
  bool per_record = false; ///< also identify each record alone
  /// identify's own model (the beam: identify_builtin) or a registered model offering
  /// identify_forward (scene/models.h): "fem".
  std::string forward_model = "beam";

  static void declare_parameters(dealii::ParameterHandler& prm) {
    prm.declare_entry("Delta c min", "0.2", Double(0), "Lower bound of delta_c (mm).");
    prm.declare_entry("Delta c max", "40", Double(0), "Upper bound of delta_c (mm).");
    prm.declare_entry("Stress max", "20000", Double(0),
                      "Upper bound of sigma_1 (kPa); sigma_2 <= sigma_1, both >= 1e-3 of it.");
    prm.declare_entry("J tip min", "20", Double(0), "Lower bound of J_tip (J/m^2).");
    prm.declare_entry("J tip max", "3000", Double(0), "Upper bound of J_tip (J/m^2).");
    prm.declare_entry(
        "Load scatter", "0.02", Double(0),
        "Expected load misfit as a fraction of the peak load (weights the load rows).");
    prm.declare_entry("Crack scatter", "1", Double(0),
                      "Expected crack-reading misfit in mm (weights the fresh crack readings).");
    prm.declare_entry("Calibrate modulus", "true", Bool(),
                      "E_L from each record's initial compliance by corrected beam theory; false: "
                      "Material/E_L as given.");
    prm.declare_entry("Compliance low", "0.1", Double(0, 1),
                      "The initial compliance is fitted over the rows before the first crack jump "
                      "with a load between these fractions of the peak.");
    prm.declare_entry("Compliance high", "0.5", Double(0, 1), "See Compliance low.");
    prm.declare_entry(
        "Large displacement correction", "true", Bool(),
        "Map the beam's small-rotation states onto large rotations with ISO 15024's F and N.");
    prm.declare_entry("Algorithm", "bobyqa", Selection("bobyqa|sbplx"),
                      "NLopt bounded derivative-free method.");
    prm.declare_entry("Max evaluations", "300", Integer(10), "Misfit evaluations per start.");
    prm.declare_entry("Starts", "2", Integer(1), "Optimizer starts (different delta_c guesses).");
    prm.declare_entry("Tolerance", "1e-4", Double(0, 1), "Relative change of the misfit to stop.");
    prm.declare_entry("Number of elements", "160", Integer(4),
                      "Beam elements on the ligament of the forward model.");
    prm.declare_entry("Tip advance", "1", Double(0), "Beam tip advance of the forward model (mm).");
    prm.declare_entry("Per record", "false", Bool(),
                      "Also identify each record alone (identify.per_record in summary.json).");
    // Anything, checked in parse_parameters: the models that can serve are the registry's (a
    // build without the FEM says so by name rather than by a pattern mismatch).
    prm.declare_entry(
        "Forward model", "beam", dealii::Patterns::Anything(),
        "The simulation each trial law runs in: beam (identify's own, with Number of elements and "
        "Tip advance above) or fem (the FEM section's settings, one mesh for every trial, each run "
        "on one rank; started from the beam's identification, whose figures the notes give; "
        "minutes per record with today's FEM, docs/verification.md).");
  }
  void parse_parameters(dealii::ParameterHandler& prm) {
    delta_c_min = prm.get_double("Delta c min") * mm;
    delta_c_max = prm.get_double("Delta c max") * mm;
    stress_max = prm.get_double("Stress max") * kPa;
    j_tip_min = prm.get_double("J tip min");
    j_tip_max = prm.get_double("J tip max");
    load_scatter = prm.get_double("Load scatter");
    crack_scatter = prm.get_double("Crack scatter") * mm;
    calibrate_modulus = prm.get_bool("Calibrate modulus");
    compliance_low = prm.get_double("Compliance low");
    compliance_high = prm.get_double("Compliance high");
    large_displacement = prm.get_bool("Large displacement correction");
    algorithm = prm.get("Algorithm");
    max_evaluations = prm.get_integer("Max evaluations");
    starts = prm.get_integer("Starts");
    relative_tolerance = prm.get_double("Tolerance");
    beam.n_elements = prm.get_integer("Number of elements");
    beam.tip_advance = prm.get_double("Tip advance") * mm;
    per_record = prm.get_bool("Per record");
    forward_model = prm.get("Forward model");
    validate("Identify");
    const SimulationModel* m = find_model(forward_model);
    if (!m || !m->identify_builtin) {
      // identify's own model first, then every built model that offers itself as its forward
      // model (scene/models.h).
      std::string offered;
      for (const auto& model : simulation_models())
        if (model.identify_builtin)
          offered += (offered.empty() ? "" : ", ") + std::string(model.name);
      for (const auto& model : simulation_models())
        if (model.built && model.identify_forward)
          offered += (offered.empty() ? "" : ", ") + std::string(model.name);
      if (m && !m->built)
        throw InputError(
            "Identify/Forward model: '" + forward_model +
            "' is not built in this fiberbridge (FIBERBRIDGE_MODELS); offered: " + offered);
      if (!m || !m->identify_forward)
        throw InputError("Identify/Forward model: expected one of " + offered + ", got '" +
                         forward_model + "'");
    }
  }
};

void declare_identify_section(dealii::ParameterHandler& prm) {
  declare_section<IdentifySection>(prm, "Identify");
}

void parse_identify_section(dealii::ParameterHandler& prm, SceneParameters& out) {
  parse_into<IdentifySection>(prm, "Identify", out);
}

namespace {

/// What a fit's bytes hold when it crosses from the rank that ran it (core/binary_archive.h).
const char* fit_kind = "fiberbridge identify fit";

/// The records of the Test section: `reduce`'s (it ran before, scene order) or the ones identify's
/// check read, else read here, as reduce reads them (identify's check reads them and keeps them
/// in the context, its run fits them and hands them on when it read them).
std::shared_ptr<const std::vector<analysis::TestRecord>> scene_records(const SceneContext& ctx) {
  std::shared_ptr<const std::vector<analysis::TestRecord>> records = ctx.records;
  if (!records) {
    // After `dic` (without reduce) the records are the ones dic wrote, read as reduce reads
    // them (item_reduce.cc); Test/Files then names the machine record.
    const auto& test = ctx.parameters().section<TestSection>("Test");
    analysis::RecordReadOptions read = ctx.record_chain().read;
    std::vector<std::string> files = test.resolved_files(ctx.scene_file);
    if (!ctx.records_from_dic.empty()) {
      files = ctx.records_from_dic;
      read.columns = {};
    }
    records =
        std::make_shared<std::vector<analysis::TestRecord>>(analysis::read_records(files, read));
  }
  if (records->empty())
    throw InputError(ctx.scene_file + ": 'identify' needs records in Test/Files");
  return records;
}

/// identify's independent jobs (identify.h, IdentifyJobRunner) as tasks across the ranks of the
/// simulation communicator (task_distributor.h): every rank gets every job's result. Inside a task
/// that communicator is MPI_COMM_SELF, so the jobs then run one after the other. With `log`, each
/// batch is listed there (fit, what, tasks, the rank and the CPU seconds of each).
identify::IdentifyJobRunner jobs_across_ranks(Json* log, const std::string& fit) {
  return [log, fit](const std::string& what, std::size_t n, const identify::IdentifyJob& job) {
    auto done = run_tasks_across_ranks(n, job, simulation_communicator());
    if (log)
      log->push_back({{"fit", fit},
                      {"what", what},
                      {"tasks", n},
                      {"ranks", done.rank},
                      {"cpu_s", done.cpu_seconds}});
    return std::move(done.output);
  };
}

/// The forward model of Identify/Forward model: empty (identify's own beam) or the registry's.
identify::ForwardModel forward_model_of(const SceneContext& ctx, const IdentifySection& section) {
  const SimulationModel* m = find_model(section.forward_model);
  if (m->identify_builtin)
    return {};
  return m->identify_forward(ctx);
}

/// One fit of `records`. With a forward model other than the beam, the beam's identification
/// first (seconds) and the other model's from its optimum (IdentifySettings::start_law): today's
/// FEM costs about a second a run, so its search starts where the beam's ended and corrects the
/// beam's model error (docs/design.md section 6, "Forward model of identify"). The beam route's
/// figures go to the notes (they are kept for --resume with the fit).
identify::Identification
fit_records(const std::vector<analysis::TestRecord>& records, const specimen::Specimen& specimen,
            const specimen::Material& quoted, const identify::IdentifySettings& settings,
            const std::function<void(const std::string&)>& progress,
            const identify::IdentifyJobRunner& jobs, const identify::ForwardModel& forward) {
  if (!forward.run)
    return identify::identify_law(records, specimen, quoted, settings, progress, jobs);
  const auto beam = identify::identify_law(records, specimen, quoted, settings, progress, jobs);
  identify::IdentifySettings from_beam = settings;
  from_beam.start_law = beam.law;
  from_beam.start_j_tip = beam.j_tip;
  auto id = identify::identify_law(records, specimen, quoted, from_beam, progress, jobs, forward);
  id.notes.insert(
      id.notes.begin(),
      "beam route (the " + forward.name + "'s start): chi^2 " + fmt(beam.chi2) + ", load RMS " +
          fmt(100 * beam.load_rms_rel, 3) + " % of the peak, crack RMS " +
          fmt(beam.crack_rms / mm, 3) + " mm, J_tip " + fmt(beam.j_tip, 4) + " J/m^2, G_ss " +
          fmt(beam.g_ss, 4) + " J/m^2, d1 " + fmt(beam.law.d1 / mm, 4) + " mm, sigma1 " +
          fmt(beam.law.s1 / kPa, 4) + " kPa, d2 " + fmt(beam.law.d2 / mm, 4) + " mm, sigma2 " +
          fmt(beam.law.s2 / kPa, 4) + " kPa, delta_c " + fmt(beam.law.dc / mm, 4) + " mm; " +
          std::to_string(beam.forward_runs) + " beam runs in " + fmt(beam.wall_time_s, 3) + " s");
  return id;
}

/// The scene's fits (the joint one, then one per record with Identify/Per record), each restored
/// from its record under --resume, else run; the fits still to run are spread over the ranks
/// (docs/cluster.md, "identify"):
///   - one fit left, or one rank: the fits run one after the other, each spreading its own
///     independent forward runs (optimizer starts, Jacobian runs) over the ranks;
///   - several fits left on several ranks: each fit is one task (its forward runs then serial on
///     its rank), the joint fit, which runs every record, first.
/// Each fit is kept for --resume as soon as it is finished when rank 0 ran it, else by rank 0
/// after the gather (only rank 0 writes). `tasks` gets the batches with their ranks.
std::vector<identify::Identification>
run_or_restore_fits(const SceneContext& ctx, const std::vector<std::string>& units,
                    const std::vector<std::vector<analysis::TestRecord>>& of,
                    const identify::IdentifySettings& settings, const specimen::Specimen& specimen,
                    const specimen::Material& quoted, const identify::ForwardModel& forward,
                    const Fingerprint& inputs, Json& tasks) {
  auto progress = [&ctx](const std::string& line) { ctx.progress(line); };
  std::vector<std::optional<identify::Identification>> fits(units.size());
  std::vector<std::size_t> todo;
  for (std::size_t i = 0; i < units.size(); ++i)
    if (auto kept = find_finished_unit<identify::Identification>(ctx.output_dir, ctx.resume,
                                                                 units[i], inputs))
      fits[i] = std::move(*kept);
    else
      todo.push_back(i);
  const MPI_Comm comm = simulation_communicator();
  int n_ranks = 1;
  MPI_Comm_size(comm, &n_ranks);
  tasks = {{"ranks", n_ranks}, {"batches", Json::array()}};
  Json& log = tasks["batches"];
  if (todo.size() >= 2 && n_ranks > 1) {
    if (output_enabled())
      std::cerr << "fiberbridge: identify: " << todo.size() << " fits as independent tasks on "
                << n_ranks << " ranks\n";
    std::vector<double> cost;
    for (const auto i : todo)
      cost.push_back(static_cast<double>(of[i].size())); // forward runs per misfit evaluation
    const auto done = run_tasks_across_ranks(
        todo.size(),
        [&](std::size_t t) {
          const std::size_t i = todo[t];
          const auto id = fit_records(of[i], specimen, quoted, settings, progress,
                                      jobs_across_ranks(nullptr, units[i]), forward);
          keep_finished_unit(ctx.output_dir, units[i], inputs, id); // on rank 0 only
          return to_archive_bytes(id, fit_kind);
        },
        comm, cost);
    for (std::size_t t = 0; t < todo.size(); ++t) {
      const std::size_t i = todo[t];
      fits[i] = from_archive_bytes<identify::Identification>(done.output[t], fit_kind);
      if (done.rank[t] != 0) // rank 0 keeps the fits the other ranks ran
        keep_finished_unit(ctx.output_dir, units[i], inputs, *fits[i]);
    }
    log.push_back({{"fit", "all"},
                   {"what", "fits"},
                   {"tasks", todo.size()},
                   {"ranks", done.rank},
                   {"cpu_s", done.cpu_seconds}});
  } else {
    for (const auto i : todo) {
      fits[i] = fit_records(of[i], specimen, quoted, settings, progress,
                            jobs_across_ranks(&log, units[i]), forward);
      keep_finished_unit(ctx.output_dir, units[i], inputs, *fits[i]);
    }
  }
  std::vector<identify::Identification> out;
  for (auto& f : fits)
    out.push_back(std::move(*f));
  return out;
}

} // namespace

void check_identify_item(SceneContext& ctx) {
  // The forward model's own section is checked here too (the FEM's keys), before anything runs.
  forward_model_of(ctx, ctx.parameters().section<IdentifySection>("Identify"));
  // The records are small: reading them is the check of Test. When reduce runs, it reads them
  // (its check has the Test section) and hands them on; when dic runs, the records are the
  // ones it will write (its check reads the machine record).
  if (!ctx.run_items.count("reduce") && !ctx.run_items.count("dic"))
    ctx.records = scene_records(ctx);
  ctx.specimen_setup();
}

ItemOutcome run_identify_item(const SceneContext& ctx) {
  const auto& section = ctx.parameters().section<IdentifySection>("Identify");
  const identify::IdentifySettings& settings = section;
  const bool per_record = section.per_record;
  ItemOutcome out;
  const auto records_read = scene_records(ctx);
  if (records_read != ctx.records)
    out.records = records_read; // read here: later items see the same records
  const auto& records = *records_read;
  const SpecimenSetup setup = ctx.specimen_setup();
  const specimen::Specimen& specimen = setup.specimen;
  const specimen::Material& quoted = setup.material;
  // The fits: the joint one, and one per record with Identify/Per record. Each fit is a unit of
  // work that --resume restores once finished (identify_resume.h).
  const Fingerprint inputs = identify_inputs(ctx, records);
  std::vector<std::string> units = {"identify_joint"};
  std::vector<std::vector<analysis::TestRecord>> of = {records};
  const bool each_record = per_record && records.size() > 1;
  if (each_record)
    for (std::size_t k = 0; k < records.size(); ++k) {
      units.push_back("identify_record_" + std::to_string(k + 1));
      of.push_back({records[k]});
    }
  Json tasks;
  const identify::ForwardModel forward = forward_model_of(ctx, section);
  auto fits =
      run_or_restore_fits(ctx, units, of, settings, specimen, quoted, forward, inputs, tasks);
  // Written: the summary block, the tables and plots (identify_writers.cc).
  out.report["identify"] = identify_summary(fits, settings, quoted, records);
  out.report["identify"]["forward_model"] = section.forward_model;
  // Which rank ran which job (not part of the identification: the rest of the summary is the
  // same on 1 and N ranks).
  out.report["identify_tasks"] = tasks;
  auto id = std::make_shared<const identify::Identification>(std::move(fits[0]));
  write_identification(ctx, *id, out.report);
  // Handed on: later simulations get the identified law, J_tip and the first record's specimen.
  out.law = CrackLaw{std::make_shared<law::PiecewiseLinearLaw>(law::make_trilinear(id->law)),
                     id->j_tip, LawSource::identify};
  SpecimenSetup identified{specimen, quoted, SpecimenSource::identify};
  identified.specimen.initial_crack = id->records.front().initial_crack;
  identified.material.E_L = id->records.front().E_L;
  out.specimen = identified;
  out.identification = id;
  return out;
}

identify::Identification
identify_scene_records(const SceneContext& ctx,
                       const std::function<void(const std::string&)>& progress,
                       std::shared_ptr<const std::vector<analysis::TestRecord>>& records) {
  const auto& section = ctx.parameters().section<IdentifySection>("Identify");
  records = scene_records(ctx);
  const SpecimenSetup setup = ctx.specimen_setup();
  return fit_records(*records, setup.specimen, setup.material, section, progress, {},
                     forward_model_of(ctx, section));
}

void check_identified_against_simulations(const SceneContext& ctx, ItemReport& report) {
  // The identified law back through each simulation, on the first record's specimen: the load
  // misfit of the simulated P(opening) against the measured one (large displacements mapped as in
  // identify).
  const auto& rec = ctx.identification->records.front();
  const bool large = ctx.parameters().section<IdentifySection>("Identify").large_displacement;
  std::vector<SimulationAgainstRecord> checks;
  for (const auto& [name, result] : ctx.results) {
    SimulationAgainstRecord c;
    c.model = name;
    result::SimulationResult mapped = result; // geometrically linear models, mapped as in identify
    if (large)
      identify::with_large_displacements(mapped, ctx.specimen().arm_thickness());
    identify::model_at_openings(mapped, rec.opening, c.load, c.a);
    // Only the rows the simulation reached (the FEM stops at steady state).
    const double reached = mapped.rcurve.back().load_point_opening;
    double sum = 0;
    for (; c.compared < c.load.size() && rec.opening[c.compared] <= reached; ++c.compared)
      sum += std::pow(c.load[c.compared] - rec.load[c.compared], 2);
    c.load_rms_rel = std::sqrt(sum / std::max<std::size_t>(c.compared, 1)) / rec.peak_load;
    c.final_a = result.rcurve.back().a;
    checks.push_back(std::move(c));
  }
  write_identified_against_simulations(ctx, rec, checks, report);
}

} // namespace fiberbridge::app
