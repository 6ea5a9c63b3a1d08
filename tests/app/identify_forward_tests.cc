// The FEM as identify's forward model (issue 34 item 4; app/items/fem_forward_model.h): a record
// written by the FEM from a known law (the IdentifyFromFem set-up of
// tests/identify/identify_fem_tests.cc on a coarse mesh) identified with the beam and then with the
// FEM from the beam's optimum, as `Identify/Forward model = fem` does (item_identify.cc,
// fit_records).
#include "../identify/record_specimen.h"
#include "fiberbridge/analysis/synthetic_record.h"
#include "fiberbridge/app/items/fem_forward_model.h"
#include "fiberbridge/core/units.h"
#include "fiberbridge/fem/distributed_dcb.h"
#include "fiberbridge/identify/identify.h"
#include "fiberbridge/law/piecewise_linear_law.h"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>

using namespace fiberbridge;
using identify::testing::record_material;
using identify::testing::record_specimen;
using units::kPa;
using units::mm;

namespace {

void print(const char* route, const identify::Identification& id,
           const law::TrilinearParameters& truth) {
  std::printf("%s: d1 %.4g mm s1 %.4g kPa d2 %.4g mm s2 %.4g kPa dc %.4g mm J_tip %.4g; J_c %.5g "
              "(true %.5g, %+.2f %%); chi2 %.5g, load rms %.3g %%, crack rms %.3g mm; %d "
              "evaluations, %d forward runs, %.3g s\n",
              route, id.law.d1 / mm, id.law.s1 / kPa, id.law.d2 / mm, id.law.s2 / kPa,
              id.law.dc / mm, id.j_tip, id.law.area(), truth.area(),
              100 * (id.law.area() / truth.area() - 1), id.chi2, 100 * id.load_rms_rel,
              id.crack_rms / mm, id.evaluations, id.forward_runs, id.wall_time_s);
}

} // namespace

TEST(IdentifyForwardModel, FemRecordIdentifiedWithTheFem) {
  // The law and J_tip of IdentifyFromFem (J_c 722.5 J/m^2, G_ss 1122.5 J/m^2).
  const law::TrilinearParameters truth{0.05 * mm, 700 * kPa, 1.5 * mm, 100 * kPa, 4 * mm};
  const double j_tip = 400;
  // A coarse mesh keeps the test cheap: 2.5 mm elements (35 mm / 14; four layers per 2.7 mm
  // arm, aspect 3.7 under the bound 4), the estimated zone (29 mm) over 11 of them.
  fem::FemParameters fp;
  fp.mesh.element_size = 2.5 * mm;
  const auto specimen = record_specimen();
  const auto run = fem::simulate_dcb(specimen, record_material(25e9), law::make_trilinear(truth),
                                     j_tip, fp, "", {}, MPI_COMM_SELF);
  ASSERT_TRUE(run.reached_steady_state);
  analysis::SyntheticRecordOptions ro; // as IdentifyFromFem: a 1 Hz machine, 0.5 N load noise
  ro.sampling_rate_hz = 1;
  ro.load_noise = 0.5;
  ro.crack_reading_interval = 8;
  ro.crack_reading_noise = 0.3e-3;
  ro.seed = 12;
  const auto rec = analysis::make_synthetic_record(run, ro, "fem_synthetic");

  identify::IdentifySettings s;
  s.large_displacement = false; // the record's FEM is geometrically linear
  s.load_scatter = 0.005;
  s.crack_scatter = 0.3 * mm;
  s.starts = 1;
  // A CI budget: the beam from the records' start values with a third of the default evaluations
  // (it ends within about 1 % of its J_c with the default 300, docs/verification.md).
  s.max_evaluations = 100;
  // The quoted modulus is wrong on purpose (both routes calibrate it from the record).
  const auto beam = identify::identify_law({rec}, specimen, record_material(19.3e9), s);
  print("beam", beam, truth);

  identify::IdentifySettings from_beam = s;
  from_beam.start_law = beam.law;
  from_beam.start_j_tip = beam.j_tip;
  // BOBYQA's first quadratic model takes 2 x 6 + 1 = 13 evaluations: the FEM gets those and a
  // step or two from the beam's optimum, each round (about 40 FEM runs with the Jacobian's).
  from_beam.max_evaluations = 16;
  from_beam.relative_tolerance = 1e-3;
  const auto forward = app::fem_forward_model(fp);
  const auto fem =
      identify::identify_law({rec}, specimen, record_material(19.3e9), from_beam, {}, {}, forward);
  print("fem", fem, truth);
  for (const auto& n : fem.notes)
    std::printf("  note: %s\n", n.c_str());
  // Both misfits are printed above (docs/verification.md, "Forward model of identify"). Measured
  // on this record: beam J_c -3.16 %, chi^2 540, load RMS 0.71 %; FEM J_c -2.33 %, chi^2 578,
  // load RMS 0.75 %. The FEM's chi^2 at the beam's law is above the beam's own: the beam's law
  // carries the beam's model error, and 16 evaluations a round from there move the FEM only
  // locally, so the misfits are stated, not ordered. What the FEM must do is recover the law at
  // least as well: J_c within the beam's error plus 1 % (the 0.5 % load noise moves J_c by about
  // that between neighbouring optima), and reach the noise as IdentifyFromFem asks (load RMS
  // under 2x the 0.5 % noise).
  EXPECT_LE(std::abs(fem.law.area() / truth.area() - 1),
            std::abs(beam.law.area() / truth.area() - 1) + 0.01);
  EXPECT_LT(fem.load_rms_rel, 0.01);
  // The FEM ran: its own runs (the start, a polish round, the Jacobian's 13) beside the
  // compliance passes.
  EXPECT_GE(fem.forward_runs, 13 + 16);
}
