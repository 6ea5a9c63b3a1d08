// identify's fit in the archive (app/run/identify_resume.h) and the resume record around any
// payload (app/run/resume_store.h): a fit kept for --resume or sent from another rank comes back
// exactly; a record is restored only under the inputs it was made with, and a record that is not
// one (cut short, another file) is an InputError naming it.
#include "fiberbridge/app/run/resume_store.h"
#include "fiberbridge/core/error.h"
#include "fiberbridge/core/json_archive.h"
#ifdef FIBERBRIDGE_HAVE_IDENTIFY
#include "fiberbridge/app/run/identify_resume.h"
#endif

#include <gtest/gtest.h>

#include <cstring>
#include <filesystem>
#include <fstream>
#include <limits>
#include <sstream>

namespace fs = std::filesystem;
using namespace fiberbridge;

namespace {

std::uint64_t bits(double v) {
  std::uint64_t b = 0;
  std::memcpy(&b, &v, sizeof b);
  return b;
}

/// Element-wise by bits (a NaN must come back as that NaN).
void expect_same_bits(const std::vector<double>& a, const std::vector<double>& b,
                      const std::string& what) {
  ASSERT_EQ(a.size(), b.size()) << what;
  for (std::size_t i = 0; i < a.size(); ++i)
    EXPECT_EQ(bits(a[i]), bits(b[i])) << what << "[" << i << "]";
}

fs::path fresh_dir(const std::string& name) {
  const fs::path dir = fs::path(FIBERBRIDGE_WORK_DIR) / name;
  fs::remove_all(dir);
  fs::create_directories(dir);
  return dir;
}

const double nan = std::numeric_limits<double>::quiet_NaN();

} // namespace

#ifdef FIBERBRIDGE_HAVE_IDENTIFY
namespace {

/// Every field set, none to its default, with the values a decimal form would lose.
identify::Identification sample_fit() {
  identify::Identification id;
  id.law = {0.1e-3 / 3, 661e3 + 1.0 / 3, 1.1e-3, 187e3, 6e-3};
  id.j_tip = 200.0 / 3;
  id.g_ss = 1101.0 + 1e-12;
  id.j_c_std_error = nan;
  for (int k = 0; k < 2; ++k) {
    identify::RecordFit f;
    f.name = k == 0 ? "DCB-05" : std::string("odd\0name,\xff", 10);
    f.initial_crack = 0.05 + k / 3.0;
    f.initial_compliance = 1e-6 / 7;
    f.E_L = 19.3e9 + k;
    f.peak_load = 412.123456789012345;
    f.load_rms_rel = 0.0123;
    f.crack_rms = k == 0 ? nan : 1e-4;
    f.max_opening_over_a = 0.2;
    f.min_F = 0.97;
    f.opening = {0, 1e-4 / 3, 2e-4};
    f.load = {0, 100.0 / 3, nan};
    f.crack_length = k == 0 ? std::vector<double>{} : std::vector<double>{0.05, 0.051};
    f.model_load = {0, 33.3, 66.6};
    f.model_crack_length = {};
    id.records.push_back(f);
  }
  id.load_rms_rel = 0.02;
  id.crack_rms = 2e-4 / 3;
  id.chi2 = 123.456;
  id.n_residuals = 4321;
  id.evaluations = 77;
  id.forward_runs = 901;
  id.forward_time_s = 1.5;
  id.wall_time_s = 2.25;
  id.parameters = {{"d1_mm", 0.1 / 3, nan}, {"J_tip_J_m2", 66.7, 1.25}};
  id.correlation = {{1, -0.5}, {}, {-0.5, 1, nan}};
  id.notes = {"d2 and sigma2 move together", ""};
  id.band_delta = {0, 1e-3};
  id.band_sigma = {661e3, 0};
  id.band_lo = {};
  id.band_hi = {700e3, nan};
  return id;
}

void expect_same_fit(const identify::Identification& a, const identify::Identification& b) {
  expect_same_bits(
      {a.law.d1, a.law.s1, a.law.d2, a.law.s2, a.law.dc, a.j_tip, a.g_ss, a.j_c_std_error,
       a.load_rms_rel, a.crack_rms, a.chi2, a.forward_time_s, a.wall_time_s},
      {b.law.d1, b.law.s1, b.law.d2, b.law.s2, b.law.dc, b.j_tip, b.g_ss, b.j_c_std_error,
       b.load_rms_rel, b.crack_rms, b.chi2, b.forward_time_s, b.wall_time_s},
      "scalars");
  EXPECT_EQ(a.n_residuals, b.n_residuals);
  EXPECT_EQ(a.evaluations, b.evaluations);
  EXPECT_EQ(a.forward_runs, b.forward_runs);
  ASSERT_EQ(a.records.size(), b.records.size());
  for (std::size_t k = 0; k < a.records.size(); ++k) {
    const auto &x = a.records[k], &y = b.records[k];
    EXPECT_EQ(x.name, y.name);
    expect_same_bits({x.initial_crack, x.initial_compliance, x.E_L, x.peak_load, x.load_rms_rel,
                      x.crack_rms, x.max_opening_over_a, x.min_F},
                     {y.initial_crack, y.initial_compliance, y.E_L, y.peak_load, y.load_rms_rel,
                      y.crack_rms, y.max_opening_over_a, y.min_F},
                     "record scalars");
    expect_same_bits(x.opening, y.opening, "opening");
    expect_same_bits(x.load, y.load, "load");
    expect_same_bits(x.crack_length, y.crack_length, "crack_length");
    expect_same_bits(x.model_load, y.model_load, "model_load");
    expect_same_bits(x.model_crack_length, y.model_crack_length, "model_crack_length");
  }
  ASSERT_EQ(a.parameters.size(), b.parameters.size());
  for (std::size_t k = 0; k < a.parameters.size(); ++k) {
    EXPECT_EQ(a.parameters[k].name, b.parameters[k].name);
    expect_same_bits({a.parameters[k].value, a.parameters[k].std_error},
                     {b.parameters[k].value, b.parameters[k].std_error}, "parameter");
  }
  ASSERT_EQ(a.correlation.size(), b.correlation.size());
  for (std::size_t k = 0; k < a.correlation.size(); ++k)
    expect_same_bits(a.correlation[k], b.correlation[k], "correlation");
  EXPECT_EQ(a.notes, b.notes);
  expect_same_bits(a.band_delta, b.band_delta, "band_delta");
  expect_same_bits(a.band_sigma, b.band_sigma, "band_sigma");
  expect_same_bits(a.band_lo, b.band_lo, "band_lo");
  expect_same_bits(a.band_hi, b.band_hi, "band_hi");
}

} // namespace

