#pragma once
// R at initiation and its first rise, fitted to the dissipated energy itself rather than to its
// windowed slopes (docs/design.md section 6, "R at initiation"). A slope of D(a) over a window
// that starts at the first growth reading is one-sided: it averages R over the rise that follows
// and reads high at initiation (J_tip +5 to +26 % on the FEM's virtual tests). Seed Eq. 2 says
// what R does there: flat at J_tip while the notch-root opening stays on the law's elastic rise,
// then rising linearly in delta on a linear segment of the law. So R(delta) = J + s max(0, delta -
// delta_h) is integrated along the measured a and delta_root and fitted to D directly:
//   D_i = c + B [ J (a_i - a_1) + s int_{a_1}^{a_i} max(0, delta - delta_h) da ],
// linear in (c, J, s) for each hinge delta_h, which is scanned over the readings. The free c
// absorbs whatever dissipated before the first fitted reading.
#include <cmath>
#include <cstddef>
#include <string>
#include <vector>

namespace fiberbridge::analysis {

struct InitialRise {
  bool fitted = false;
  double j_tip = NAN;    ///< R at initiation [J/m^2]
  double slope = 0;      ///< dR/ddelta after the hinge [J/m^3], >= 0
  double hinge = 0;      ///< delta_root where R starts to rise [m]
  std::size_t onset = 0; ///< first growth reading with dissipation beyond the noise of D
  std::size_t end = 0;   ///< readings [onset, end) were fitted
  double delta_end = 0;  ///< delta_root of the last fitted reading [m]
  std::string why;       ///< why it was not fitted (empty when fitted)
  /// The fitted R at notch-root opening delta [J/m^2].
  double R(double delta) const { return j_tip + slope * std::max(0.0, delta - hinge); }
};

/// The growth readings (crack length a > a0, in time order) with their notch-root opening and
/// D = W - P opening/2; `D_before`: D on the last row before the first of them; `D_noise`: the
/// noise of D on the rows before growth (one standard deviation); `width`: the specimen's [m].
/// The onset is the first reading whose D exceeds D_before by 3 D_noise and by 1e-4 of the
/// largest |D| (a 1 % strain tip creeps ahead while the load rises before the crack grows: those
/// readings carry no dissipation and are left out). The fit spans the readings with delta_root up
/// to a fraction of its range past the onset's, at least 6 readings: from 5 % (the window of
/// steady_state.h's J_tip) up to 20 %, the widest whose J and s still lie within 2 standard
/// errors of every narrower window's (intersection of confidence intervals, as the energy
/// slopes' windows). The hinge is tried on the readings and at quarter steps between them, with
/// at least 3 readings after it. Not fitted (`fitted` false, `why` says) with fewer readings.
InitialRise fit_initial_rise(const std::vector<double>& a, const std::vector<double>& delta_root,
                             const std::vector<double>& D, double D_before, double D_noise,
                             double width);

} // namespace fiberbridge::analysis
