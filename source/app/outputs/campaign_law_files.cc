// The campaign's per-group law files and FE cards.
#include "outputs/campaign_out.h"

#include "fiberbridge/analysis/cohesive_export.h"
#include "fiberbridge/analysis/line_fit.h"
#include "fiberbridge/core/csv.h"
#include "fiberbridge/core/format.h"
#include "fiberbridge/core/units.h"

#include <cmath>

namespace fiberbridge::app::campaign_out {

using units::kPa;
using units::mm;

std::vector<std::string> write_group_laws(const CampaignResult& r, bool fe_export,
                                          const std::string& dir) {
  std::vector<std::string> files;
  int id = 0;
  for (const auto& g : r.groups) {
    ++id;
    if (!g.estimate.ok || !g.estimate.has_law)
      continue;
    const auto& e = g.estimate;
    const std::string stem = "campaign_law_" + group_stem(g);
    std::vector<double> grid = g.law_delta;
    if (grid.empty())
      grid = e.laws.delta;
    const auto tri = law::make_trilinear(e.tri);
    CsvWriter w(dir + "/" + stem + ".csv",
                {"delta_mm", "sigma_eq6_kPa", "sigma_dRdd_kPa", "sigma_trilinear_kPa",
                 "band_lo_kPa", "band_hi_kPa"},
                {g.material + " after " + fmt(g.cycles) + " cycles, " +
                 std::to_string(g.members.size()) +
                 " specimens: law by seed Eq. 6 beside sigma = dR/ddelta, the trilinear fit, and "
                 "the bootstrap band of the Eq. 6 law (" +
                 fmt(100 * r.options.confidence) + " %; empty without bootstrap)"});
    for (std::size_t i = 0; i < grid.size(); ++i) {
      const double d = grid[i];
      w.row({d / mm, analysis::interpolate_within(e.laws.delta, e.laws.sigma_eq6, d) / kPa,
             analysis::interpolate_within(e.laws.delta, e.laws.sigma_dRdd, d) / kPa,
             tri.envelope(d) / kPa, g.law_lo.empty() ? NAN : g.law_lo[i] / kPa,
             g.law_hi.empty() ? NAN : g.law_hi[i] / kPa});
    }
    w.close();
    files.push_back(stem + ".csv");
    if (!fe_export)
      continue;
    const auto poly =
        analysis::trilinear_polyline(e.tri.d1, e.tri.s1, e.tri.d2, e.tri.s2, e.tri.dc);
    const std::string title = g.material + " after " + fmt(g.cycles) + " cycles (trilinear fit)";
    try {
      write_file_atomically(dir + "/" + stem + "_lsdyna_mat186.k",
                            "*KEYWORD\n" +
                                analysis::lsdyna_mat_cohesive_general(poly, id, 1000 + id, title) +
                                "*END\n");
      files.push_back(stem + "_lsdyna_mat186.k");
      write_file_atomically(dir + "/" + stem + "_abaqus.inp",
                            analysis::abaqus_cohesive_material(poly, file_name_part(g.material) +
                                                                         "_C" + fmt(g.cycles)));
      files.push_back(stem + "_abaqus.inp");
    } catch (const std::exception&) {
      // A fitted law the codes cannot take (a zero first stress): the CSV says the law; the
      // group's notes are already written. Not worth failing the campaign over.
    }
  }
  return files;
}

} // namespace fiberbridge::app::campaign_out
