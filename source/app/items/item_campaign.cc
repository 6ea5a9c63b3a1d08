// Scene item `campaign` (section Campaign; issue 33): a durability campaign from its manifest to
// the paper's Table 1 and ranking with bootstrap intervals (analysis/campaign_run.h), written by
// campaign_writers.h. The Data, Fit and Bridging sections give every group's defaults; the Test
// section and Specimen say how raw records are read and reduced. Groups run as independent tasks
// over the MPI ranks (task_distributor.h); each group's numbers depend only on its specimens,
// the options and its own seed, so 1 and N ranks give the same tables.
#include "fiberbridge/analysis/campaign.h"
#include "fiberbridge/analysis/campaign_run.h"
#include "fiberbridge/app/items/analysis_steps.h"
#include "fiberbridge/app/items/campaign_dic.h"
#include "fiberbridge/app/items/campaign_simulation.h"
#include "fiberbridge/app/items/items.h"
#include "fiberbridge/app/outputs/campaign_simulation_writers.h"
#include "fiberbridge/app/outputs/campaign_writers.h"
#include "fiberbridge/app/run/campaign_resume.h"
#include "fiberbridge/app/run/task_distributor.h"
#include "fiberbridge/app/scene/dic_section.h"
#include "fiberbridge/app/scene/scene_reader.h"
#include "fiberbridge/app/scene/section.h"
#include "fiberbridge/app/scene/test_section.h"
#include "fiberbridge/core/clock.h"
#include "fiberbridge/core/csv.h"
#include "fiberbridge/core/error.h"
#include "fiberbridge/core/format.h"
#include "fiberbridge/core/output_guard.h"
#include "fiberbridge/core/units.h"

#include <deal.II/base/patterns.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <map>
#include <memory>
#include <sstream>
#ifdef FIBERBRIDGE_HAVE_IDENTIFY
#include "fiberbridge/app/items/fit_correction_step.h"
#endif

namespace fiberbridge::app {

using units::mm;

namespace {

/// Campaign: the manifest and the bootstrap.
struct CampaignSection {
  std::string manifest;
  int bootstrap_samples = 1000;
  unsigned seed = 1;
  double confidence = 0.95;
  analysis::CampaignOptions::Interval interval = analysis::CampaignOptions::Interval::student_t;
  std::vector<std::string> reference_materials;
  double outlier_mads = 3.5;
  double chain_u_G_ss = analysis::CampaignOptions{}.chain_u_G_ss;
  double chain_u_J_tip = analysis::CampaignOptions{}.chain_u_J_tip;
  bool fe_export = true;
  bool simulate = false;
  std::string model;
  std::string ra_estimator = "energy";

