// Scene item `programme study` (issue 39 item 5; docs/design.md section 3, "The programme,
// simulated"): the seed's experiment run end to end with known answers. From the Table 1 laws it
// makes a campaign of virtual specimens (each group's sigma1 and sigma2 scattered around its law, a
// fixed seed), each specimen a FEM virtual test (FEM/Virtual DIC) and so a DIC set (a manifest row
// whose file is a folder), then runs the campaign item on that manifest through the scene runner as
// a user would, and compares the groups' laws and intervals with the truth. The campaign's time is
// measured apart from the FEM's.
#include "items/chain_study_item.h"
#include "items/virtual_test_run.h"
#include "outputs/programme_study_writers.h"

#include "fiberbridge/analysis/campaign_synthetic.h"
#include "fiberbridge/app/run/scene_runner.h"
#include "fiberbridge/app/scene/scene_reader.h"
#include "fiberbridge/app/scene/section.h"
#include "fiberbridge/core/clock.h"
#include "fiberbridge/core/csv.h"
#include "fiberbridge/core/error.h"
#include "fiberbridge/core/format.h"
#include "fiberbridge/core/units.h"

#include <deal.II/base/patterns.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <random>
#include <sstream>

namespace fiberbridge::app {

using namespace units;

namespace {

namespace fs = std::filesystem;

struct ProgrammeStudySection {
  std::string table1;
  int specimens = 4;
  double stress_cv = 0.08;
  unsigned seed = 1;
  bool reuse = true;
  std::vector<std::string> campaign_sets;

