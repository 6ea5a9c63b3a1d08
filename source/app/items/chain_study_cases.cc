// The design of `chain study` (chain_study_cases.h): one factor at a time around the scene's own
// virtual test, because a full factorial of laws x layouts x noise x rates would cost hours of
// FEM runs and tell little more than the one-factor lines do about where each error comes from.
#include "items/chain_study_cases.h"

#include "fiberbridge/analysis/campaign_synthetic.h"
#include "fiberbridge/core/error.h"
#include "fiberbridge/core/format.h"
#include "fiberbridge/core/units.h"

#include <cmath>
#include <limits>
#include <sstream>

namespace fiberbridge::app {

using namespace units;

namespace {

const double no_value = std::numeric_limits<double>::quiet_NaN();

} // namespace

std::vector<ChainCase> chain_study_cases(const analysis::PropertyTable& table1) {
  std::vector<ChainCase> v;
  v.push_back({"base", "base", no_value, {}, false});
  // The 20 Table 1 laws at the base (J_tip 200 J/m^2 for all: Table 1 prints none).
  for (const auto& t : analysis::table1_truth(table1, 200)) {
    const std::string name = t.material + "_c" + num(t.cycles);
    v.push_back({name,
                 "law",
                 no_value,
                 {"Cohesive law/Type=trilinear",
                  "Cohesive law/Points=0.1:" + num(t.law.s1 / kPa) + ", 1.0:" + num(t.law.s2 / kPa),
                  "Cohesive law/Delta c=" + num(t.law.dc / mm), "Cohesive law/J tip=200"},
                 true});
  }
  // Other shapes: the fit is trilinear at the paper's d1, d2 whatever the true law; its truth
  // at d1 and d2 is the true envelope there.
  v.push_back({"linear",
               "law",
               no_value,
               {"Cohesive law/Type=linear", "Cohesive law/Peak stress=400",
                "Cohesive law/Delta c=3", "Cohesive law/J tip=200"}});
  v.push_back({"bilinear",
               "law",
               no_value,
               {"Cohesive law/Type=bilinear", "Cohesive law/Points=0.2:500",
                "Cohesive law/Delta c=3", "Cohesive law/J tip=200"}});
  v.push_back({"exponential",
               "law",
               no_value,
               {"Cohesive law/Type=exponential", "Cohesive law/Peak stress=500",
                "Cohesive law/Delta c=3", "Cohesive law/J tip=200"}});
  // Zone length follows delta_c: the PVA peaks with a short and a long tail.
  v.push_back({"short_zone",
               "law",
               no_value,
               {"Cohesive law/Type=trilinear", "Cohesive law/Points=0.1:661, 1.0:187",
                "Cohesive law/Delta c=1.5", "Cohesive law/J tip=200"}});
  v.push_back({"long_zone",
               "law",
               no_value,
               {"Cohesive law/Type=trilinear", "Cohesive law/Points=0.1:661, 1.0:187",
                "Cohesive law/Delta c=9", "Cohesive law/J tip=200"}});
  // Layouts (GOM: the FEM writes it; whether the DIC reader takes it is part of the answer).
  v.push_back({"dice", "layout", no_value, {"FEM/Virtual DIC/Format=dice"}});
  v.push_back({"gom", "layout", no_value, {"FEM/Virtual DIC/Format=gom"}});
  v.push_back({"y_down", "layout", no_value, {"FEM/Virtual DIC/Y axis=down"}});
  v.push_back({"px", "layout", no_value, {"FEM/Virtual DIC/Coordinates=px"}});
  v.push_back({"dice_px_y_down",
               "layout",
               no_value,
               {"FEM/Virtual DIC/Format=dice", "FEM/Virtual DIC/Coordinates=px",
                "FEM/Virtual DIC/Y axis=down"}});
  for (double n : {0.0, 0.001, 0.005})
    v.push_back(
        {"noise_" + num(n), "noise_mm", n, {"FEM/Virtual DIC/Displacement noise=" + num(n)}});
  for (double f : {0.01, 0.02, 0.05})
    v.push_back(
        {"failed_" + num(f), "failed_fraction", f, {"FEM/Virtual DIC/Failed fraction=" + num(f)}});
  for (double r : {0.5, 2.0, 4.0})
    v.push_back(
        {"frame_rate_" + num(r), "frame_rate_Hz", r, {"FEM/Virtual DIC/Frame rate=" + num(r)}});
  for (double c : {2.0, 5.0, 20.0})
    v.push_back({"crosshead_" + num(c),
                 "crosshead_mm_min",
                 c,
                 {"FEM/Virtual DIC/Crosshead rate=" + num(c)}});
  return v;
}

std::vector<ChainCase> select_chain_cases(const std::vector<ChainCase>& all,
                                          const std::string& list, const std::string& where) {
  const auto names = split_list(list, ',');
  if (names.size() == 1 && names[0] == "all")
    return all;
  if (names.empty())
    throw InputError(where + ": no case named (expected all or a list of case names)");
  std::vector<ChainCase> out;
  for (const auto& n : names) {
    const ChainCase* found = nullptr;
    for (const auto& c : all)
      if (c.name == n)
        found = &c;
    if (!found) {
      std::string known;
      for (const auto& c : all)
        known += (known.empty() ? "" : ", ") + c.name;
      throw InputError(where + ": unknown case '" + n + "'; known: all, " + known);
    }
    out.push_back(*found);
  }
  return out;
}

} // namespace fiberbridge::app
