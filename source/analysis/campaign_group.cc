// One group of a campaign: the one-data-set chain on its specimens (estimate_group) and the
// bootstrap over whole specimens that gives its intervals (campaign.h; docs/design.md section 1,
// "Durability campaign").
#include "fiberbridge/analysis/campaign.h"
#include "fiberbridge/analysis/campaign_statistics.h"
#include "fiberbridge/analysis/line_fit.h"
#include "fiberbridge/analysis/trilinear_fit.h"
#include "fiberbridge/core/csv.h"
#include "fiberbridge/core/error.h"
#include "fiberbridge/core/format.h"
#include "fiberbridge/core/median.h"
#include "fiberbridge/core/units.h"

#include <boost/math/distributions/normal.hpp>
#include <boost/math/distributions/students_t.hpp>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <numeric>
#include <random>

namespace fiberbridge::analysis {

using units::kPa;
using units::mm;

namespace {

/// Crack growth from the first row to where delta reaches `d` (linear in delta); NaN without a.
double growth_to_opening(const Replicate& r, double d) {
  if (r.a.size() != r.delta.size() || r.a.empty() || r.delta.back() < d)
    return NAN;
  for (std::size_t i = 1; i < r.delta.size(); ++i)
    if (r.delta[i] >= d) {
      const double w =
          r.delta[i] > r.delta[i - 1] ? (d - r.delta[i - 1]) / (r.delta[i] - r.delta[i - 1]) : 1.0;
      return r.a[i - 1] + w * (r.a[i] - r.a[i - 1]) - r.a.front();
    }
  return NAN;
}

/// Mean of the finite values, NaN when there is none.
double finite_mean(const std::vector<double>& v) {
  double s = 0;
  int n = 0;
  for (double x : v)
    if (std::isfinite(x)) {
      s += x;
      ++n;
    }
  return n ? s / n : NAN;
}

/// Linear interpolation on an increasing grid; 0 outside [x0, xn] (a law beyond its delta_c).
double law_at(const std::vector<double>& x, const std::vector<double>& y, double t) {
  // Outside the polyline: a law is zero beyond its delta_c; inside: the one linear interpolation
  // (line_fit.h).
  if (x.empty() || t < x.front() || t > x.back())
    return 0;
  return interpolate_linear(x, y, t);
}

/// sqrt(n/(n-1)) t_{n-1, 1-(1-level)/2}: the small-sample factor of both corrected intervals
/// (the bootstrap's variance of a mean of n is (n-1)/n of the sample's, and its tails are
/// Student's, not normal).
double small_sample_factor(const CampaignOptions& o, std::size_t n) {
  const double nn = static_cast<double>(n);
  const boost::math::students_t t(nn - 1);
  return std::sqrt(nn / (nn - 1)) * boost::math::quantile(t, 1 - 0.5 * (1 - o.confidence));
}

/// The tail probability of each end of a percentile interval: (1 - level)/2, or with the
/// expanded percentile bootstrap (Hesterberg) Phi(-small_sample_factor).
double bootstrap_tail(const CampaignOptions& o, std::size_t n) {
  if (o.interval != CampaignOptions::Interval::expanded_percentile || n < 2)
    return 0.5 * (1 - o.confidence);
  return boost::math::cdf(boost::math::normal(), -small_sample_factor(o, n));
}

/// The interval of `samples` around the point estimate `v` by the chosen method. student_t:
/// v -+ small_sample_factor x the samples' standard deviation, not below 0 (every group quantity
/// is non-negative: stresses, toughnesses, openings, lengths, densities).
Interval make_interval(const CampaignOptions& o, std::size_t n, double v,
                       const std::vector<double>& samples) {
  if (o.interval != CampaignOptions::Interval::student_t) {
    const double a = bootstrap_tail(o, n);
    return {sample_quantile(samples, a), sample_quantile(samples, 1 - a)};
  }
  double s = 0, ss = 0;
  int m = 0;
  for (double x : samples)
    if (std::isfinite(x)) {
      s += x;
      ss += x * x;
      ++m;
    }
  if (m < 2 || !std::isfinite(v))
    return {};
  const double mean = s / m, sd = std::sqrt(std::max(0.0, (ss - m * mean * mean) / (m - 1)));
  const double k = small_sample_factor(o, n);
  return {std::max(0.0, v - k * sd), v + k * sd};
}

/// The cell of a specimen's R(delta) curve farthest from the curve's median, in multiples of
/// the median (`ratio`), and where it is: "file:line: R = ... J/m^2 at delta = ... mm".
struct FarCell {
  double ratio = 0;
  std::string text;
};

FarCell farthest_cell(const CampaignSpecimen& s) {
  const auto& R = s.curve.R;
  if (R.size() < 3)
    return {};
  const double mid = median_upper(R);
  std::size_t worst = 0;
  for (std::size_t i = 1; i < R.size(); ++i)
    if (std::abs(R[i] - mid) > std::abs(R[worst] - mid))
      worst = i;
  std::string where = s.row.file;
  // The file's own line, when the file is the R(delta) table that row came from.
  try {
    const CsvTable t = CsvTable::read(s.row.file);
    if (t.has_column("R_J_m2")) {
      const auto file_R = t.numeric("R_J_m2");
      for (std::size_t i = 0; i < file_R.size(); ++i)
        if (file_R[i] == R[worst]) {
          where += ":" + std::to_string(t.line_of_row(i));
          break;
        }
    }
  } catch (const std::exception&) {
    // The message still names the file and the value.
  }
  FarCell c;
  c.ratio = mid > 0 ? std::abs(R[worst] - mid) / mid : 0;
  c.text = where + ": R = " + fmt(R[worst]) +
           " J/m^2 at delta = " + fmt(s.curve.delta[worst] / mm) + " mm (the curve's median is " +
           fmt(mid) + " J/m^2)";
  return c;
}

/// A group without estimate that has one under a leave-one-out: the specimen whose removal
/// restores it and whose farthest cell is farthest off, named with that cell (issue 42: one R
/// cell of 1e6 in six specimens dropped the group, and the note named neither specimen nor
/// line). Removing a sound specimen of a marginal group may restore it too: the cell decides.
std::string single_spoiler(const CampaignGroup& group,
                           const std::vector<CampaignSpecimen>& specimens,
                           const CampaignOptions& o) {
  if (group.members.size() < 3)
    return "";
  const CampaignSpecimen* worst = nullptr;
  FarCell worst_cell;
  for (std::size_t k = 0; k < group.members.size(); ++k) {
    std::vector<std::size_t> others;
    for (std::size_t j = 0; j < group.members.size(); ++j)
      if (j != k)
        others.push_back(group.members[j]);
    if (!estimate_group(specimens, others, o, false).ok)
      continue;
    const CampaignSpecimen& s = specimens[group.members[k]];
    const FarCell c = farthest_cell(s);
    if (!worst || c.ratio > worst_cell.ratio) {
      worst = &s;
      worst_cell = c;
    }
  }
  if (!worst)
    return "";
  return "the group estimates without specimen '" + worst->row.specimen + "' (" +
         worst->row.where() +
         (worst_cell.text.empty() ? "" : "; farthest cell " + worst_cell.text) +
         "): check that specimen's file";
}

} // namespace

/// The rho_b range from sigma_1 at l_b (Eqs. 13/15, exact governing form), tracheid and bundle
/// fibers as the seed brackets it; NaN without l_b.
static void set_bridged_density(GroupEstimate& g, const CampaignOptions& o) {
  g.rho_low = g.rho_high = NAN;
  if (std::isfinite(g.l_b) && g.l_b > 0 && g.tri.s1 > 0) {
    const double r1 = bridged_density(g.tri.s1, o.rho_opening, g.l_b, o.fiber_low,
                                      BridgingMechanism::governing, false);
    const double r2 = bridged_density(g.tri.s1, o.rho_opening, g.l_b, o.fiber_high,
                                      BridgingMechanism::governing, false);
    g.rho_low = std::min(r1, r2);
    g.rho_high = std::max(r1, r2);
  }
}

void apply_law_shift(GroupEstimate& e, const LawShift& shift, const CampaignOptions& o) {
  if (!shift.applied || !e.ok || !e.has_law)
    return;
  e.tri.d1 += shift.d1;
  e.tri.s1 += shift.s1;
  e.tri.d2 += shift.d2;
  e.tri.s2 += shift.s2;
  e.tri.dc += shift.dc;
  e.j_tip += shift.j_tip;
  e.delta_c = e.tri.dc;
  e.J1 = e.tri.j1();
  e.J2 = e.tri.j2();
  set_bridged_density(e, o);
  // A resample whose law the shift carries out of the trilinear laws is a failed sample, not a
  // law (counted in the group's note as any other).
  const auto& t = e.tri;
  if (!(t.d1 > 0 && t.d1 < t.d2 && t.d2 < t.dc && t.s1 > 0 && t.s2 > 0 && e.j_tip > 0)) {
    e.ok = false;
    e.failure = "the correction's shift leaves no trilinear law for this resample";
  }
}

GroupEstimate estimate_group(const std::vector<CampaignSpecimen>& specimens,
                             const std::vector<std::size_t>& members, const CampaignOptions& o,
                             bool keep_curves) {
  GroupEstimate g;
  try {
    if (members.empty())
      throw InputError("no specimens");
    if (!specimens[members.front()].has_rdelta) {
      // R(a)-only (raw records without delta_root): the direct-energy initiation and plateau.
      std::vector<double> init, plat;
      for (auto m : members) {
        init.push_back(specimens[m].initiation);
        plat.push_back(specimens[m].plateau);
      }
      g.j_tip = finite_mean(init);
      g.G_ss = finite_mean(plat);
      g.ok = std::isfinite(g.G_ss);
      if (!g.ok)
        g.failure = "no record has a plateau";
      return g;
    }
    RDeltaData d;
    d.source = specimens[members.front()].row.material + " at " +
               fmt(specimens[members.front()].row.cycles) + " cycles";
    std::vector<double> dcs, jts;
    for (auto m : members) {
      d.replicates.push_back(specimens[m].curve);
      dcs.push_back(specimens[m].row.delta_c);
      jts.push_back(specimens[m].row.j_tip);
    }
    const RDeltaCurve curve = average_replicates(d, o.grid_points);
    SteadyStateOptions so;
    so.delta_c = std::isfinite(finite_mean(dcs)) ? finite_mean(dcs) : o.delta_c;
    so.j_tip = std::isfinite(finite_mean(jts)) ? finite_mean(jts) : o.j_tip;
    const SteadyState st = find_steady_state(curve, so, d.source);
    const ExtractedLaws laws = extract_cohesive_laws(curve, st.delta_c, o.intervals, o.half_width);
    const double dc = st.delta_c, G_B = st.G_ss - st.j_tip;
    TrilinearFit fit;
    if (o.free_breakpoints)
      fit = fit_trilinear_free(laws.delta, laws.sigma_eq6, dc, G_B, o.d1_min, o.d1_max,
                               o.d2_max > 0 ? o.d2_max : 0.5 * dc);
    else {
      if (!(o.d1 < o.d2 && o.d2 < dc))
        throw InputError("Fit: need Delta 1 < Delta 2 < delta_c (" + fmt(dc / mm) + " mm)");
      fit = fit_trilinear_fixed(laws.delta, laws.sigma_eq6, o.d1, o.d2, dc, G_B);
    }
    g.j_tip = st.j_tip;
    g.G_ss = st.G_ss;
    g.delta_c = dc;
    g.tri = fit.law;
    g.J1 = fit.law.j1();
    g.J2 = fit.law.j2();
    g.rms_residual = fit.rms_residual;
    g.has_law = true;
    // l_b: crack growth to the peak-stress opening d1 (seed section 3.4), where the records carry
    // crack lengths; the rho_b range from sigma_1 at that opening by Eqs. 13/15 (exact governing
    // form), tracheid and bundle fibers as the seed brackets it.
    std::vector<double> lbs;
    for (auto m : members)
      lbs.push_back(growth_to_opening(specimens[m].curve, fit.law.d1));
    g.l_b = finite_mean(lbs);
    set_bridged_density(g, o);
    if (keep_curves) {
      g.curve = curve;
      g.laws = laws;
      g.steady = st;
    }
    g.ok = true;
  } catch (const std::exception& e) {
    g.ok = false;
    g.failure = e.what();
  }
  return g;
}

void assess_campaign_specimen(CampaignSpecimen& s, const CampaignOptions& o) {
  if (!s.has_rdelta) {
    s.steady = false;
    return;
  }
  try {
    RDeltaData d;
    d.source = s.row.file;
    d.replicates.push_back(s.curve);
    const RDeltaCurve c = average_replicates(d, o.grid_points);
    SteadyStateOptions so;
    so.delta_c = std::isfinite(s.row.delta_c) ? s.row.delta_c : o.delta_c;
    so.j_tip = std::isfinite(s.row.j_tip) ? s.row.j_tip : o.j_tip;
    s.own = find_steady_state(c, so, s.row.file);
    s.steady = true;
  } catch (const std::exception& e) {
    s.steady = false;
    s.notes.push_back(std::string("its R curve alone reaches no steady state (") + e.what() +
                      "); kept in the group's average");
  }
  s.l_b = growth_to_opening(s.curve, o.d1);
}

double quantity_value(const GroupEstimate& g, GroupQuantity q) {
  const bool law = g.ok && g.has_law;
  switch (q) {
  case GroupQuantity::d1:
    return law ? g.tri.d1 / mm : NAN;
  case GroupQuantity::sigma1:
    return law ? g.tri.s1 / kPa : NAN;
  case GroupQuantity::d2:
    return law ? g.tri.d2 / mm : NAN;
  case GroupQuantity::sigma2:
    return law ? g.tri.s2 / kPa : NAN;
  case GroupQuantity::delta_c:
    return law ? g.delta_c / mm : NAN;
  case GroupQuantity::J1:
    return law ? g.J1 : NAN;
  case GroupQuantity::J2:
    return law ? g.J2 : NAN;
  case GroupQuantity::G_ss:
    return g.ok ? g.G_ss : NAN;
  case GroupQuantity::J_tip:
    return g.ok ? g.j_tip : NAN;
  case GroupQuantity::l_b:
    return law ? g.l_b / mm : NAN;
  case GroupQuantity::rho_low:
    return law ? g.rho_low * units::mm2 : NAN;
  case GroupQuantity::rho_high:
    return law ? g.rho_high * units::mm2 : NAN;
  default:
    return NAN;
  }
}

const char* quantity_key(GroupQuantity q) {
  static const char* keys[] = {"d1_mm",      "sigma1_kPa",        "d2_mm",
                               "sigma2_kPa", "delta_c_mm",        "J1_J_m2",
                               "J2_J_m2",    "G_ss_J_m2",         "J_tip_J_m2",
                               "l_b_mm",     "rho_b_low_per_mm2", "rho_b_high_per_mm2"};
  return keys[static_cast<std::size_t>(q)];
}

std::string group_file_stem(const std::string& material, double cycles) {
  return file_name_part(material) + "_c" + fmt(cycles);
}

unsigned group_seed(unsigned campaign_seed, const std::string& material, double cycles) {
  // FNV-1a over the seed, the material and the cycle count as printed: the same on every
  // platform and independent of the group's position in the manifest.
  std::uint64_t h = 1469598103934665603ull;
  auto mix = [&](const std::string& s) {
    for (unsigned char c : s) {
      h ^= c;
      h *= 1099511628211ull;
    }
  };
  mix(std::to_string(campaign_seed));
  mix("|" + material + "|" + fmt(cycles));
  return static_cast<unsigned>(h ^ (h >> 32));
}

std::vector<CampaignGroup> make_campaign_groups(const std::vector<CampaignSpecimen>& specimens) {
  std::vector<CampaignGroup> groups;
  for (std::size_t i = 0; i < specimens.size(); ++i) {
    const auto& s = specimens[i];
    auto it = std::find_if(groups.begin(), groups.end(), [&](const CampaignGroup& g) {
      return g.material == s.row.material && g.cycles == s.row.cycles;
    });
    if (it == groups.end()) {
      groups.push_back({});
      it = groups.end() - 1;
      it->material = s.row.material;
      it->cycles = s.row.cycles;
    } else {
      const auto& first = specimens[it->members.front()];
      if (first.has_rdelta != s.has_rdelta)
        throw InputError(s.row.where() + ": specimen '" + s.row.specimen + "' (" +
                         (s.has_rdelta ? "R(delta)" : "R(a) only, no delta_root") +
                         ") joins a group of " + (first.has_rdelta ? "R(delta)" : "R(a)-only") +
                         " specimens (" + first.row.where() +
                         "): one group, one kind of input (the laws and the plateaus are not "
                         "averaged together)");
      if (first.input != s.input)
        throw InputError(s.row.where() + ": specimen '" + s.row.specimen + "' is a " +
                         to_string(s.input) + ", " + first.row.where() + " of the same group a " +
                         to_string(first.input) + ": one group, one kind of input");
    }
    it->members.push_back(i);
  }
  return groups;
}

namespace {

/// The group's law corrected by simulation (CampaignOptions::correct_law) as the shift from the
/// chain's; not applied (with the reason in the notes) when a member has no record or the
/// correction did not converge.
LawShift law_correction(const CampaignGroup& group, const std::vector<CampaignSpecimen>& specimens,
                        const CampaignOptions& o, const std::string& name,
                        std::vector<std::string>& notes) {
  LawShift shift;
  const GroupEstimate& e = group.estimate;
  if (!o.correct_law || !e.ok || !e.has_law)
    return shift;
  std::vector<const CampaignSpecimen*> members;
  for (auto m : group.members) {
    if (!specimens[m].record)
      return shift; // R(delta) tables: nothing to simulate
    members.push_back(&specimens[m]);
  }
  const LawCorrection c = o.correct_law(members, e.tri, e.j_tip);
  for (const auto& n : c.notes)
    notes.push_back(name + ": law correction: " + n);
  if (!c.converged)
    return shift;
  shift = {true,
           c.law.d1 - e.tri.d1,
           c.law.s1 - e.tri.s1,
           c.law.d2 - e.tri.d2,
           c.law.s2 - e.tri.s2,
           c.law.dc - e.tri.dc,
           c.j_tip - e.j_tip};
  notes.push_back(name + ": law corrected by simulation (" + std::to_string(c.simulations) +
                  " simulations of the members' records; Fit/Model correction): sigma1 " +
                  fmt(e.tri.s1 / kPa) + " -> " + fmt(c.law.s1 / kPa) + " kPa, sigma2 " +
                  fmt(e.tri.s2 / kPa) + " -> " + fmt(c.law.s2 / kPa) + " kPa, delta_c " +
                  fmt(e.tri.dc / mm) + " -> " + fmt(c.law.dc / mm) + " mm, J_tip " + fmt(e.j_tip) +
                  " -> " + fmt(c.j_tip) +
                  " J/m^2; the bootstrap samples and the intervals move by the same shift, the "
                  "Eq. 6 law and its band do not");
  return shift;
}

/// Interval `i` around `v` widened on each side by `h` in quadrature (the replicates' half-width
/// and the chain's accuracy are independent), not below 0 as make_interval.
Interval widened(const Interval& i, double v, double h) {
  if (!(h > 0) || !std::isfinite(v) || !std::isfinite(i.lo) || !std::isfinite(i.hi))
    return i;
  return {std::max(0.0, v - std::hypot(v - i.lo, h)), v + std::hypot(i.hi - v, h)};
}

/// The relative standard uncertainties the chain adds to the group's G_ss and J_tip: none (NaN)
/// unless every member is a record with delta_root (the chain measured its curve); no J_tip term
/// where J_tip is given (Data/J tip, the rows' j_tip_J_m2), not measured.
struct ChainAccuracy {
  double u_G = NAN, u_J = NAN;
};
ChainAccuracy chain_accuracy(const CampaignGroup& group,
                             const std::vector<CampaignSpecimen>& specimens,
                             const CampaignOptions& o) {
  if (!group.estimate.ok || group.members.empty() || (o.chain_u_G_ss <= 0 && o.chain_u_J_tip <= 0))
    return {};
  bool j_tip_given = o.j_tip > 0;
  for (auto m : group.members) {
    if (!specimens[m].record)
      return {};
    j_tip_given = j_tip_given || std::isfinite(specimens[m].row.j_tip);
  }
  return {o.chain_u_G_ss, j_tip_given ? 0.0 : o.chain_u_J_tip};
}

/// The chain's accuracy as the fraction of the bridging area G_B = G_ss - J_tip it leaves
/// uncertain, standard; NaN without a term.
double bridging_fraction(const GroupEstimate& e, const ChainAccuracy& u) {
  const double G_B = e.G_ss - e.j_tip;
  if (!std::isfinite(u.u_G) || !(G_B > 0))
    return NAN;
  return std::hypot(u.u_G * e.G_ss, u.u_J * e.j_tip) / G_B;
}

/// The normal quantile of the options' two-sided confidence.
double normal_quantile(const CampaignOptions& o) {
  return boost::math::quantile(boost::math::normal(), 1 - 0.5 * (1 - o.confidence));
}

} // namespace

double chain_accuracy_half_width(const CampaignGroup& group,
                                 const std::vector<CampaignSpecimen>& specimens,
                                 const CampaignOptions& o, GroupQuantity q) {
  const ChainAccuracy u = chain_accuracy(group, specimens, o);
  if (!std::isfinite(u.u_G))
    return 0;
  const GroupEstimate& e = group.estimate;
  const double z = normal_quantile(o), v = quantity_value(e, q);
  const double f = bridging_fraction(e, u); // NaN when G_B <= 0
  switch (q) {
  case GroupQuantity::G_ss:
    return std::isfinite(v) ? z * u.u_G * v : 0;
  case GroupQuantity::J_tip:
    return std::isfinite(v) ? z * u.u_J * v : 0;
  case GroupQuantity::sigma1:
  case GroupQuantity::sigma2:
  case GroupQuantity::J1:
  case GroupQuantity::J2:
    return e.has_law && std::isfinite(v) && std::isfinite(f) ? z * f * v : 0;
  default:
    return 0;
  }
}

void analyse_campaign_group(CampaignGroup& group, const std::vector<CampaignSpecimen>& specimens,
                            const CampaignOptions& o) {
  group.estimate = estimate_group(specimens, group.members, o, true);
  group.seed = group_seed(o.seed, group.material, group.cycles);
  const std::string name = group.material + " at " + fmt(group.cycles) + " cycles";
  group.correction = law_correction(group, specimens, o, name, group.notes);
  apply_law_shift(group.estimate, group.correction, o);
  if (group.estimate.ok && group.estimate.steady.end_effect)
    // The plateau this G_ss is read from is cut short (SteadyState::end_effect); a campaign's
    // groups are corrected by the beam, which does not hold the far end, and G_ss is measured.
    group.notes.push_back(
        name + ": R falls over the end of the group's averaged R(delta) beyond the plateau band "
               "(the zone meets the specimens' far end, so the tip runs ahead of the work done): "
               "G_ss is read before the fall and is low by that effect (2.6-5.2 % on the virtual "
               "tests of PVA's laws at 8-24 cycles, "
               "docs/verification.md, session 32); longer specimens, or a scene's fit with "
               "Fit/Model correction = auto (the FEM), take it out");
  if (!group.estimate.ok) {
    group.notes.push_back(name + ": no estimate (" + group.estimate.failure + ")");
    if (const std::string culprit = single_spoiler(group, specimens, o); !culprit.empty())
      group.notes.push_back(name + ": " + culprit);
  }

  // Specimens named in the notes (never dropped): no steady state of their own, or far from the
  // group (robust z of G_ss).
  std::vector<double> gss;
  for (auto m : group.members) {
    const auto& s = specimens[m];
    for (const auto& n : s.notes)
      group.notes.push_back("specimen '" + s.row.specimen + "' (" + s.row.where() + "): " + n);
    gss.push_back(s.steady ? s.own.G_ss : s.plateau);
  }
  if (group.members.size() >= 3) {
    const double med = median(gss);
    std::vector<double> dev;
    for (double x : gss)
      if (std::isfinite(x))
        dev.push_back(std::abs(x - med));
    const double mad = 1.4826 * median(dev);
    for (std::size_t i = 0; i < gss.size(); ++i) {
      const double x = gss[i];
      if (!std::isfinite(x))
        continue;
      const double z = mad > 0 ? std::abs(x - med) / mad : 0;
      if (z > o.outlier_mads && std::abs(x - med) > 0.1 * med) {
        const auto& s = specimens[group.members[i]];
        group.notes.push_back("specimen '" + s.row.specimen + "' (" + s.row.where() +
                              ") stands far from its group: G_ss " + fmt(x) +
                              " J/m^2 against the group's median " + fmt(med) + " J/m^2 (" +
                              fmt(z) + " robust standard deviations); kept in the group");
      }
    }
  }

  if (group.members.size() < 2) {
    group.notes.push_back(name + ": one specimen, no interval (the bootstrap resamples whole "
                                 "specimens and needs at least two)");
    return;
  }
  if (o.bootstrap_samples <= 0)
    return;
  std::mt19937 rng(group.seed);
  std::uniform_int_distribution<std::size_t> pick(0, group.members.size() - 1);
  std::vector<std::size_t> resample(group.members.size());
  const bool law = group.estimate.ok && group.estimate.has_law;
  if (law) {
    const int nb = std::max(2, o.law_band_points);
    group.law_delta.resize(nb);
    for (int i = 0; i < nb; ++i)
      // The Eq. 6 law's own grid: its delta_c before the correction's shift (the band is of the
      // Eq. 6 law, which the correction does not move).
      group.law_delta[i] = (group.estimate.delta_c - group.correction.dc) * i / (nb - 1);
  }
  std::vector<std::vector<double>> band(group.law_delta.size());
  group.samples.reserve(o.bootstrap_samples);
  for (int b = 0; b < o.bootstrap_samples; ++b) {
    for (auto& r : resample)
      r = group.members[pick(rng)];
    GroupEstimate e = estimate_group(specimens, resample, o, law);
    apply_law_shift(e, group.correction, o);
    std::array<double, n_group_quantities> q;
    for (std::size_t k = 0; k < n_group_quantities; ++k)
      q[k] = e.ok ? quantity_value(e, static_cast<GroupQuantity>(k)) : NAN;
    group.samples.push_back(q);
    if (!e.ok) {
      ++group.failed_samples;
      continue;
    }
    if (law && e.has_law)
      for (std::size_t i = 0; i < group.law_delta.size(); ++i)
        band[i].push_back(law_at(e.laws.delta, e.laws.sigma_eq6, group.law_delta[i]));
  }
  const std::size_t n = group.members.size();
  for (std::size_t k = 0; k < n_group_quantities; ++k) {
    std::vector<double> v;
    for (const auto& s : group.samples)
      v.push_back(s[k]);
    const auto q = static_cast<GroupQuantity>(k);
    const double at = quantity_value(group.estimate, q);
    group.ci[k] =
        widened(make_interval(o, n, at, v), at, chain_accuracy_half_width(group, specimens, o, q));
  }
  // The law's band takes the chain's accuracy as the law's stresses do: the same fraction of
  // the law at each opening.
  const ChainAccuracy u = chain_accuracy(group, specimens, o);
  const double f = bridging_fraction(group.estimate, u);
  group.law_lo.resize(band.size());
  group.law_hi.resize(band.size());
  for (std::size_t i = 0; i < band.size(); ++i) {
    const double at =
        law ? law_at(group.estimate.laws.delta, group.estimate.laws.sigma_eq6, group.law_delta[i])
            : NAN;
    const Interval b = widened(make_interval(o, n, at, band[i]), at,
                               std::isfinite(f) ? normal_quantile(o) * f * std::abs(at) : 0);
    group.law_lo[i] = b.lo;
    group.law_hi[i] = b.hi;
  }
  if (std::isfinite(f) && group.estimate.has_law)
    group.notes.push_back(
        name +
        ": the intervals hold the chain's accuracy on records besides the replicates' "
        "scatter (Campaign/Chain accuracy: G_ss " +
        fmt(100 * o.chain_u_G_ss) + " %, J_tip " +
        (u.u_J > 0 ? fmt(100 * o.chain_u_J_tip) + " %" : std::string("given, not measured: none")) +
        ", standard), which is " + fmt(100 * f) + " % of this group's bridging area G_ss - J_tip " +
        "and of its law's stresses; in quadrature: sigma1 -+" +
        fmt(chain_accuracy_half_width(group, specimens, o, GroupQuantity::sigma1)) + " kPa");
  if (group.failed_samples > 0)
    group.notes.push_back(name + ": " + std::to_string(group.failed_samples) + " of " +
                          std::to_string(o.bootstrap_samples) +
                          " bootstrap samples gave no estimate (left out of the intervals)");
  if (group.members.size() < 4)
    group.notes.push_back(name + ": " + std::to_string(group.members.size()) +
                          " specimens: a bootstrap over so few specimens gives intervals that "
                          "are too narrow (treat them as indicative)");
}

} // namespace fiberbridge::analysis
