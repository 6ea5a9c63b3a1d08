// Rigid laws (sigma(0+) > 0) in the models: extrinsic insertion, one rule for all
// (include/fiberbridge/law/rigid_law.h), and the elastic rise kept for comparisons.
#include "fiberbridge/core/error.h"
#include "fiberbridge/law/exponential_law.h"
#include "fiberbridge/law/piecewise_linear_law.h"
#include "fiberbridge/law/rigid_law.h"

#include <gtest/gtest.h>

#include <string>
#include <vector>

using namespace fiberbridge;
using namespace fiberbridge::law;

TEST(RigidLaw, InsertionNoteOnlyForRigidLaws) {
  const std::string n = rigid_law_insertion_note(make_linear_softening(400e3, 1e-3));
  EXPECT_NE(n.find("inserted extrinsically"), std::string::npos) << n;
  EXPECT_NE(n.find("400 kPa"), std::string::npos) << n;
  EXPECT_EQ(rigid_law_insertion_note(make_bilinear(0.1e-3, 600e3, 2e-3)), "");
  EXPECT_EQ(rigid_law_insertion_note(NoBridgingLaw()), "");
}

TEST(RigidLaw, ModelsNoteOnlyARigidLaw) {
  // note_rigid_law_insertion appends the insertion note for a rigid law and nothing otherwise.
  std::vector<std::string> notes{"earlier"};
  note_rigid_law_insertion(make_bilinear(0.1e-3, 600e3, 2e-3), notes);
  EXPECT_EQ(notes.size(), 1u);
  const auto lin = make_linear_softening(400e3, 1e-3);
  note_rigid_law_insertion(lin, notes);
  ASSERT_EQ(notes.size(), 2u);
  EXPECT_EQ(notes[1], rigid_law_insertion_note(lin));
}

TEST(RigidLaw, ElasticRiseWithStatedAreaChange) {
  const double sc = 400e3, dc = 1e-3, de = 5e-6;
  const auto lin = make_linear_softening(sc, dc);
  const auto reg = with_elastic_rise(lin, de, "test");
  ASSERT_TRUE(reg);
  EXPECT_FALSE(reg->rigid_at_zero_opening());
  // Exact for a polyline: the triangle (0, sc)-(de, sigma(de))-(0, 0) is removed.
  EXPECT_NEAR(reg->area(), lin.area() - 0.5 * sc * de, 1e-9 * lin.area());
  EXPECT_NEAR(reg->initial_stiffness(), lin.envelope(de) / de, 1e-6 * sc / de);
  // Other laws are wrapped: the same triangle to first order in de.
  const ExponentialLaw ex(sc, dc);
  const auto rex = with_elastic_rise(ex, de, "test");
  ASSERT_TRUE(rex);
  EXPECT_NEAR(rex->area(), ex.area() - 0.5 * sc * de, 0.01 * 0.5 * sc * de);
  // A law with its own rise is left alone; a rise past the first kink names the key.
  EXPECT_FALSE(with_elastic_rise(make_bilinear(0.1e-3, 600e3, 2e-3), de, "test"));
  EXPECT_THROW(with_elastic_rise(lin, 2e-3, "Some/Key"), InputError);
  try {
    with_elastic_rise(lin, -1, "Some/Key");
    ADD_FAILURE();
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("Some/Key"), std::string::npos);
  }
}
