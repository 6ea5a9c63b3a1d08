#include "fiberbridge/app/outputs/bridging_writers.h"

#include "fiberbridge/core/csv.h"
#include "fiberbridge/core/units.h"

namespace fiberbridge::app {

using units::kPa;
using units::mm;

void write_bridging(const analysis::BridgingEstimate& e, const std::string& stress_source,
                    const std::string& out_dir, ItemReport& report) {
  const analysis::BridgingFiber& f = e.fiber;
  report["bridging"] = {{"sigma_kPa", e.sigma / kPa},
                        {"sigma_source", stress_source},
                        {"opening_mm", e.delta / mm},
                        {"zone_length_mm", e.zone_length / mm},
                        {"rho_b_eq15_peeling_per_mm2", e.rho_peeling * units::mm2},
                        {"rho_b_eq13_breaking_per_mm2", e.rho_breaking * units::mm2},
                        {"rho_b_exact_governing_per_mm2", e.rho_exact * units::mm2},
                        {"governing_mechanism", e.peeling_governs ? "peeling" : "breaking"},
                        {"fiber",
                         {{"E_f_GPa", f.E_f / units::GPa},
                          {"r_f_um", f.r_f / units::um},
                          {"sigma_f_MPa", f.sigma_fb / units::MPa},
                          {"G_c_J_m2", f.G_c}}}};
  // The model's law up to the peak region (its stated range of validity, seed section 3.4).
  CsvWriter w(out_dir + "/bridging_model.csv",
              {"delta_mm", "sigma_exact_kPa", "sigma_eq13_kPa", "sigma_eq15_kPa"},
              {"seed Eqs. 11-15 with rho_b from the exact governing form; valid only up to the "
               "peak stress"});
  w.row({0.0, 0.0, 0.0, 0.0});
  for (int i = 1; i <= 50; ++i) {
    const double d = 2 * e.delta * i / 50;
    w.row({d / mm, e.stress_exact(d) / kPa, e.stress_eq13(d) / kPa, e.stress_eq15(d) / kPa});
  }
  w.close();
}

} // namespace fiberbridge::app
