// Scene item `identify` (section Identify): the trilinear law and J_tip for which the beam model
// reproduces the records of the Test section (include/fiberbridge/identify/identify.h). The
// identified law, J_tip and the effective specimen (first record's a0 and calibrated E_L) are
// handed to the simulations that follow, as `fit` hands its law.
#include "fiberbridge/app/identify_resume.h"
#include "fiberbridge/app/items.h"
#include "fiberbridge/app/scene.h"
#include "fiberbridge/app/section.h"
#include "fiberbridge/app/task_distributor.h"
#include "fiberbridge/app/test_section.h"
#include "fiberbridge/core/csv.h"
#include "fiberbridge/core/error.h"
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
    validate("Identify");
  }
};

void declare_identify_section(dealii::ParameterHandler& prm) {
  declare_section<IdentifySection>(prm, "Identify");
}

namespace {

/// What a fit's bytes hold when it crosses from the rank that ran it (core/binary_archive.h).
const char* fit_kind = "fiberbridge identify fit";

/// A record name as a gnuplot title (enhanced text would turn '_' into a subscript).
std::string title_of(std::string name) {
  std::replace(name.begin(), name.end(), '_', ' ');
  return name;
}

/// The records of the Test section, read once: `reduce`'s (it ran before, scene order), else
/// read here, as reduce reads them, and kept in the context (identify's check reads them, its run
/// fits them).
const std::vector<analysis::TestRecord>& scene_records(SceneContext& ctx) {
  if (!ctx.records) {
    const auto test = parse_section<TestSection>(*ctx.prm, "Test");
    const analysis::RecordReadOptions read = test.read_options(ctx.scene_file);
    auto records = std::make_shared<std::vector<analysis::TestRecord>>();
    for (const auto& path : test.resolved_files(ctx.scene_file))
      for (auto& r : analysis::read_test_records(path, read))
        records->push_back(std::move(r));
    ctx.records = std::move(records);
  }
  if (ctx.records->empty())
    throw InputError(ctx.scene_file + ": 'identify' needs records in Test/Files");
  return *ctx.records;
}

Json identification_json(const identify::Identification& id) {
  Json j = Json::object();
  j["trilinear"] = {{"d1_mm", id.law.d1 / mm},
                    {"sigma1_kPa", id.law.s1 / kPa},
                    {"d2_mm", id.law.d2 / mm},
                    {"sigma2_kPa", id.law.s2 / kPa},
                    {"delta_c_mm", id.law.dc / mm}};
  j["J_tip_J_m2"] = id.j_tip;
  j["G_ss_J_m2"] = id.g_ss;
  j["load_rms_rel"] = id.load_rms_rel;
  j["crack_rms_mm"] = id.crack_rms / mm;
  j["evaluations"] = id.evaluations;
  j["wall_time_s"] = id.wall_time_s;
  j["J_c_J_m2"] = id.law.area();
  j["J_c_std_error_J_m2"] = json_number(id.j_c_std_error);
  Json se = Json::object();
  for (const auto& p : id.parameters)
    se[p.name] = json_number(p.std_error);
  j["std_error"] = se;
  Json corr = Json::array();
  for (const auto& row : id.correlation) {
    Json r = Json::array();
    for (double v : row)
      r.push_back(json_number(v));
    corr.push_back(r);
  }
  j["correlation"] = {{"order", {"d1", "sigma1", "d2", "sigma2", "delta_c", "J_tip"}},
                      {"matrix", corr}};
  j["chi2"] = id.chi2;
  j["n_residuals"] = id.n_residuals;
  j["forward_runs"] = id.forward_runs;
  j["forward_time_s"] = id.forward_time_s;
  Json recs = Json::array();
  for (const auto& r : id.records)
    recs.push_back({{"record", r.name},
                    {"a0_mm", r.initial_crack / mm},
                    {"initial_compliance_mm_N", r.initial_compliance / mm},
                    {"E_L_effective_GPa", r.E_L * 1e-9},
                    {"peak_load_N", r.peak_load},
                    {"load_rms_rel", r.load_rms_rel},
                    {"crack_rms_mm", r.crack_rms / mm},
                    {"max_opening_over_a", r.max_opening_over_a},
                    {"min_F", r.min_F}});
  j["records"] = recs;
  j["notes"] = id.notes;
  return j;
}

void write_identification(SceneContext& ctx, const identify::Identification& id) {
  {
    CsvWriter w(ctx.out("identify_fit.csv"),
                {"record", "opening_mm", "load_N", "model_load_N", "a_mm", "model_a_mm"},
                {"measured rows and the identified beam model at the same openings"});
    for (const auto& r : id.records)
      for (std::size_t i = 0; i < r.opening.size(); ++i)
        w.row({r.name}, {r.opening[i] / mm, r.load[i], r.model_load[i], r.crack_length[i] / mm,
                         r.model_crack_length[i] / mm});
    w.close();
  }
  {
    CsvWriter w(ctx.out("identify_law.csv"),
                {"delta_mm", "sigma_kPa", "sigma_lo_kPa", "sigma_hi_kPa"},
                {"identified trilinear law with a one-standard-error band (Jacobian covariance)"});
    for (std::size_t i = 0; i < id.band_delta.size(); ++i)
      w.row({id.band_delta[i] / mm, id.band_sigma[i] / kPa, id.band_lo[i] / kPa,
             id.band_hi[i] / kPa});
    w.close();
  }
  // One curve per record: gnuplot's 'every' cannot select by label, so each record is a block.
  std::string load_plot, crack_plot;
  for (std::size_t k = 0; k < id.records.size(); ++k) {
    const std::string file = "identify_fit_" + std::to_string(k) + ".csv";
    CsvWriter w(ctx.out(file), {"opening_mm", "load_N", "model_load_N", "a_mm", "model_a_mm"});
    const auto& r = id.records[k];
    for (std::size_t i = 0; i < r.opening.size(); ++i)
      w.row({r.opening[i] / mm, r.load[i], r.model_load[i], r.crack_length[i] / mm,
             r.model_crack_length[i] / mm});
    w.close();
    const std::string sep = k ? ", " : "plot ";
    load_plot += sep + "'" + file + "' using 1:2 with points pt 7 ps 0.4 lc " +
                 std::to_string(k + 1) + " title '" + title_of(r.name) + " measured', '" + file +
                 "' using 1:3 with lines lw 2 lc " + std::to_string(k + 1) + " title 'model'";
    crack_plot += sep + "'" + file + "' using 1:4 with points pt 7 ps 0.4 lc " +
                  std::to_string(k + 1) + " title '" + title_of(r.name) + " readings', '" + file +
                  "' using 1:5 with lines lw 2 lc " + std::to_string(k + 1) + " title 'model'";
  }
  const std::string head = "set datafile separator ','\nset key autotitle columnhead\n";
  auto plot = [&](const std::string& png, const std::string& body) {
    if (run_gnuplot(ctx.output_dir, gnuplot_png_preamble(png) + head + body))
      ctx.summary["plots"].push_back(png);
  };
  // Headroom above the highest load of any record (gnuplot's autoscale stops at the next tic and
  // cut DCB-01's peak at 100 N), the key top right, away from the rising branches.
  double peak = 0;
  for (const auto& r : id.records)
    peak = std::max(peak, r.peak_load);
  plot("identify_load_opening.png",
       "set title 'identify: measured and simulated P(opening)'\nset xlabel 'load-line opening "
       "(mm)'\nset ylabel 'load (N)'\nset key top right\nset yrange [0:" +
           std::to_string(1.1 * peak) + "]\n" + load_plot + "\n");
  plot("identify_crack_opening.png",
       "set title 'identify: measured and simulated a(opening)'\nset xlabel 'load-line opening "
       "(mm)'\nset ylabel 'crack length (mm)'\nset key bottom right\n" +
           crack_plot + "\n");
  plot("identify_law.png",
       "set title 'identified law, one-standard-error band'\nset xlabel 'opening {/Symbol d} "
       "(mm)'\nset ylabel '{/Symbol s} (kPa)'\nplot 'identify_law.csv' using 1:3:4 with "
       "filledcurves fs transparent solid 0.3 title 'band', '' using 1:2 with lines lw 2 title "
       "'identified'\n");
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
run_or_restore_fits(SceneContext& ctx, const std::vector<std::string>& units,
                    const std::vector<std::vector<analysis::TestRecord>>& of,
                    const identify::IdentifySettings& settings, const specimen::Specimen& specimen,
                    const specimen::Material& quoted, const Fingerprint& inputs, Json& tasks) {
  auto progress = [](const std::string& line) { std::cerr << line << "\n"; };
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
          const auto id = identify::identify_law(of[i], specimen, quoted, settings, progress,
                                                 jobs_across_ranks(nullptr, units[i]));
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
      fits[i] = identify::identify_law(of[i], specimen, quoted, settings, progress,
                                       jobs_across_ranks(&log, units[i]));
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
  parse_section<IdentifySection>(*ctx.prm, "Identify");
  // The records are small: reading them is the check of Test. When reduce runs, it reads them
  // (its check has the Test section) and hands them on.
  if (!ctx.run_items.count("reduce"))
    scene_records(ctx);
  ctx.specimen_setup();
}

void run_identify_item(SceneContext& ctx) {
  const auto section = parse_section<IdentifySection>(*ctx.prm, "Identify");
  const identify::IdentifySettings& settings = section;
  const bool per_record = section.per_record;
  const auto& records = scene_records(ctx);
  const SpecimenSetup setup = ctx.specimen_setup();
  const specimen::Specimen& specimen = setup.specimen;
  const specimen::Material& quoted = setup.material;
  // Each fit is a unit of work that --resume restores once finished (identify_resume.h).
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
  auto fits = run_or_restore_fits(ctx, units, of, settings, specimen, quoted, inputs, tasks);
  auto id = std::make_shared<identify::Identification>(std::move(fits[0]));
  Json block = identification_json(*id);
  block["modulus"] = settings.calibrate_modulus
                         ? "E_L calibrated per record from the initial compliance (CBT)"
                         : "E_L as quoted (Material/E_L)";
  block["E_L_quoted_GPa"] = quoted.E_L * 1e-9;
  if (std::all_of(records.begin(), records.end(),
                  [](const analysis::TestRecord& r) { return !r.delta_root.empty(); }))
    block["notes"].push_back("delta_root measured: with 'extract' in Run (after reduce) the "
                             "scene compares Eq. 5/6, dR/ddelta and this law (law_routes)");
  if (each_record) {
    Json each = Json::array();
    for (std::size_t k = 0; k < records.size(); ++k) {
      Json j = identification_json(fits[k + 1]);
      j["record"] = records[k].name;
      each.push_back(j);
    }
    block["per_record"] = each;
  }
  ctx.summary["identify"] = block;
  // Which rank ran which job (not part of the identification: the rest of the summary is the
  // same on 1 and N ranks).
  ctx.summary["identify_tasks"] = tasks;
  write_identification(ctx, *id);
  // Later simulations get the identified law, J_tip and the first record's specimen.
  ctx.handed_law = CrackLaw{std::make_shared<law::PiecewiseLinearLaw>(law::make_trilinear(id->law)),
                            id->j_tip, LawSource::identify};
  SpecimenSetup identified{specimen, quoted, SpecimenSource::identify};
  identified.specimen.initial_crack = id->records.front().initial_crack;
  identified.material.E_L = id->records.front().E_L;
  ctx.handed_specimen = identified;
  ctx.identification = id;
}

void check_identified_against_simulations(SceneContext& ctx) {
  // The identified law back through each simulation, on the first record's specimen: the load
  // misfit of the simulated P(opening) against the measured one (large displacements mapped as in
  // identify).
  const auto& rec = ctx.identification->records.front();
  const bool large = parse_section<IdentifySection>(*ctx.prm, "Identify").large_displacement;
  Json block = Json::object();
  std::string plot = "plot 'identify_fit_0.csv' using 1:2 with points pt 7 ps 0.4 title '" +
                     title_of(rec.name) + " measured'";
  for (const auto& [name, result] : ctx.results) {
    std::vector<double> load, a;
    result::SimulationResult mapped = result; // geometrically linear models, mapped as in identify
    if (large)
      identify::with_large_displacements(mapped, ctx.specimen().arm_thickness());
    identify::model_at_openings(mapped, rec.opening, load, a);
    double sum = 0;
    const std::string file = "identify_check_" + name + ".csv";
    CsvWriter w(ctx.out(file), {"opening_mm", "load_N", "model_load_N", "a_mm", "model_a_mm"},
                {name + " with the identified law at the record's openings"});
    // Only the rows the simulation reached (the FEM stops at steady state).
    const double reached = mapped.rcurve.back().load_point_opening;
    std::size_t n = 0;
    for (std::size_t i = 0; i < load.size() && rec.opening[i] <= reached; ++i, ++n) {
      sum += std::pow(load[i] - rec.load[i], 2);
      w.row({rec.opening[i] / mm, rec.load[i], load[i],
             (rec.crack_length.empty() ? NAN : rec.crack_length[i]) / mm, a[i] / mm});
    }
    w.close();
    block[name] = {{"record", rec.name},
                   {"load_rms_rel", std::sqrt(sum / std::max<std::size_t>(n, 1)) / rec.peak_load},
                   {"rows_compared", n},
                   {"rows", load.size()},
                   {"final_a_mm", result.rcurve.back().a / mm}};
    plot += ", '" + file + "' using 1:3 with lines lw 2 title '" + name + "'";
  }
  ctx.summary["identify_check"] = block;
  // The simulations' R(a) beside the record's measured R(a) when `reduce` ran in this scene.
  if (std::filesystem::exists(ctx.out("rcurve_test.csv"))) {
    std::string r_plot = "plot 'rcurve_test.csv' using 2:(strcol(1) eq '" + rec.name +
                         "' ? $4 : NaN) every ::1 with points pt 7 ps 0.5 title '" +
                         title_of(rec.name) + " R_{energy} measured', '' using 2:(strcol(1) eq '" +
                         rec.name +
                         "' ? $7 : NaN) every ::1 with points pt 6 ps 0.5 title 'R_{MBT} measured'";
    for (const auto& [name, result] : ctx.results)
      r_plot += ", 'rcurve_" + name + ".csv' using 1:4 every ::1 with lines lw 2 title '" + name +
                " R_J, identified law'";
    if (run_gnuplot(ctx.output_dir,
                    gnuplot_png_preamble("identify_check_R_a.png") +
                        "set datafile separator ','\nset title 'identified law in the "
                        "simulations against the measured R(a)'\nset xlabel 'crack length a "
                        "(mm)'\nset ylabel 'R (J/m^2)'\nset key bottom right\n" +
                        r_plot + "\n"))
      ctx.summary["plots"].push_back("identify_check_R_a.png");
  }
  if (run_gnuplot(ctx.output_dir,
                  gnuplot_png_preamble("identify_check_load.png") +
                      "set datafile separator ','\nset title 'identified law in the "
                      "simulations against the record'\nset xlabel 'load-line opening (mm)'\n"
                      "set ylabel 'load (N)'\n" +
                      plot + "\n"))
    ctx.summary["plots"].push_back("identify_check_load.png");
}

} // namespace fiberbridge::app
