// The campaign's laws back in the specimen (campaign_simulation.h; the paper's Fig. 10).
#include "fiberbridge/app/campaign_simulation.h"
#include "fiberbridge/analysis/line_fit.h"

#include "fiberbridge/app/items.h"
#include "fiberbridge/app/models.h"
#include "fiberbridge/app/task_distributor.h"
#include "fiberbridge/core/csv.h"
#include "fiberbridge/core/error.h"
#include "fiberbridge/core/format.h"
#include "fiberbridge/core/plot.h"
#include "fiberbridge/core/units.h"
#include "fiberbridge/law/piecewise_linear_law.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <sstream>

namespace fiberbridge::app {

using units::mm;

namespace {

std::string stem(const std::string& material, double cycles) {
  std::string o;
  for (char c : material)
    o += std::isalnum(static_cast<unsigned char>(c)) || c == '-' || c == '_' ? c : '_';
  return o + "_c" + fmt(cycles);
}

double interpolate(const std::vector<double>& x, const std::vector<double>& y, double t) {
  // Outside the polyline: no value; inside: the one linear interpolation (line_fit.h).
  if (x.empty() || t < x.front() || t > x.back())
    return NAN;
  return analysis::interpolate_linear(x, y, t);
}

result::SimulationResult run_model(SceneContext& ctx, const std::string& model,
                                   const law::TractionLaw& law, double j_tip) {
  // One place chooses a model by name: the registry (models.h).
  const SimulationModel* m = built_model(model);
  if (!m || !m->simulate)
    throw InputError("Campaign/Simulation model: '" + model + "' is not available in this build");
  return m->simulate(ctx, law, j_tip);
}

GroupSimulation simulate_group(SceneContext& ctx, const analysis::CampaignGroup& g,
                               const std::string& model) {
  GroupSimulation s;
  s.material = g.material;
  s.cycles = g.cycles;
  s.model = model;
  const auto t0 = std::chrono::steady_clock::now();
  try {
    const auto law = law::make_trilinear(g.estimate.tri);
    const auto res = run_model(ctx, model, law, g.estimate.j_tip);
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
      const double sim = interpolate(s.delta_root, s.R, c.delta[i]);
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

std::string encode(const GroupSimulation& s) {
  std::string t;
  char buf[64];
  auto put = [&](double v) {
    std::snprintf(buf, sizeof buf, "%.17g ", v);
    t += buf;
  };
  t += std::to_string(s.ran ? 1 : 0) + " " + std::to_string(s.delta_root.size()) + " ";
  for (std::size_t i = 0; i < s.delta_root.size(); ++i) {
    put(s.delta_root[i]);
    put(s.R[i]);
  }
  put(s.G_ss);
  put(s.misfit_rel);
  put(s.within_scatter);
  put(s.wall_time_s);
  return t + "\n" + s.failure;
}

void decode(const std::string& t, GroupSimulation& s) {
  std::istringstream in(t);
  auto get = [&] {
    std::string w;
    in >> w;
    return std::strtod(w.c_str(), nullptr);
  };
  int ran = 0;
  std::size_t n = 0;
  in >> ran >> n;
  s.ran = ran != 0;
  s.delta_root.resize(n);
  s.R.resize(n);
  for (std::size_t i = 0; i < n; ++i) {
    s.delta_root[i] = get();
    s.R[i] = get();
  }
  s.G_ss = get();
  s.misfit_rel = get();
  s.within_scatter = get();
  s.wall_time_s = get();
  std::string line;
  std::getline(in, line);
  std::getline(in, s.failure);
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

std::vector<GroupSimulation> simulate_campaign_laws(SceneContext& ctx,
                                                    const analysis::CampaignResult& r,
                                                    const std::string& model) {
  std::vector<const analysis::CampaignGroup*> groups;
  for (const auto& g : r.groups)
    if (g.estimate.ok && g.estimate.has_law)
      groups.push_back(&g);
  std::vector<GroupSimulation> sims(groups.size());
  int ranks = 1;
  MPI_Comm_size(simulation_communicator(), &ranks);
  if (ranks == 1) {
    for (std::size_t i = 0; i < groups.size(); ++i) {
      sims[i] = simulate_group(ctx, *groups[i], model);
      std::cerr << "campaign: " << model << " simulation " << i + 1 << "/" << groups.size() << " "
                << groups[i]->material << " at " << fmt(groups[i]->cycles) << " cycles, "
                << fmt(sims[i].wall_time_s, 3) << " s\n";
    }
    return sims;
  }
  const auto out = run_tasks_across_ranks(
      groups.size(), [&](std::size_t i) { return encode(simulate_group(ctx, *groups[i], model)); },
      simulation_communicator());
  for (std::size_t i = 0; i < groups.size(); ++i) {
    sims[i].material = groups[i]->material;
    sims[i].cycles = groups[i]->cycles;
    sims[i].model = model;
    decode(out.output[i], sims[i]);
  }
  return sims;
}

void add_campaign_simulation_summary(const analysis::CampaignResult& r,
                                     const std::vector<GroupSimulation>& sims, Json& summary) {
  auto& groups = summary["campaign"]["groups"];
  for (const auto& s : sims)
    for (std::size_t i = 0; i < r.groups.size(); ++i)
      if (r.groups[i].material == s.material && r.groups[i].cycles == s.cycles)
        groups[i]["simulation"] = {{"model", s.model},
                                   {"ran", s.ran},
                                   {"failure", s.failure},
                                   {"G_ss_J_m2", json_number(s.G_ss)},
                                   {"misfit_rel_to_G_B", json_number(s.misfit_rel)},
                                   {"fraction_within_2_std", json_number(s.within_scatter)},
                                   {"wall_time_s", json_number(s.wall_time_s)}};
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
    CsvWriter w(out_dir + "/campaign_fig10_" + stem(s.material, s.cycles) + ".csv",
                {"delta_mm", "R_measured_J_m2", "R_std_J_m2", "R_simulated_J_m2"},
                {s.material + " after " + fmt(s.cycles) +
                 " cycles: the group's averaged R(delta) "
                 "and its scatter (standard deviation over the specimens) against the " +
                 s.model + " simulation of the group's trilinear law (R_energy)"});
    for (std::size_t i = 0; i < c.delta.size(); ++i)
      w.row({c.delta[i] / mm, c.R[i], c.R_std[i], interpolate(s.delta_root, s.R, c.delta[i])});
    w.close();
  }
  // One PNG per material: measured (band of 2 std) and simulated for every cycle count.
  std::vector<std::string> materials;
  for (const auto& s : sims)
    if (s.ran && std::find(materials.begin(), materials.end(), s.material) == materials.end())
      materials.push_back(s.material);
  for (const auto& m : materials) {
    const std::string s0 = stem(m, 0);
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
      const std::string csv = "campaign_fig10_" + stem(s.material, s.cycles) + ".csv";
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
