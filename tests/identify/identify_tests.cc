// Identification of the bridging law from test records (include/fiberbridge/identify/identify.h).
#include "fiberbridge/core/error.h"
#include "fiberbridge/core/units.h"
#include "fiberbridge/identify/identify.h"

#include <gtest/gtest.h>

#include <cstdio>

using namespace fiberbridge;
using namespace fiberbridge::identify;
using units::mm;

namespace {

/// The shared records' specimen (data/dcb_records/README.md) with the quoted moduli.
law::Specimen record_specimen() {
  law::Specimen s;
  s.width = 25 * mm;
  s.height = 5.4 * mm;
  s.length = 123 * mm;
  s.initial_crack = 35 * mm;
  return s;
}
law::Material quoted_material() {
  law::Material m;
  m.E_L = 19.3e9;
  m.E_T = 6.11e9;
  m.G_LT = 2.288e9;
  m.nu_LT = 0.3;
  return m;
}

analysis::TestRecord shared_record(const std::string& name) {
  analysis::RecordReadOptions o;
  o.columns = analysis::RecordColumnMap::parse(
      "time_s: Time, opening_mm: Disp, load_N: Force, a_mm: CrackExt", "test");
  return analysis::read_test_records(
             std::string(FIBERBRIDGE_DATA_DIR) + "/dcb_records/" + name + "_Toughness.csv", o)
      .at(0);
}

} // namespace

TEST(Identify, SharedRecords) {
  for (const char* name : {"DCB-01", "DCB-02", "DCB-03", "DCB-05"}) {
    const auto rec = shared_record(name);
    IdentifySettings s;
    const auto id = identify_law({rec}, record_specimen(), quoted_material(), s,
                                 [](const std::string& l) { std::printf("%s\n", l.c_str()); });
    std::printf("%s: E_L %.4g GPa, d1 %.4g mm s1 %.4g kPa d2 %.4g mm s2 %.4g kPa dc %.4g mm "
                "J_tip %.4g G_ss %.4g | load rms %.4g %% crack rms %.4g mm | %d evals, %d runs, "
                "%.3g s (forward %.3g s)\n",
                name, id.records[0].E_L * 1e-9, id.law.d1 / mm, id.law.s1 / 1e3, id.law.d2 / mm,
                id.law.s2 / 1e3, id.law.dc / mm, id.j_tip, id.g_ss, 100 * id.load_rms_rel,
                id.crack_rms / mm, id.evaluations, id.forward_runs, id.wall_time_s,
                id.forward_time_s);
    for (const auto& p : id.parameters)
      std::printf("  %s = %.4g +- %.3g\n", p.name.c_str(), p.value, p.std_error);
    for (const auto& n : id.notes)
      std::printf("  note: %s\n", n.c_str());
  }
}
