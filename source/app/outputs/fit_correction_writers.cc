// The fit's correction by simulation, written (fit_correction_writers.h).
#include "outputs/fit_correction_writers.h"

#include "fiberbridge/app/outputs/extraction_writers.h"

#include "fiberbridge/core/csv.h"
#include "fiberbridge/core/units.h"

namespace fiberbridge::app {

using units::kPa;
using units::mm;

namespace {

Json estimate_json(const identify::ChainEstimate& e) {
  Json j = trilinear_json(e.law);
  j["J_tip_J_m2"] = e.j_tip;
  // The law's own steady-state toughness, J_tip + its area (seed Eq. 2 at delta_c): for the
  // corrected law, the specimen's far end taken out where the forward model holds it
  // (docs/verification.md, "The chain's accuracy in the intervals, and the correction's forward
  // model").
  j["G_ss_J_m2"] = e.j_tip + e.law.j1() + e.law.j2();
  return j;
}

std::vector<double> estimate_cells(const identify::ChainEstimate& e) {
  const auto& t = e.law;
  return {e.j_tip, t.d1 / mm, t.s1 / kPa, t.d2 / mm, t.s2 / kPa, t.dc / mm};
}

} // namespace

void write_fit_correction(const identify::ChainCorrection& c, const std::string& out_dir,
                          ItemReport& report) {
  {
    CsvWriter w(out_dir + "/fit_correction.csv",
                {"simulation", "J_tip_J_m2", "delta1_mm", "sigma1_kPa", "delta2_mm", "sigma2_kPa",
                 "delta_c_mm", "chain_J_tip_J_m2", "chain_delta1_mm", "chain_sigma1_kPa",
                 "chain_delta2_mm", "chain_sigma2_kPa", "chain_delta_c_mm", "mismatch"},
                {"the fit corrected by simulation: each row a law simulated by the " +
                     c.forward_model +
                     " at the records' openings and what the same chain (reduce, Eq. 6, fit) "
                     "gave on the simulated records; the next law is this one plus (records' "
                     "estimate - chain's)",
                 "mismatch: largest difference from the records' estimate (J_tip of itself, "
                 "stresses of the larger stress, openings of delta_c)"});
    for (std::size_t k = 0; k < c.steps.size(); ++k) {
      std::vector<double> row = {double(k + 1)};
      for (double x : estimate_cells(c.steps[k].simulated))
        row.push_back(x);
      for (double x : estimate_cells(c.steps[k].measured))
        row.push_back(x);
      row.push_back(c.steps[k].mismatch);
      w.row(row);
    }
    w.close();
  }
  Json block = {
      {"converged", c.converged},
      {"simulations", c.steps.size()},
      {"forward_runs", c.forward_runs},
      {"forward_time_s", c.forward_time_s},
      {"records_estimate", estimate_json(c.measured)},
      {"table", "fit_correction.csv"},
      {"notes", c.notes},
      {"method", "the chain's estimate is a function of the law; the correction finds the law "
                 "whose simulated records (the " +
                     c.forward_model +
                     " at the records' openings and crack readings) the same chain measures as "
                     "it measured the records: p <- p + (records' estimate - chain on simulation "
                     "of p) (identify/chain_correction.h)"},
      {"forward_model", c.forward_model}};
  if (c.converged) {
    block["corrected"] = estimate_json(c.corrected);
    const auto& t = c.corrected.law;
    CsvWriter w(out_dir + "/trilinear_fit_corrected.csv", {"delta_mm", "sigma_kPa"},
                {"trilinear law corrected by simulation: the law whose simulated records the chain "
                 "measures as the records (fit_correction.csv); J_tip_J_m2 = " +
                 std::to_string(c.corrected.j_tip)});
    w.row({0.0, 0.0});
    w.row({t.d1 / mm, t.s1 / kPa});
    w.row({t.d2 / mm, t.s2 / kPa});
    w.row({t.dc / mm, 0.0});
    w.close();
    report["trilinear_corrected"] = estimate_json(c.corrected);
  }
  report["fit_correction"] = block;
}

} // namespace fiberbridge::app