  static void declare_parameters(dealii::ParameterHandler& prm) {
    prm.declare_entry("Manifest", "", dealii::Patterns::Anything(),
                      "CSV with columns file, material, cycles, specimen (one row per specimen; "
                      "optional delta_c_mm, j_tip_J_m2, width_mm, arm_thickness_mm, a0_mm, "
                      "length_mm); files relative to the manifest: R(delta) tables, raw test "
                      "records, or folders of DIC sets (frames named by DIC/Frames and the "
                      "machine record by Test/Files inside each folder).");
    prm.declare_entry("Bootstrap samples", "1000", dealii::Patterns::Integer(0, 1000000),
                      "Resamples of whole specimens within each group (0: no intervals).");
    prm.declare_entry("Seed", "1", dealii::Patterns::Integer(0, 2147483647),
                      "Seed of the bootstrap; each group mixes it with its (material, cycles).");
    prm.declare_entry("Confidence level", "0.95", dealii::Patterns::Double(0.5, 0.999),
                      "Level of every interval.");
    prm.declare_entry("Interval", "student t",
                      dealii::Patterns::Selection("student t|expanded percentile|percentile"),
                      "Bootstrap interval: student t (estimate -+ sqrt(n/(n-1)) t_{n-1} bootstrap "
                      "standard deviations; covers its level with few specimens), expanded "
                      "percentile (Hesterberg) or percentile (docs/design.md section 1).");
    prm.declare_entry("Reference materials", "DF", dealii::Patterns::Anything(),
                      "Comma-separated materials reported beside the others but not ranked "
                      "(the seed's solid wood DF has no adhesive).");
    prm.declare_entry("Outlier threshold", "3.5", dealii::Patterns::Double(1),
                      "A specimen is named far from its group when its G_ss lies more than this "
                      "many robust standard deviations (1.4826 MAD) from the group's median.");
    const analysis::CampaignOptions defaults;
    prm.declare_entry("Chain accuracy of G_ss", fmt(defaults.chain_u_G_ss),
                      dealii::Patterns::Double(0, 1),
                      "Relative standard uncertainty of the G_ss the chain measures from a record "
                      "(the RMS error on the virtual tests of the 20 Table 1 laws, "
                      "docs/verification.md). Added in quadrature to the replicates' intervals of "
                      "groups of records with delta_root (raw records or DIC sets), through the "
                      "bridging area G_ss - J_tip to the law's stresses; 0 with the J_tip entry: "
                      "the replicates alone.");
    prm.declare_entry("Chain accuracy of J_tip", fmt(defaults.chain_u_J_tip),
                      dealii::Patterns::Double(0, 1),
                      "Relative standard uncertainty of the J_tip the chain measures from a "
                      "record (as Chain accuracy of G_ss).");
    prm.declare_entry("FE export", "true", dealii::Patterns::Bool(),
                      "Write each group's trilinear law for LS-DYNA (MAT_186) and Abaqus.");
    prm.declare_entry("Simulate laws", "false", dealii::Patterns::Bool(),
                      "Put each group's law back in the specimen (the paper's Fig. 10): the "
                      "simulated R(delta_root) against the group's measured curves, misfit per "
                      "group. Uses the Specimen, Material and the model's section.");
    prm.declare_entry("R(a) estimator", "energy",
                      dealii::Patterns::Selection("energy|MBT|CC|MCC|CBBM"),
                      "What gives the initiation (J_tip) and plateau (G_ss) of a raw record "
                      "without notch-root opening: direct energy, ASTM D5528 MBT, CC, MCC, or CBBM "
                      "(equivalent crack). The others are reported beside it in "
                      "campaign_specimens.csv, with a note where they disagree beyond the "
                      "direct-energy band (docs/design.md, \"Durability campaign\").");
    prm.declare_entry("Simulation model", "auto", dealii::Patterns::Anything(),
                      "Model for Simulate laws: auto (the FEM when built, else the cheapest built "
                      "model) or a model's name (fem, beam, mpm), run with its own section.");
  }
  void parse_parameters(dealii::ParameterHandler& prm) {
    manifest = prm.get("Manifest");
    bootstrap_samples = prm.get_integer("Bootstrap samples");
    seed = static_cast<unsigned>(prm.get_integer("Seed"));
    confidence = prm.get_double("Confidence level");
    const std::string iv = prm.get("Interval");
    interval = iv == "percentile" ? analysis::CampaignOptions::Interval::percentile
               : iv == "expanded percentile"
                   ? analysis::CampaignOptions::Interval::expanded_percentile
                   : analysis::CampaignOptions::Interval::student_t;
    outlier_mads = prm.get_double("Outlier threshold");
    chain_u_G_ss = prm.get_double("Chain accuracy of G_ss");
    chain_u_J_tip = prm.get_double("Chain accuracy of J_tip");
    fe_export = prm.get_bool("FE export");
    simulate = prm.get_bool("Simulate laws");
    model = prm.get("Simulation model");
    ra_estimator = prm.get("R(a) estimator");
    const auto models = campaign_simulation_models();
    if (simulate) {
      if (model == "auto" && !models.empty())
        model = models.front();
      if (std::find(models.begin(), models.end(), model) == models.end()) {
        std::string have;
        for (const auto& m : models)
          have += (have.empty() ? "" : ", ") + m;
        throw InputError("Campaign/Simulation model: '" + model +
                         "' cannot put the laws back in the specimen in this build (available: " +
                         (have.empty() ? std::string("none") : have) + ")");
      }
    }
    for (auto& m : split_list(prm.get("Reference materials"), ','))
      reference_materials.push_back(std::move(m));
    if (manifest.empty())
      throw InputError("Campaign/Manifest: the scene runs 'campaign' but names no manifest");
  }
};

/// "auto" or a positive number times `unit`; 0 for auto (the Data section's convention).
double auto_or_positive(const std::string& v, const std::string& key, double unit) {
  if (v == "auto")
    return 0;
  char* end = nullptr;
  const double x = std::strtod(v.c_str(), &end);
  if (end == v.c_str() || *end != '\0' || !(x > 0) || !std::isfinite(x))
    throw InputError(key + ": expected 'auto' or a positive number, got '" + v + "'");
  return x * unit;
}

/// The name the group defaults are kept under in the scene's parameters (parse_campaign_section).
const std::string group_defaults_entry = "Campaign: group defaults";

/// The group defaults from the Data, Fit and Bridging sections. Their section structs are local
/// to items_analysis.cc, so the keys are read here as declared there, once, when the scene is read
/// (read only: nothing is written back into the handler).
analysis::CampaignOptions group_defaults(dealii::ParameterHandler& prm) {
  analysis::CampaignOptions o;
  prm.enter_subsection("Data");
  o.intervals = prm.get_integer("Intervals");
  o.half_width = prm.get_integer("Smoothing half-width");
  o.grid_points = prm.get_integer("Averaging grid points");
  const std::string dc = prm.get("Delta c"), jt = prm.get("J tip");
  prm.leave_subsection();
  o.delta_c = auto_or_positive(dc, "Data/Delta c", mm);
  o.j_tip = auto_or_positive(jt, "Data/J tip", 1.0);
  if (o.half_width < 1 || 2 * o.half_width >= o.intervals)
    throw InputError("Data/Smoothing half-width: must lie in [1, intervals/2), got " +
                     std::to_string(o.half_width));
  prm.enter_subsection("Fit");
  o.d1 = prm.get_double("Delta 1") * mm;
  o.d2 = prm.get_double("Delta 2") * mm;
  o.free_breakpoints = prm.get_bool("Free breakpoints");
  o.d1_min = prm.get_double("Delta 1 minimum") * mm;
  o.d1_max = prm.get_double("Delta 1 maximum") * mm;
  o.d2_max = prm.get_double("Delta 2 maximum") * mm;
  prm.leave_subsection();
  if (!o.free_breakpoints && !(o.d1 > 0 && o.d1 < o.d2))
    throw InputError("Fit/Delta 1, Delta 2: need 0 < Delta 1 < Delta 2 (mm), got " +
                     fmt(o.d1 / mm) + " and " + fmt(o.d2 / mm));
  // rho_b's range (seed section 3.4): the Bridging section's fiber at its peeling toughness
  // against the seed's fiber bundle at 50 J/m^2, at the Bridging section's opening.
  prm.enter_subsection("Bridging");
  o.fiber_low.E_f = prm.get_double("Fiber modulus") * units::GPa;
  o.fiber_low.r_f = prm.get_double("Fiber radius") * units::um;
  o.fiber_low.sigma_fb = prm.get_double("Fiber strength") * units::MPa;
  o.fiber_low.G_c = prm.get_double("Peeling toughness");
  o.rho_opening = prm.get_double("Opening") * mm;
  prm.leave_subsection();
  return o;
}

struct CampaignInputs {
  std::string manifest_path;
  CampaignSection section;
  analysis::CampaignOptions options;
  analysis::RawRecordOptions raw;
  /// The test records the DIC sets made (dic_record.csv's text), by manifest line: written
  /// beside the tables as campaign_dic_<material>_c<cycles>_<specimen>.csv.
  std::shared_ptr<std::map<std::size_t, std::pair<std::string, std::string>>> dic_records =
      std::make_shared<std::map<std::size_t, std::pair<std::string, std::string>>>();
};

CampaignInputs campaign_inputs(const SceneContext& ctx) {
  CampaignInputs in;
  in.section = ctx.parameters().section<CampaignSection>("Campaign");
  in.manifest_path = std::filesystem::path(resolve_scene_path(in.section.manifest, ctx.scene_file))
                         .lexically_normal()
                         .string();
  if (!std::filesystem::is_regular_file(in.manifest_path))
    throw InputError(ctx.scene_file + ": Campaign/Manifest: file '" + in.section.manifest +
                     "' not found");
  in.options = ctx.parameters().section<analysis::CampaignOptions>(group_defaults_entry);
  in.options.bootstrap_samples = in.section.bootstrap_samples;
  in.options.seed = in.section.seed;
  in.options.confidence = in.section.confidence;
  in.options.interval = in.section.interval;
  in.options.outlier_mads = in.section.outlier_mads;
  in.options.chain_u_G_ss = in.section.chain_u_G_ss;
  in.options.chain_u_J_tip = in.section.chain_u_J_tip;
#ifdef FIBERBRIDGE_HAVE_IDENTIFY
  // Fit/Model correction: groups of records (raw or DIC sets with delta_root) corrected by
  // simulation, as a scene's fit is (items/fit_correction_step.h).
  in.options.correct_law = group_law_correction(ctx, in.options);
#endif
  // Raw records: read and reduced with the scene's one chain, as `reduce` does (a manifest row's
  // width_mm / arm_thickness_mm / length_mm / a0_mm override its Specimen).
  const auto& t = ctx.parameters().section<TestSection>("Test");
  static_cast<analysis::RecordChainOptions&>(in.raw) = ctx.record_chain();
  in.raw.estimator = analysis::parse_ra_method(in.section.ra_estimator,
                                               ctx.scene_file + ": Campaign/R(a) estimator");
  const specimen::Specimen s = ctx.specimen();
  // DIC sets (a row naming a folder): the DIC step with the DIC section, then read as a record
  // dic hands reduce (campaign_dic.h).
  CampaignDicSets sets;
  sets.dic = ctx.parameters().section<DicSection>("DIC");
  sets.test = t;
  sets.read = in.raw.read;
  sets.scene_initial_crack = s.initial_crack;
  in.raw.dic_set = [sets, texts = in.dic_records](const analysis::CampaignRow& row) {
    std::string text;
    auto record = read_campaign_dic_set(row, sets, text);
    (*texts)[row.line] = {"campaign_dic_" + analysis::group_file_stem(row.material, row.cycles) +
                              "_" + file_name_part(row.specimen) + ".csv",
                          text};
    return record;
  };
  return in;
}

/// Every group: restored from its record when resuming (campaign_resume.h), else analysed and
/// kept as it finishes. On N ranks the groups still to do run as tasks over the ranks of the
/// simulation communicator (the rank that runs a group keeps its record); every rank gets every
/// group. The point estimate is recomputed for a restored or gathered group (deterministic, a
/// fraction of the bootstrap's cost) rather than stored: it carries the averaged curve and the
/// laws the writers need.
void run_groups(std::vector<analysis::CampaignGroup>& groups,
                const std::vector<analysis::CampaignSpecimen>& specimens,
                const analysis::CampaignOptions& o, const analysis::CampaignProgress& progress,
                const SceneContext& ctx, const Fingerprint& scene) {
  std::vector<Fingerprint> inputs;
  std::vector<bool> restored(groups.size(), false);
  for (std::size_t i = 0; i < groups.size(); ++i) {
    inputs.push_back(campaign_group_inputs(scene, groups[i], specimens));
    analysis::CampaignGroup kept = groups[i];
    if (restore_campaign_group(ctx.output_dir, ctx.resume, inputs[i], kept)) {
      groups[i] = kept;
      restored[i] = true;
    }
  }
  auto finish = [&](std::size_t i) {
    auto& g = groups[i];
    g.estimate = analysis::estimate_group(specimens, g.members, o, true);
    analysis::apply_law_shift(g.estimate, g.correction, o);
    g.seed = analysis::group_seed(o.seed, g.material, g.cycles);
    if (output_enabled())
      ctx.progress("campaign: resume: group " + g.material + " at " + fmt(g.cycles) +
                   " cycles restored from " + campaign_group_record(ctx.output_dir, g));
  };
  int ranks = 1;
  MPI_Comm_size(simulation_communicator(), &ranks);
  if (ranks == 1) {
    for (std::size_t i = 0; i < groups.size(); ++i) {
      if (restored[i]) {
        finish(i);
      } else {
        analysis::analyse_campaign_group(groups[i], specimens, o);
        keep_campaign_group(ctx.output_dir, inputs[i], groups[i]);
      }
      if (progress)
        progress(i + 1, groups.size(), groups[i]);
    }
    return;
  }
  std::vector<std::size_t> todo;
  std::vector<double> cost;
  for (std::size_t i = 0; i < groups.size(); ++i)
    if (!restored[i]) {
      todo.push_back(i);
      cost.push_back(static_cast<double>(groups[i].members.size()));
    }
  const auto results = run_tasks_across_ranks(
      todo.size(),
      [&](std::size_t k) {
        analysis::CampaignGroup g = groups[todo[k]];
        analysis::analyse_campaign_group(g, specimens, o);
        const TaskOwnsItsFiles own; // its record, written by the rank that ran it
        keep_campaign_group(ctx.output_dir, inputs[todo[k]], g);
        return campaign_group_bytes(g);
      },
      simulation_communicator(), cost);
  for (std::size_t k = 0; k < todo.size(); ++k) {
    auto& g = groups[todo[k]];
    g.seed = analysis::group_seed(o.seed, g.material, g.cycles);
    campaign_group_from_bytes(results.output[k],
                              "campaign group from rank " + std::to_string(results.rank[k]), g);
    g.estimate = analysis::estimate_group(specimens, g.members, o, true);
    analysis::apply_law_shift(g.estimate, g.correction, o);
  }
  for (std::size_t i = 0; i < groups.size(); ++i) {
    if (restored[i])
      finish(i);
    if (progress)
      progress(i + 1, groups.size(), groups[i]);
  }
}

} // namespace

void declare_campaign_section(dealii::ParameterHandler& prm) {
  declare_section<CampaignSection>(prm, "Campaign");
}

void parse_campaign_section(dealii::ParameterHandler& prm, SceneParameters& out) {
  parse_into<CampaignSection>(prm, "Campaign", out);
  // The group defaults as read from Data, Fit and Bridging, kept apart from those sections'
  // own parse (group_defaults validates them its own way).
  try {
    out.store(group_defaults_entry, group_defaults(prm));
  } catch (...) {
    out.store_error(group_defaults_entry, std::current_exception());
  }
}

namespace {
/// The line a campaign gives per group ("campaign: group 3/20 PVA at 8 cycles (...), 1.2 s"), the
/// seconds counted from `t0`.
std::string group_progress_line(std::size_t done, std::size_t all, const analysis::CampaignGroup& g,
                                std::chrono::steady_clock::time_point t0) {
  const double seconds = seconds_since(t0);
  return "campaign: group " + std::to_string(done) + "/" + std::to_string(all) + " " + g.material +
         " at " + fmt(g.cycles) + " cycles (" + std::to_string(g.members.size()) + " specimens, " +
         std::to_string(g.samples.size()) + " bootstrap samples), " + fmt(seconds, 3) + " s";
}
} // namespace

analysis::CampaignResult analyse_scene_campaign(const SceneContext& ctx) {
  const CampaignInputs in = campaign_inputs(ctx);
  const auto manifest = analysis::read_campaign_manifest(in.manifest_path);
  // Lines only to a caller's sink (the Python module's, which checks for Ctrl-C there): this
  // computes without writing, to files or to the terminal.
  const auto t0 = std::chrono::steady_clock::now();
  analysis::CampaignProgress progress;
  if (ctx.progress_sink)
    progress = [&](std::size_t done, std::size_t all, const analysis::CampaignGroup& g) {
      ctx.progress(group_progress_line(done, all, g, t0));
    };
  // The default runner: every group here, in order (the same numbers as any placement).
  return analysis::analyse_campaign(manifest, in.raw, in.options, in.section.reference_materials,
                                    progress);
}

void check_campaign_item(SceneContext& ctx) {
  // The manifest's own errors (missing file, duplicates: manifest:line) before any item runs.
  analysis::read_campaign_manifest(campaign_inputs(ctx).manifest_path);
}

ItemOutcome run_campaign_item(const SceneContext& ctx) {
  const CampaignInputs in = campaign_inputs(ctx);
  const auto manifest = analysis::read_campaign_manifest(in.manifest_path);
  const auto t0 = std::chrono::steady_clock::now();
  const bool speak = output_enabled();
  auto progress = [&](std::size_t done, std::size_t all, const analysis::CampaignGroup& g) {
    if (!speak)
      return;
    ctx.progress(group_progress_line(done, all, g, t0));
  };
  int ranks = 1;
  MPI_Comm_size(simulation_communicator(), &ranks);
  // Each group is a unit of work for --resume (campaign_resume.h).
  const Fingerprint scene = scene_fingerprint(ctx.parameters());
  const analysis::GroupRunner runner = [&](std::vector<analysis::CampaignGroup>& groups,
                                           const std::vector<analysis::CampaignSpecimen>& specimens,
                                           const analysis::CampaignOptions& o,
                                           const analysis::CampaignProgress& p) {
    run_groups(groups, specimens, o, p, ctx, scene);
  };
  auto result = analysis::analyse_campaign(manifest, in.raw, in.options,
                                           in.section.reference_materials, progress, runner);
  CampaignWriteOptions w;
  w.fe_export = in.section.fe_export;
  w.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  if (in.section.simulate)
    w.simulations = simulate_campaign_laws(ctx, result, in.section.model);
  // A group whose specimens differ in geometry: the simulation says on which it ran.
  for (const auto& sim : w.simulations)
    for (auto& g : result.groups)
      if (!sim.geometry_note.empty() && g.material == sim.material && g.cycles == sim.cycles)
        g.notes.push_back(sim.geometry_note);
  // Everything is computed before the first file is written: a campaign that fails leaves no
  // table behind (and no summary.json, run/scene_runner.cc).
  if (!w.simulations.empty())
    w.simulation_pngs = write_campaign_simulation_files(result, w.simulations, ctx.output_dir);
  ItemOutcome out;
  write_campaign_outputs(result, w, ctx.output_dir, out.report);
  for (const auto& [line, file] : *in.dic_records) {
    write_file_atomically(ctx.out(file.first), file.second);
    out.report["campaign"]["dic_records"].push_back(file.first);
  }
  out.report["campaign"]["ranks"] = ranks;
  return out;
}

} // namespace fiberbridge::app