TEST(IdentifyArchive, FitComesBackBitForBit) {
  const auto id = sample_fit();
  expect_same_fit(from_archive_bytes<identify::Identification>(to_archive_bytes(id, "fit"), "fit"),
                  id);
  // An empty fit (no records, no parameters) too.
  const identify::Identification empty;
  expect_same_fit(
      from_archive_bytes<identify::Identification>(to_archive_bytes(empty, "fit"), "fit"), empty);
}

TEST(IdentifyArchive, FitKeptForResumeComesBackUnderTheSameInputs) {
  const fs::path dir = fresh_dir("identify_archive");
  const app::Fingerprint inputs = {{"Identify/Starts", "2"}, {"Test record 1", "DCB-05, hash 1"}};
  app::keep_finished_unit(dir.string(), "identify_joint", inputs, sample_fit());
  EXPECT_FALSE(app::find_finished_unit<identify::Identification>(dir.string(), false,
                                                                 "identify_joint", inputs))
      << "without --resume nothing is restored";
  const auto back = app::find_finished_unit<identify::Identification>(dir.string(), true,
                                                                      "identify_joint", inputs);
  ASSERT_TRUE(back);
  expect_same_fit(*back, sample_fit());
  EXPECT_FALSE(app::find_finished_unit<identify::Identification>(dir.string(), true,
                                                                 "identify_record_1", inputs))
      << "no record, nothing restored";
}
#endif

TEST(ResumeRecord, ChangedInputsAreNamed) {
  const fs::path dir = fresh_dir("resume_record_inputs");
  const app::Fingerprint inputs = {{"Beam/Number of elements", "100"}, {"law in effect", "x"}};
  app::keep_finished_unit(dir.string(), "study_beam_level0", inputs, std::string("payload"));
  auto message = [&](const app::Fingerprint& now) -> std::string {
    try {
      app::find_finished_unit<std::string>(dir.string(), true, "study_beam_level0", now);
    } catch (const InputError& e) {
      return e.what();
    }
    return "";
  };
  EXPECT_EQ(message(inputs), "");
  EXPECT_NE(message({{"Beam/Number of elements", "200"}, {"law in effect", "x"}})
                .find("Beam/Number of elements was '100', now '200'"),
            std::string::npos);
  EXPECT_NE(message({{"law in effect", "x"}}).find("Beam/Number of elements is gone"),
            std::string::npos);
  EXPECT_NE(message({{"Beam/Number of elements", "100"}, {"law in effect", "x"}, {"new", "1"}})
                .find("new is new"),
            std::string::npos);
}

TEST(ResumeRecord, ARecordOfAnotherPayloadOrUnitIsAClearError) {
  // A record renamed by hand to another unit, and a payload read as another type: the record
  // says whose it is, and the archive's bounds stop a read past its end.
  const fs::path dir = fresh_dir("resume_record_other");
  const app::Fingerprint inputs = {{"k", "v"}};
  Json summary = {{"beam", {{"G_ss_J_m2", 1101.5}}}};
  app::keep_finished_unit(dir.string(), "item_beam", inputs, summary);
  fs::copy_file(dir / "resume" / "item_beam.rec", dir / "resume" / "item_fem.rec");
  try {
    app::find_finished_unit<Json>(dir.string(), true, "item_fem", inputs);
    ADD_FAILURE() << "a record of item_beam was restored as item_fem";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("a record of 'item_beam', not of 'item_fem'"),
              std::string::npos)
        << e.what();
  }
  EXPECT_EQ(*app::find_finished_unit<Json>(dir.string(), true, "item_beam", inputs), summary);
  EXPECT_THROW(
      (app::find_finished_unit<std::vector<double>>(dir.string(), true, "item_beam", inputs)),
      InputError);
}
