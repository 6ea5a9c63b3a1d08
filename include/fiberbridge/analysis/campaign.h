#pragma once
// A durability campaign (issue 33; docs/design.md section 1, "Durability campaign"): every
// specimen of a test series listed in a manifest, grouped by (material, cycles), each group taken
// to the paper's Table 1 quantities (seed section 3.3) by the one-data-set chain (replicates
// averaged, Eq. 6, trilinear fit), with intervals from a bootstrap over whole specimens.
// SI inside: delta in m, sigma in Pa, J in J/m^2.
#include "fiberbridge/analysis/bridging_model.h"
#include "fiberbridge/analysis/inverse.h"
#include "fiberbridge/analysis/rdelta_data.h"
#include "fiberbridge/analysis/record_chain.h"
#include "fiberbridge/analysis/record_reduction.h"
#include "fiberbridge/analysis/steady_state.h"
#include "fiberbridge/analysis/test_record.h"
#include "fiberbridge/law/piecewise_linear_law.h"

#include <array>
#include <cmath>
#include <cstddef>
#include <functional>
#include <memory>
#include <string>
#include <vector>

namespace fiberbridge::analysis {

/// One manifest row: one specimen.
struct CampaignRow {
  std::string file;            ///< resolved against the manifest's folder
  std::string file_as_written; ///< as in the manifest (for tables)
  std::string material, specimen;
  double cycles = 0;
  double delta_c = NAN;       ///< optional per-row delta_c [m]
  double j_tip = NAN;         ///< optional per-row J_tip [J/m^2]
  double width = NAN;         ///< optional per-row width B [m]
  double arm_thickness = NAN; ///< optional per-row arm thickness h [m]
  double initial_crack = NAN; ///< optional per-row a0 from the load line [m]
  double length = NAN;        ///< optional per-row specimen length [m]
  std::string manifest;       ///< the manifest file (for messages)
  std::size_t line = 0;       ///< its line in the manifest
  std::string where() const { return manifest + ":" + std::to_string(line); }
};

struct CampaignManifest {
  std::string source;
  std::vector<CampaignRow> rows;
};

/// Reads `file, material, cycles, specimen` (required) and `delta_c_mm, j_tip_J_m2, width_mm,
/// arm_thickness_mm, a0_mm, length_mm` (optional; an empty cell = not given; the geometry where it
/// differs from the scene's Specimen: raw records are reduced with it, and the group's Fig. 10
/// simulation runs on it). Paths are relative to the manifest's folder; `file` is a file or, for a
/// DIC set, a folder. Throws InputError naming manifest:line for: a missing column, an empty file,
/// material or specimen, cycles not a number >= 0, a file that does not exist, a specimen
/// (material, cycles, specimen) or a file listed twice, a given optional value that is not
/// positive, and a manifest with no rows.
CampaignManifest read_campaign_manifest(const std::string& path);

/// What a row's file is: an R(delta) table (columns delta_mm, R_J_m2), a raw test record, or a
/// DIC set (a folder: DIC frames and the testing machine's record).
enum class SpecimenInput { rdelta, raw_record, dic_set };
const char* to_string(SpecimenInput k);
/// A folder -> dic_set; a file: delta_mm and R_J_m2 in its header -> rdelta, else raw_record.
SpecimenInput classify_specimen_file(const std::string& path);

/// The R(a) estimators of a raw record (record_reduction.h), in the order campaign tables list
/// them: direct energy, ASTM D5528 MBT, CC, MCC, and CBBM's equivalent crack.
enum class RaMethod { energy, MBT, CC, MCC, CBBM };
constexpr std::size_t n_ra_methods = 5;
const char* to_string(RaMethod m);
/// "energy", "MBT", "CC", "MCC" or "CBBM"; InputError naming `where` for another word.
RaMethod parse_ra_method(const std::string& word, const std::string& where);

/// How raw records are read and reduced: the scene's one RecordChainOptions (record_chain.h;
/// a row's width_mm / arm_thickness_mm / length_mm / a0_mm override its Specimen), and the DIC
/// step for DIC sets.
struct RawRecordOptions : RecordChainOptions {
  /// A DIC set's test record (its frames through the DIC step and matched to its machine record,
  /// as `dic` hands `reduce` one); the app provides it (the dic library sits beside analysis).
  /// The record is then reduced as a raw record. Empty: DIC sets are refused.
  std::function<TestRecord(const CampaignRow&)> dic_set;
  /// Which estimator gives an R(a)-only specimen's initiation and plateau (Campaign/R(a)
  /// estimator; docs/design.md, "Durability campaign", says why the default is what it is). The
  /// others are reported beside it.
  RaMethod estimator = RaMethod::energy;
};

/// One specimen as loaded: its R(delta_root) curve when it has one, else (a raw record without
/// delta_root) its R(a) initiation and plateau only.
struct CampaignSpecimen {
  CampaignRow row;
  SpecimenInput input = SpecimenInput::rdelta;
  bool has_rdelta = false;
  Replicate curve;                        ///< R(delta) [SI]; a[] when the file has a_mm
  double initiation = NAN, plateau = NAN; ///< R(a)-only specimens, by the estimator [J/m^2]
  /// R(a)-only specimens: every estimator's initiation and plateau (RaMethod order; NaN where the
  /// record cannot give it, e.g. MBT without crack readings).
  std::array<MethodSummary, n_ra_methods> methods;
  /// Half-width of the direct-energy band of the plateau mean: the band's mean half-width over
  /// the plateau over sqrt(plateau extent / window) [J/m^2]
  double plateau_band = NAN;
  bool steady = false;            ///< its own curve reaches a steady state
  SteadyState own;                ///< its own steady state (when steady)
  double l_b = NAN;               ///< crack growth to delta = d1 [m] (needs a_mm)
  std::vector<std::string> notes; ///< why not steady, and what else to know
  /// A raw record or DIC set with delta_root: the record its curve was reduced from and the
  /// reduction used (the row's overrides in), for the group's correction by simulation.
  std::shared_ptr<const TestRecord> record;
  RecordChainOptions chain;
};

/// A material name as a part of file names: letters, digits, '-' and '_' kept, anything else
/// '_'. The manifest refuses two materials with the same part.
std::string campaign_file_part(const std::string& material);

/// Reads one row's file. An R(delta) file must hold one replicate (one specimen per row); a raw
/// record file one record. Errors name the manifest line and the file.
CampaignSpecimen load_campaign_specimen(const CampaignRow& row, const RawRecordOptions& raw);

struct CampaignOptions;
/// The specimen's own steady state (its curve alone, the group's options and its row's
/// delta_c / J_tip) and l_b; a curve without steady state gets steady = false and a note.
void assess_campaign_specimen(CampaignSpecimen& s, const CampaignOptions& o);

/// A group's law corrected by simulation (identify/chain_correction.h): the law and J_tip whose
/// simulated records the group's chain measures as it measured the members' records.
struct LawCorrection {
  bool converged = false;
  law::TrilinearParameters law; ///< SI
  double j_tip = NAN;
  int simulations = 0;
  std::vector<std::string> notes;
};

/// The shift the correction moves a group's law by (corrected - the chain's), applied to the point
/// estimate and to every bootstrap sample, so that the interval moves with it.
struct LawShift {
  bool applied = false;
  double d1 = 0, s1 = 0, d2 = 0, s2 = 0, dc = 0, j_tip = 0; ///< SI
};

/// The settings every group shares (the scene's Data, Fit, Bridging and Campaign sections).
struct CampaignOptions {
  // Data (seed Eq. 6)
  int intervals = 100, half_width = 3, grid_points = 401;
  double delta_c = 0, j_tip = 0; ///< 0: automatic (a row's value overrides)
  // Fit
  double d1 = 0.1e-3, d2 = 1.0e-3;
  bool free_breakpoints = false;
  double d1_min = 0.02e-3, d1_max = 0.5e-3, d2_max = 0;
  // Bridging (rho_b range: seed section 3.4, sigma_1 at `rho_opening`)
  BridgingFiber fiber_low = seed_tracheid_fiber(), fiber_high = seed_bundle_fiber(50);
  double rho_opening = 0.1e-3;
  // Campaign
  int bootstrap_samples = 1000;
  unsigned seed = 1;
  double confidence = 0.95;
  /// How the bootstrap samples become an interval (docs/design.md section 1, "Durability
  /// campaign"). A percentile interval cannot reach beyond the range the n specimens span, which
  /// holds the true mean with probability 1 - 2^(1-n) at best (0.94 for n = 5), so with 4-10
  /// specimens it covers less than its level; student_t (estimate +- sqrt(n/(n-1)) t_{n-1}
  /// times the bootstrap standard deviation) does not have that limit.
  enum class Interval { student_t, expanded_percentile, percentile };
  Interval interval = Interval::student_t;
  /// A specimen stands far from its group when its G_ss differs from the group's median by more
  /// than this many robust standard deviations (1.4826 MAD) and by more than 10 % of the median.
  double outlier_mads = 3.5;
  int law_band_points = 101; ///< points of the law band grid over [0, delta_c]
  /// The chain's own accuracy on records: relative standard uncertainties of the G_ss and J_tip
  /// it measures from a record (Campaign/Chain accuracy of G_ss, of J_tip; the RMS errors of the
  /// chain on the virtual tests of the 20 Table 1 laws, docs/verification.md, "The chain's
  /// accuracy in the intervals"). The bootstrap over specimens holds the replicates' scatter, not
  /// an error every record of the chain shares; this term, added in quadrature
  /// (chain_accuracy_half_width), does. Only groups whose members are records with delta_root
  /// (raw records or DIC sets) get it: the chain measured their curves. 0: the replicates alone.
  double chain_u_G_ss = 0.020, chain_u_J_tip = 0.021;
  /// Fit/Model correction: given a group's members (each with its record) and the law and J_tip
  /// the group's chain gave, the law corrected by simulation. Set by the app where the beam is
  /// built; empty: no correction. Groups whose members are R(delta) tables are never corrected
  /// (there is no record to simulate).
  std::function<LawCorrection(const std::vector<const CampaignSpecimen*>& members,
                              const law::TrilinearParameters& law, double j_tip)>
      correct_law;
};

/// The Table 1 quantities of one group, from one set of specimens (the group or a resample).
struct GroupEstimate {
  bool ok = false;
  std::string failure; ///< why not ok (no steady state, fit failed, ...)
  bool has_law = false;
  double j_tip = NAN, G_ss = NAN, delta_c = NAN;
  law::TrilinearParameters tri;
  double J1 = NAN, J2 = NAN;
  double l_b = NAN;                     ///< mean over the specimens that have it [m]
  double rho_low = NAN, rho_high = NAN; ///< [1/m^2]
  double rms_residual = NAN;            ///< [Pa]
  // Kept only for the point estimate (keep_curves):
  RDeltaCurve curve;
  ExtractedLaws laws;
  SteadyState steady;
};

/// The group's chain on `members` (indices into `specimens`): averaged R(delta) (replicates
/// averaged as `extract` does), steady state (Data defaults, the rows' delta_c_mm / j_tip_J_m2
/// averaged over the members that give them), Eq. 6 beside dR/ddelta, the trilinear fit with area
/// G_ss - J_tip, J1, J2, l_b and the rho_b range. R(a)-only groups: J_tip and G_ss are the means of
/// the records' initiation and plateau, no law. Never throws for the data: a failure (e.g. no
/// steady state in a resample) comes back in `failure`.
GroupEstimate estimate_group(const std::vector<CampaignSpecimen>& specimens,
                             const std::vector<std::size_t>& members, const CampaignOptions& o,
                             bool keep_curves);

/// The scalar quantities of a group, in a fixed order (the keys of summary.json).
enum class GroupQuantity {
  d1,
  sigma1,
  d2,
  sigma2,
  delta_c,
  J1,
  J2,
  G_ss,
  J_tip,
  l_b,
  rho_low,
  rho_high,
  count
};
constexpr std::size_t n_group_quantities = static_cast<std::size_t>(GroupQuantity::count);
/// Value in the units of the tables (mm, kPa, J/m^2, 1/mm^2).
double quantity_value(const GroupEstimate& g, GroupQuantity q);
/// summary.json key: d1_mm, sigma1_kPa, ..., J1_J_m2, ..., l_b_mm, rho_b_low_per_mm2, ...
const char* quantity_key(GroupQuantity q);

struct Interval {
  double lo = NAN, hi = NAN;
};

/// One group: the specimens, the point estimate, the bootstrap.
struct CampaignGroup {
  std::string material;
  double cycles = 0;
  std::vector<std::size_t> members; ///< indices into the campaign's specimens, manifest order
  GroupEstimate estimate;
  unsigned seed = 0; ///< this group's bootstrap seed (from the campaign's seed)
  /// Bootstrap: per sample the quantities (NaN row for a failed sample), in sample order.
  std::vector<std::array<double, n_group_quantities>> samples;
  int failed_samples = 0;
  std::array<Interval, n_group_quantities> ci;
  /// The law's band on law_delta (the point estimate's grid over [0, delta_c]) [Pa].
  std::vector<double> law_delta, law_lo, law_hi;
  std::vector<std::string> notes;
  /// The correction by simulation, applied to `estimate` and `samples` (kept with the group for
  /// --resume and the MPI hand-out: a restored group's recomputed estimate gets it again).
  LawShift correction;
  bool has_interval() const { return !samples.empty(); }
};

/// `shift` added to a law estimate: the trilinear law and J_tip, then what follows from them
/// (delta_c, J1, J2 and the rho_b range at the options' opening).
void apply_law_shift(GroupEstimate& e, const LawShift& shift, const CampaignOptions& o);

/// The half-width the chain's accuracy (CampaignOptions::chain_u_G_ss, chain_u_J_tip) adds in
/// quadrature to quantity q's interval, in the units of the tables, at the options' confidence
/// (normal quantile: a systematic term of known size, not a sample's): u_G G_ss for G_ss, u_J J_tip
/// for J_tip, and for the law's stresses and energies (sigma1, sigma2, J1, J2) the same fraction as
/// of the bridging area G_B = G_ss - J_tip, u(G_B)^2 = (u_G G_ss)^2 + (u_J J_tip)^2 (Eq. 6's law
/// scales with R - J_tip, and the fit keeps its area G_B). 0 for the other quantities, for a group
/// without an estimate, and for a group not made of records with delta_root.
double chain_accuracy_half_width(const CampaignGroup& group,
                                 const std::vector<CampaignSpecimen>& specimens,
                                 const CampaignOptions& o, GroupQuantity q);

/// The group's seed: the campaign's seed mixed with the group's key (material, cycles) by a
/// fixed hash, so a group's resamples do not depend on which other groups exist or on the order
/// or rank they run on.
unsigned group_seed(unsigned campaign_seed, const std::string& material, double cycles);

/// The group's (material, cycles) as the stem of its file names, e.g. "PVA_control_c0": the
/// material as a file-name part (core/format.h), "_c", the cycles as fmt prints them. Every file
/// of a group (its law, its Fig. 10 curves, its resume records, its DIC records) carries it.
std::string group_file_stem(const std::string& material, double cycles);

/// Groups by (material, cycles) in order of first appearance; checks one input kind per group
/// (InputError naming both manifest lines otherwise).
std::vector<CampaignGroup> make_campaign_groups(const std::vector<CampaignSpecimen>& specimens);

/// Point estimate, notes on specimens (not steady, far from the group) and the bootstrap of one
/// group (resampling whole specimens with replacement, o.bootstrap_samples times, std::mt19937
/// seeded with group.seed: deterministic). A group of one specimen gets no interval (said in
/// its notes).
void analyse_campaign_group(CampaignGroup& group, const std::vector<CampaignSpecimen>& specimens,
                            const CampaignOptions& o);

} // namespace fiberbridge::analysis
