// The campaign's laws back in the specimen (campaign_simulation.h; the paper's Fig. 10).
#include "fiberbridge/app/campaign_simulation.h"
#include "fiberbridge/analysis/campaign.h"
#include "fiberbridge/analysis/line_fit.h"

#include "fiberbridge/app/campaign_resume.h"
#include "fiberbridge/app/items.h"
#include "fiberbridge/app/models.h"
#include "fiberbridge/app/resume_store.h"
#include "fiberbridge/app/task_distributor.h"
#include "fiberbridge/core/csv.h"
#include "fiberbridge/core/error.h"
#include "fiberbridge/core/format.h"
#include "fiberbridge/core/output_guard.h"
#include "fiberbridge/core/plot.h"
#include "fiberbridge/core/units.h"
#include "fiberbridge/law/law_fingerprint.h"
#include "fiberbridge/law/piecewise_linear_law.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <sstream>

namespace fiberbridge::app {

using units::mm;

namespace {

result::SimulationResult run_model(SceneContext& ctx, const std::string& model,
                                   const law::TractionLaw& law, double j_tip) {
  // One place chooses a model by name: the registry (models.h).
  const SimulationModel* m = built_model(model);
  if (!m || !m->simulate)
    throw InputError("Campaign/Simulation model: '" + model + "' is not available in this build");
  return m->simulate(ctx, law, j_tip);
}

/// The group's simulation before it runs: its name, model and specimen (with the note on
/// differing geometry).
GroupSimulation prepare_group(const SceneContext& ctx, const analysis::CampaignResult& r,
                              const analysis::CampaignGroup& g, const std::string& model) {
  GroupSimulation s;
  s.material = g.material;
  s.cycles = g.cycles;
  s.model = model;
  s.specimen = campaign_group_specimen(ctx.specimen(), g, r.specimens, s.geometry_note);
  return s;
}

/// The context a group's simulation reads: the scene's, with the group's specimen handed on.
SceneContext group_context(const SceneContext& ctx, const GroupSimulation& s) {
  SceneContext sub = ctx.derived(ctx.output_dir, SceneContext::HandOn::everything);
  SpecimenSetup setup = ctx.specimen_setup();
  setup.specimen = s.specimen;
  sub.handed_specimen = setup;
  return sub;
}

GroupSimulation simulate_group(const SceneContext& ctx, const analysis::CampaignGroup& g,
                               GroupSimulation s) {
  const auto t0 = std::chrono::steady_clock::now();
  try {
    s.specimen.validate("Campaign: the specimen of " + g.material + " at " + fmt(g.cycles) +
                        " cycles");
    SceneContext sub = group_context(ctx, s);
    const auto law = law::make_trilinear(g.estimate.tri);
    const auto res = run_model(sub, s.model, law, g.estimate.j_tip);
    if (!res.rcurve.empty())
      s.a_start = res.rcurve.front().a;
    for (const auto& p : res.rcurve) {
      const double R = std::isfinite(p.R_energy) ? p.R_energy : p.R_J;
      if (!std::isfinite(p.delta_root) || !std::isfinite(R))
        continue;
      // delta_root held at its running maximum (it does not decrease once the root moves).
      const double d =
          s.delta_root.empty() ? p.delta_root : std::max(s.delta_root.back(), p.delta_root);
      s.delta_root.push_back(d);
      s.R.push_back(R);
    }
    s.G_ss = res.G_ss;
    const auto& c = g.estimate.curve;
    double ss = 0;
    int n = 0, inside = 0;
    for (std::size_t i = 0; i < c.delta.size(); ++i) {
      const double sim = analysis::interpolate_within(s.delta_root, s.R, c.delta[i]);
      if (!std::isfinite(sim))
        continue;
      ss += (sim - c.R[i]) * (sim - c.R[i]);
      ++n;
      inside += std::abs(sim - c.R[i]) <= 2 * c.R_std[i] ? 1 : 0;
    }
    const double G_B = g.estimate.G_ss - g.estimate.j_tip;
    if (n > 0) {
      s.misfit_rel = std::sqrt(ss / n) / G_B;
      s.within_scatter = static_cast<double>(inside) / n;
    }
    s.ran = true;
  } catch (const std::exception& e) {
    s.failure = e.what();
  }
  s.wall_time_s = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  return s;
}

/// What a group's simulation depends on: the scene and what a simulation takes from it
/// (simulation_fingerprint, with the group's specimen in effect), the group's members and files,
/// and the group's law and J_tip to the bit.
Fingerprint simulation_inputs(const SceneContext& ctx, const Fingerprint& group_inputs,
                              const analysis::CampaignGroup& g, const GroupSimulation& s) {
  SceneContext sub = group_context(ctx, s);
  Fingerprint fp = simulation_fingerprint(sub);
  for (std::size_t i = scene_fingerprint(ctx.parameters()).size(); i < group_inputs.size(); ++i)
    fp.push_back(group_inputs[i]);
  using law::exact_number;
  const auto& t = g.estimate.tri;
  fp.emplace_back("campaign group law", exact_number(t.d1) + " " + exact_number(t.s1) + " " +
                                            exact_number(t.d2) + " " + exact_number(t.s2) + " " +
                                            exact_number(t.dc) + " J_tip " +
                                            exact_number(g.estimate.j_tip));
  fp.emplace_back("campaign simulation model", s.model);
  return fp;
}

} // namespace

std::vector<std::string> campaign_simulation_models() {
  // The FEM first (the paper's Fig. 10 puts the laws back in a FE model; issue 33 item 5), then
  // the others cheapest first.
  std::vector<std::string> names;
  for (const SimulationModel* m : built_models())
    if (m->simulate)
      names.push_back(m->name);
  std::stable_partition(names.begin(), names.end(),
                        [](const std::string& n) { return n == "fem"; });
  return names;
}

specimen::Specimen campaign_group_specimen(const specimen::Specimen& scene,
                                           const analysis::CampaignGroup& group,
                                           const std::vector<analysis::CampaignSpecimen>& specimens,
                                           std::string& note) {
  // Each member's geometry: the scene's where its row says nothing.
  std::vector<specimen::Specimen> each;
  for (auto m : group.members) {
    const auto& r = specimens[m].row;
    specimen::Specimen s = scene;
    if (std::isfinite(r.width))
      s.width = r.width;
    if (std::isfinite(r.arm_thickness))
      s.height = 2 * r.arm_thickness;
    if (std::isfinite(r.initial_crack))
      s.initial_crack = r.initial_crack;
    if (std::isfinite(r.length))
      s.length = r.length;
    each.push_back(s);
  }
  note.clear();
  if (each.empty())
    return scene;
  struct Dim {
    const char* name;
    double specimen::Specimen::*field;
    double scale; // to mm as the manifest gives it (height: the arm thickness, h = height/2)
  };
  const Dim dims[] = {{"width", &specimen::Specimen::width, 1e3},
                      {"arm thickness", &specimen::Specimen::height, 0.5e3},
                      {"a0", &specimen::Specimen::initial_crack, 1e3},
                      {"length", &specimen::Specimen::length, 1e3}};
  specimen::Specimen out = each.front();
  std::string ranges;
  for (const auto& d : dims) {
    std::vector<double> v;
    for (const auto& s : each)
      v.push_back(s.*(d.field));
    std::sort(v.begin(), v.end());
    if (v.front() == v.back())
      continue;
    // The median (of an even count: the mean of the middle two).
    const std::size_t n = v.size();
    out.*(d.field) = n % 2 ? v[n / 2] : 0.5 * (v[n / 2 - 1] + v[n / 2]);
    ranges += std::string(ranges.empty() ? "" : ", ") + d.name + " " + fmt(v.front() * d.scale) +
              "-" + fmt(v.back() * d.scale) + " mm";
  }
  if (!ranges.empty())
    note = group.material + " at " + fmt(group.cycles) + " cycles: the specimens differ in " +
           "geometry (" + ranges + "); the law is simulated on the median specimen (width " +
           fmt(out.width * 1e3) + " mm, arm thickness " + fmt(out.arm_thickness() * 1e3) +
           " mm, a0 " + fmt(out.initial_crack * 1e3) + " mm, length " + fmt(out.length * 1e3) +
           " mm)";
  return out;
}

std::vector<GroupSimulation> simulate_campaign_laws(SceneContext& ctx,
                                                    const analysis::CampaignResult& r,
                                                    const std::string& model) {
  std::vector<const analysis::CampaignGroup*> groups;
  for (const auto& g : r.groups)
    if (g.estimate.ok && g.estimate.has_law)
      groups.push_back(&g);
  // Each group's simulation is a unit of work for --resume (campaign_resume.h).
  const Fingerprint scene = scene_fingerprint(ctx.parameters());
  std::vector<GroupSimulation> sims;
  std::vector<Fingerprint> inputs;
  std::vector<bool> restored;
  for (const auto* g : groups) {
    sims.push_back(prepare_group(ctx, r, *g, model));
    inputs.push_back(
        simulation_inputs(ctx, campaign_group_inputs(scene, *g, r.specimens), *g, sims.back()));
    restored.push_back(
        restore_campaign_simulation(ctx.output_dir, ctx.resume, inputs.back(), sims.back()));
    if (restored.back() && output_enabled())
      std::cerr << "campaign: resume: " << model << " simulation of " << g->material << " at "
                << fmt(g->cycles) << " cycles restored\n";
  }
  int ranks = 1;
  MPI_Comm_size(simulation_communicator(), &ranks);
  if (ranks == 1) {
    for (std::size_t i = 0; i < groups.size(); ++i) {
      if (restored[i])
        continue;
      sims[i] = simulate_group(ctx, *groups[i], sims[i]);
      keep_campaign_simulation(ctx.output_dir, inputs[i], sims[i]);
      std::cerr << "campaign: " << model << " simulation " << i + 1 << "/" << groups.size() << " "
                << groups[i]->material << " at " << fmt(groups[i]->cycles) << " cycles, "
                << fmt(sims[i].wall_time_s, 3) << " s\n";
    }
    return sims;
  }
  std::vector<std::size_t> todo;
  for (std::size_t i = 0; i < groups.size(); ++i)
    if (!restored[i])
      todo.push_back(i);
  const auto out = run_tasks_across_ranks(
      todo.size(),
      [&](std::size_t k) {
        const std::size_t i = todo[k];
        const GroupSimulation s = simulate_group(ctx, *groups[i], sims[i]);
        const TaskOwnsItsFiles own; // its record, written by the rank that ran it
        keep_campaign_simulation(ctx.output_dir, inputs[i], s);
        return campaign_simulation_bytes(s);
      },
      simulation_communicator());
  for (std::size_t k = 0; k < todo.size(); ++k)
    campaign_simulation_from_bytes(out.output[k],
                                   "campaign simulation from rank " + std::to_string(out.rank[k]),
                                   sims[todo[k]]);
  return sims;
}

void add_campaign_simulation_summary(const analysis::CampaignResult& r,
                                     const std::vector<GroupSimulation>& sims, Json& summary) {
  auto& groups = summary["campaign"]["groups"];
  for (const auto& s : sims)
    for (std::size_t i = 0; i < r.groups.size(); ++i)
      if (r.groups[i].material == s.material && r.groups[i].cycles == s.cycles)
        groups[i]["simulation"] = {
            {"model", s.model},
            {"ran", s.ran},
            {"failure", s.failure},
            {"G_ss_J_m2", json_number(s.G_ss)},
            {"misfit_rel_to_G_B", json_number(s.misfit_rel)},
            {"fraction_within_2_std", json_number(s.within_scatter)},
            {"wall_time_s", json_number(s.wall_time_s)},
            {"specimen",
             {{"width_mm", json_number(s.specimen.width / mm)},
              {"arm_thickness_mm", json_number(s.specimen.arm_thickness() / mm)},
              {"a0_mm", json_number(s.specimen.initial_crack / mm)},
              {"length_mm", json_number(s.specimen.length / mm)}}},
            {"a_start_mm", json_number(s.a_start / mm)},
            {"geometry_note", s.geometry_note}};
}

std::vector<std::string> write_campaign_simulation_files(const analysis::CampaignResult& r,
                                                         const std::vector<GroupSimulation>& sims,
                                                         const std::string& out_dir) {
  std::vector<std::string> pngs;
  for (const auto& s : sims) {
    const analysis::CampaignGroup* g = nullptr;
    for (const auto& gg : r.groups)
      if (gg.material == s.material && gg.cycles == s.cycles)
        g = &gg;
    if (!g || !s.ran)
      continue;
    const auto& c = g->estimate.curve;
    CsvWriter w(
        out_dir + "/campaign_fig10_" + analysis::group_file_stem(s.material, s.cycles) + ".csv",
        {"delta_mm", "R_measured_J_m2", "R_std_J_m2", "R_simulated_J_m2"},
        {s.material + " after " + fmt(s.cycles) +
             " cycles: the group's averaged R(delta) "
             "and its scatter (standard deviation over the specimens) against the " +
             s.model + " simulation of the group's trilinear law (R_energy)",
         "simulated specimen: width " + fmt(s.specimen.width / mm) + " mm, arm thickness " +
             fmt(s.specimen.arm_thickness() / mm) + " mm, a0 " +
             fmt(s.specimen.initial_crack / mm) + " mm, length " + fmt(s.specimen.length / mm) +
             " mm" + (s.geometry_note.empty() ? "" : " (" + s.geometry_note + ")")});
    for (std::size_t i = 0; i < c.delta.size(); ++i)
      w.row({c.delta[i] / mm, c.R[i], c.R_std[i],
             analysis::interpolate_within(s.delta_root, s.R, c.delta[i])});
    w.close();
  }
  // One PNG per material: measured (band of 2 std) and simulated for every cycle count.
  std::vector<std::string> materials;
  for (const auto& s : sims)
    if (s.ran && std::find(materials.begin(), materials.end(), s.material) == materials.end())
      materials.push_back(s.material);
  for (const auto& m : materials) {
    const std::string s0 = analysis::group_file_stem(m, 0);
    const std::string png = "campaign_fig10_" + s0.substr(0, s0.size() - 3) + ".png";
    std::string p = gnuplot_png_preamble(png, 1000, 620);
    p += "set title '" + m + ": measured R(delta) (+-2 std over specimens) and the " +
         sims.front().model +
         " simulation of each group law'\nset xlabel 'notch-root opening delta (mm)'\n"
         "set ylabel 'R (J/m^2)'\nset key bottom right\nset style fill transparent solid 0.2 "
         "noborder\nplot ";
    int k = 0;
    for (const auto& s : sims) {
      if (s.material != m || !s.ran)
        continue;
      const std::string csv =
          "campaign_fig10_" + analysis::group_file_stem(s.material, s.cycles) + ".csv";
      const std::string lc = " lc " + std::to_string(k + 1);
      p += std::string(k ? ", " : "") + "'" + csv + "' using 1:($2-2*$3):($2+2*$3) with " +
           "filledcurves" + lc + " notitle, '" + csv + "' using 1:2 with lines lw 1" + lc +
           " title '" + fmt(s.cycles) + " cycles measured', '" + csv +
           "' using 1:4 with lines lw 2 dt 2" + lc + " title 'simulated'";
      ++k;
    }
    p += "\n";
    if (run_gnuplot(out_dir, p))
      pngs.push_back(png);
  }
  return pngs;
}

} // namespace fiberbridge::app
