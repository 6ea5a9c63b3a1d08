// The campaign's summary block.
#include "outputs/campaign_out.h"

#include "fiberbridge/core/units.h"

#include <cmath>

namespace fiberbridge::app::campaign_out {

using units::kPa;

Json summary_block(const CampaignResult& r, const CampaignWriteOptions& w) {
  Json groups = Json::array();
  for (const auto& g : r.groups) {
    Json specimens = Json::array();
    for (auto m : g.members)
      specimens.push_back(r.specimens[m].row.specimen);
    Json cij = Json::object();
    for (std::size_t k = 0; k < analysis::n_group_quantities; ++k)
      cij[analysis::quantity_key(static_cast<GroupQuantity>(k))] = interval_json(g.ci[k]);
    // The half-widths the chain's accuracy adds in quadrature to the replicates' (0: none).
    Json chain = Json::object();
    for (std::size_t k = 0; k < analysis::n_group_quantities; ++k)
      if (const double h = analysis::chain_accuracy_half_width(g, r.specimens, r.options,
                                                               static_cast<GroupQuantity>(k));
          h > 0 && g.has_interval())
        chain[analysis::quantity_key(static_cast<GroupQuantity>(k))] = json_number(h);
    Json tri = {{"d1_mm", json_number(q(g, GroupQuantity::d1))},
                {"sigma1_kPa", json_number(q(g, GroupQuantity::sigma1))},
                {"d2_mm", json_number(q(g, GroupQuantity::d2))},
                {"sigma2_kPa", json_number(q(g, GroupQuantity::sigma2))},
                {"delta_c_mm", json_number(q(g, GroupQuantity::delta_c))}};
    groups.push_back(
        {{"material", g.material},
         {"cycles", g.cycles},
         {"n_specimens", g.members.size()},
         {"specimens", specimens},
         {"ok", g.estimate.ok},
         // R(a)-only groups: which estimator gave J_tip and G_ss (Campaign/R(a) estimator).
         {"ra_estimator", !g.members.empty() && !r.specimens[g.members.front()].has_rdelta
                              ? Json(analysis::to_string(r.estimator))
                              : Json(nullptr)},
         {"trilinear", tri},
         {"J1_J_m2", json_number(q(g, GroupQuantity::J1))},
         {"J2_J_m2", json_number(q(g, GroupQuantity::J2))},
         {"G_ss_J_m2", json_number(q(g, GroupQuantity::G_ss))},
         {"J_tip_J_m2", json_number(q(g, GroupQuantity::J_tip))},
         {"l_b_mm", json_number(q(g, GroupQuantity::l_b))},
         {"rho_b_per_mm2", Json::array({json_number(q(g, GroupQuantity::rho_low)),
                                        json_number(q(g, GroupQuantity::rho_high))})},
         {"rms_residual_kPa", json_number(g.estimate.rms_residual / kPa)},
         {"ci", cij},
         {"ci_chain_accuracy_half_width", chain},
         {"bootstrap",
          {{"samples", g.samples.size()}, {"failed", g.failed_samples}, {"seed", g.seed}}},
         {"notes", g.notes}});
  }
  Json deg = Json::array();
  for (const auto& d : r.degradation)
    deg.push_back(
        {{"material", d.material},
         {"property", d.property},
         {"cycles", d.cycles},
         {"values", d.values},
         {"has_slope", d.has_slope},
         {"slope_per_cycle", json_number(d.has_slope ? d.paper.fit.slope : NAN)},
         {"r2", json_number(d.has_slope ? d.paper.fit.r2 : NAN)},
         {"significant_paper_rule", d.has_slope && d.paper.significant},
         {"normalized_rate_per_cycle", json_number(d.has_slope ? d.paper.normalized_rate : NAN)},
         {"slope_ci", interval_json(d.slope_ci)},
         {"p_value", json_number(d.p_value)},
         {"bootstrap_samples", d.samples_used},
         {"note", d.note}});
  Json ranking = Json::array(), detail = Json::array(), conf = Json::array();
  for (const auto& m : r.ranking.ranks) {
    ranking.push_back(m.material);
    detail.push_back({{"material", m.material},
                      {"rank", m.rank},
                      {"degradation_score_per_cycle", m.degradation_score},
                      {"significant_properties", m.significant_properties}});
  }
  for (const auto& p : r.ranking.pairs)
    conf.push_back({{"first", p.first},
                    {"second", p.second},
                    {"p_first_ahead", json_number(p.p_first_ahead)},
                    {"p_tie", json_number(p.p_tie)},
                    {"p_second_ahead", json_number(p.p_second_ahead)}});
  std::vector<std::string> notes = r.notes;
  for (const auto& n : r.ranking.notes)
    notes.push_back(n);
  return {{"manifest", r.manifest.source},
          {"n_specimens", r.specimens.size()},
          {"n_groups", r.groups.size()},
          {"bootstrap_samples", r.options.bootstrap_samples},
          {"seed", r.options.seed},
          {"confidence", r.options.confidence},
          {"interval", interval_name(r.options)},
          {"chain_accuracy",
           {{"G_ss_rel", r.options.chain_u_G_ss}, {"J_tip_rel", r.options.chain_u_J_tip}}},
          {"wall_time_s", w.seconds},
          {"groups", groups},
          {"degradation", deg},
          {"ranking", ranking},
          {"ranking_detail", detail},
          {"ranking_confidence", conf},
          {"ranking_bootstrap_samples", r.ranking.samples},
          {"reference_materials", r.ranking.reference},
          {"not_ranked", r.ranking.not_ranked},
          {"notes", notes}};
}

} // namespace fiberbridge::app::campaign_out
