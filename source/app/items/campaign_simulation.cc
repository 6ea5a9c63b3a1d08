// The campaign's laws back in the specimen (campaign_simulation.h; the paper's Fig. 10).
#include "fiberbridge/app/items/campaign_simulation.h"
#include "fiberbridge/analysis/campaign.h"
#include "fiberbridge/analysis/line_fit.h"

#include "fiberbridge/app/items/items.h"
#include "fiberbridge/app/run/campaign_resume.h"
#include "fiberbridge/app/run/resume_store.h"
#include "fiberbridge/app/run/task_distributor.h"
#include "fiberbridge/app/scene/models.h"
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

result::SimulationResult run_model(const SceneContext& ctx, const std::string& model,
                                   const law::TractionLaw& law, double j_tip) {
  // One place chooses a model by name: the registry (models.h).
  const SimulationModel* m = built_model(model);
  if (!m || !m->simulate)
    throw InputError("Campaign/Simulation model: '" + model + "' is not available in this build");
  return m->simulate(ctx, law, j_tip, {});
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
      // Over the law's range: past delta_c R(delta_root) is the plateau, compared as G_ss above,
      // and a finite specimen's released energy per growth there carries its far end (the FEM on
      // PVA's 16-cycle law, zone 138 mm: R_energy falls from 734 to 681 J/m^2 as the front runs
      // from 240 to 250 mm of 300, while R_J stays at G_ss, 753; docs/verification.md, "The laws
      // back in the specimen"). What the law decides is the rise.
      if (c.delta[i] > g.estimate.delta_c)
        break;
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
  // The finite-element models first (the paper's Fig. 10 puts the laws back in a FE model; issue
  // 33 item 5), then the others cheapest first.
  std::vector<const SimulationModel*> models = built_models();
  std::stable_partition(models.begin(), models.end(),
                        [](const SimulationModel* m) { return m->finite_elements; });
  std::vector<std::string> names;
  for (const SimulationModel* m : models)
    if (m->simulate)
      names.push_back(m->name);
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

std::vector<GroupSimulation> simulate_campaign_laws(const SceneContext& ctx,
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
      ctx.progress("campaign: resume: " + model + " simulation of " + g->material + " at " +
                   fmt(g->cycles) + " cycles restored");
  }
  int ranks = 1;
  MPI_Comm_size(simulation_communicator(), &ranks);
  if (ranks == 1) {
    for (std::size_t i = 0; i < groups.size(); ++i) {
      if (restored[i])
        continue;
      sims[i] = simulate_group(ctx, *groups[i], sims[i]);
      keep_campaign_simulation(ctx.output_dir, inputs[i], sims[i]);
      ctx.progress("campaign: " + model + " simulation " + std::to_string(i + 1) + "/" +
                   std::to_string(groups.size()) + " " + groups[i]->material + " at " +
                   fmt(groups[i]->cycles) + " cycles, " + fmt(sims[i].wall_time_s, 3) + " s");
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

} // namespace fiberbridge::app