  static void declare_parameters(dealii::ParameterHandler& prm) {
    prm.declare_entry("Table 1", "data/reference/seed_table1.csv", dealii::Patterns::Anything(),
                      "The groups' laws (seed_table1.csv's format; d1 0.1 mm, d2 1.0 mm, delta_c "
                      "PVA 6 mm, others 3.5 mm).");
    prm.declare_entry("Specimens per group", "4", dealii::Patterns::Integer(1, 100),
                      "Virtual specimens (DIC sets) per group.");
    prm.declare_entry("Scatter", "0.08", dealii::Patterns::Double(0, 0.4),
                      "Specimen scatter: sigma1 and sigma2 times 1 + Scatter z (z standard normal "
                      "clipped to +-2.5), as the synthetic campaign does.");
    prm.declare_entry("Seed", "1", dealii::Patterns::Integer(0), "Seed of the scatter.");
    prm.declare_entry("Reuse virtual tests", "true", dealii::Patterns::Bool(),
                      "Keep a specimen's virtual test from an earlier run into the same output "
                      "directory when it was made with the same settings (the FEM is the slow "
                      "part; the campaign always runs).");
    prm.declare_entry("Campaign settings", "", dealii::Patterns::Anything(),
                      "Settings \"Section/Key=value\" separated by ';' for the campaign's scene "
                      "(e.g. Campaign/Bootstrap samples=200).");
  }
  void parse_parameters(dealii::ParameterHandler& prm) {
    table1 = prm.get("Table 1");
    specimens = prm.get_integer("Specimens per group");
    stress_cv = prm.get_double("Scatter");
    seed = static_cast<unsigned>(prm.get_integer("Seed"));
    reuse = prm.get_bool("Reuse virtual tests");
    campaign_sets = split_list(prm.get("Campaign settings"), ';');
  }
};

std::string read_text(const std::string& path) {
  std::ifstream f(path);
  std::ostringstream s;
  s << f.rdbuf();
  return s.str();
}

struct Specimen {
  std::string name, material, label;
  double cycles = 0, s1 = 0, s2 = 0, dc = 0; // kPa, mm
  std::vector<std::string> sets;
};

/// The programme's specimens: per Table 1 group, `n` laws scattered around the group's (one
/// generator in the table's order: the same seed gives the same programme).
std::vector<Specimen> make_specimens(const std::vector<analysis::SyntheticGroupTruth>& truth,
                                     const ProgrammeStudySection& s) {
  std::mt19937 rng(s.seed);
  std::normal_distribution<double> normal;
  auto factor = [&] { return 1 + s.stress_cv * std::clamp(normal(rng), -2.5, 2.5); };
  std::vector<Specimen> out;
  for (const auto& t : truth)
    for (int k = 1; k <= s.specimens; ++k) {
      Specimen p;
      p.material = t.material;
      p.cycles = t.cycles;
      p.label = "s" + std::to_string(k);
      p.name = t.material + "_c" + fmt(t.cycles) + "_" + p.label;
      p.s1 = t.law.s1 / kPa * factor();
      p.s2 = t.law.s2 / kPa * factor();
      p.dc = t.law.dc / mm;
      p.sets = {"Cohesive law/Type=trilinear",
                "Cohesive law/Points=0.1:" + fmt(p.s1, 10) + ", 1.0:" + fmt(p.s2, 10),
                "Cohesive law/Delta c=" + fmt(p.dc, 10), "Cohesive law/J tip=" + fmt(t.j_tip, 10)};
      out.push_back(p);
    }
  return out;
}

/// The campaign's scene: the first set's dic_scene.prm (its Specimen, Material, DIC and Test
/// sections hold for every set: they are laid out alike) with the Campaign section added.
std::string write_campaign_scene(const std::string& first_set, const std::string& manifest,
                                 const std::string& path) {
  std::string scene = read_text(first_set + "/dic_scene.prm");
  if (scene.empty())
    throw ComputationError("programme study: the virtual test left no " + first_set +
                           "/dic_scene.prm");
  scene += "\nsubsection Campaign\n  set Manifest = " + manifest + "\nend\n";
  std::ofstream(path) << scene;
  return path;
}

/// The campaign's groups and ranking from its summary.json.
void read_campaign(const std::string& summary_path, ProgrammeOutcome& o) {
  std::ifstream f(summary_path);
  if (!f)
    throw ComputationError("programme study: the campaign left no " + summary_path);
  const Json s = Json::parse(f);
  const Json& c = s.at("campaign");
  auto num_of = [](const Json& j) { return j.is_number() ? j.get<double>() : std::nan(""); };
  for (const auto& g : c.at("groups")) {
    for (auto& pg : o.groups) {
      if (pg.material != g.at("material").get<std::string>() ||
          pg.cycles != g.at("cycles").get<double>())
        continue;
      pg.ok = g.value("ok", false);
      pg.sigma1 = num_of(g["trilinear"]["sigma1_kPa"]);
      pg.sigma2 = num_of(g["trilinear"]["sigma2_kPa"]);
      pg.delta_c = num_of(g["trilinear"]["delta_c_mm"]);
      pg.j_tip = num_of(g["J_tip_J_m2"]);
      pg.g_ss = num_of(g["G_ss_J_m2"]);
      pg.sigma1_lo = num_of(g["ci"]["sigma1_kPa"][0]);
      pg.sigma1_hi = num_of(g["ci"]["sigma1_kPa"][1]);
      pg.sigma2_lo = num_of(g["ci"]["sigma2_kPa"][0]);
      pg.sigma2_hi = num_of(g["ci"]["sigma2_kPa"][1]);
    }
  }
  for (const auto& m : c.at("ranking"))
    o.ranking.push_back(m.get<std::string>());
}

} // namespace

void declare_programme_study_section(dealii::ParameterHandler& prm) {
  declare_section<ProgrammeStudySection>(prm, "Programme study");
}

void parse_programme_study_section(dealii::ParameterHandler& prm, SceneParameters& out) {
  parse_into<ProgrammeStudySection>(prm, "Programme study", out);
}

void check_programme_study_item(SceneContext& ctx) {
  const auto& s = ctx.parameters().section<ProgrammeStudySection>("Programme study");
  analysis::table1_truth(
      analysis::read_property_table(resolve_scene_path(s.table1, ctx.scene_file)));
}

ItemOutcome run_programme_study_item(const SceneContext& ctx) {
  const auto& s = ctx.parameters().section<ProgrammeStudySection>("Programme study");
  const auto truth = analysis::table1_truth(
      analysis::read_property_table(resolve_scene_path(s.table1, ctx.scene_file)));
  const auto specimens = make_specimens(truth, s);

  ProgrammeOutcome o;
  o.expected_ranking = {"PF", "EPI", "PRF", "PVA"};
  for (const auto& t : truth) {
    ProgrammeGroup g;
    g.material = t.material;
    g.cycles = t.cycles;
    g.sigma1_true = t.law.s1 / kPa;
    g.sigma2_true = t.law.s2 / kPa;
    g.delta_c_true = t.law.dc / mm;
    g.j_tip_true = t.j_tip;
    g.g_ss_true = t.j_tip + t.law.area();
    g.sigma1 = g.sigma2 = g.j_tip = g.g_ss = g.delta_c = std::nan("");
    g.sigma1_lo = g.sigma1_hi = g.sigma2_lo = g.sigma2_hi = std::nan("");
    for (const auto& p : specimens)
      if (p.material == t.material && p.cycles == t.cycles) {
        ++g.n_specimens;
        g.sigma1_specimen_mean += p.s1 / s.specimens;
        g.sigma2_specimen_mean += p.s2 / s.specimens;
      }
    o.groups.push_back(g);
  }

  // The FEM: one virtual test per specimen, one after the other (the FEM with a virtual DIC runs
  // on one MPI rank; docs/design.md, "Virtual DIC test").
  const std::string sets_dir = fs::absolute(ctx.out("virtual_specimens")).string();
  fs::create_directories(sets_dir);
  const std::string manifest = sets_dir + "/manifest.csv";
  auto t0 = std::chrono::steady_clock::now();
  {
    CsvWriter m(manifest, {"file", "material", "specimen", "cycles", "delta_c_mm"},
                {"Simulated programme (not measured): each row a DIC set, the FEM virtual test of "
                 "its specimen's law (Table 1's group law, sigma1 and sigma2 times 1 + " +
                 fmt(s.stress_cv) + " z, seed " + std::to_string(s.seed) + ")"});
    for (const auto& p : specimens) {
      const std::string dir = sets_dir + "/" + p.name;
      o.n_generated += run_virtual_test(ctx, p.sets, dir, s.reuse);
      ++o.n_sets;
      ctx.progress("programme study: " + p.name + " ready");
      m.row({p.name + "/virtual_test", p.material, p.label}, {p.cycles, p.dc});
    }
    m.close();
  }
  o.generation_wall_s = seconds_since(t0);

  // The campaign as a user runs it on the 80 DIC sets.
  o.campaign_dir = fs::absolute(ctx.out("campaign")).string();
  const std::string scene =
      write_campaign_scene(sets_dir + "/" + specimens.front().name + "/virtual_test", manifest,
                           sets_dir + "/campaign_scene.prm");
  std::vector<std::string> sets = s.campaign_sets;
  sets.push_back("Run=campaign");
  sets.push_back("Output directory=" + o.campaign_dir);
  t0 = std::chrono::steady_clock::now();
  try {
    run_scene(scene, sets, false, ctx.progress_sink);
    read_campaign(o.campaign_dir + "/summary.json", o);
  } catch (const std::exception& e) {
    // The campaign's refusal is the study's finding (its reason in the table), not a crash.
    o.refusal = e.what();
  }
  o.campaign_wall_s = seconds_since(t0);
  ItemOutcome out;
  write_programme_study(ctx, o, out.report);
  return out;
}

} // namespace fiberbridge::app
