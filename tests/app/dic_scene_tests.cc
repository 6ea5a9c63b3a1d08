// The dic item in a scene (issue 32 item 4): synthetic DIC frames of a DCB (VIC layout, pixels,
// y down, failed points; tests/dic/dic_synthetic.h) and the testing machine's record of the same
// test, through `dic, reduce` into R(a); the CLI `fiberbridge dic`; bad input failing cleanly.
#include "../dic/dic_synthetic.h"
#include "fiberbridge/core/csv.h"
#include "scene_runner.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <fstream>
#include <iomanip>
#include <sstream>

using namespace fiberbridge;
using namespace fiberbridge::test;

namespace {

// The test: linear-elastic arms (E = 12 GPa, B = 20 mm, h = 5 mm each), a0 = 50 mm, a constant
// R = 300 J/m^2 once the crack runs (from t = 8 s, 0.5 mm/s), so that the load and opening follow
// from corrected-free beam theory: C = 8 a^3/(E B h^3), G = 12 P^2 a^2/(E B^2 h^3).
constexpr double E = 12e9, B = 0.02, h_arm = 0.005, a0 = 0.05, R = 300;
double crack(double t) {
  return t < 8 ? a0 : a0 + 0.5e-3 * (t - 8);
}
/// R at crack length a: R, plus `bridging` J/m^2 rising with the notch-root opening the frames
/// give (delta_root = A (a - a0)^2, SyntheticDcb with A = 1.2/m), 1 - exp(-delta_root / 0.04 mm):
/// a bridged crack (0: the constant R of the tests above).
double resistance(double a, double bridging) {
  const double delta_root = 1.2 * (a - a0) * (a - a0);
  return R + bridging * (1 - std::exp(-delta_root / 0.04e-3));
}
double load(double t, double bridging = 0) {
  const double a = crack(t);
  const double p_growth =
      std::sqrt(resistance(a, bridging) * E * B * B * h_arm * h_arm * h_arm / (12 * a * a));
  return t < 8 ? p_growth * t / 8 : p_growth;
}
double opening(double t, double bridging = 0) {
  const double a = crack(t);
  return 8 * a * a * a / (E * B * h_arm * h_arm * h_arm) * load(t, bridging);
}

/// Writes the frames (1 Hz from t = 0 to 40 s) and the machine record (10 Hz) into `dir`; `seed`
/// seeds the frames' noise (another specimen of the same test), `bridging` makes R rise
/// (resistance).
void write_test(const fs::path& dir, unsigned seed = 100, double bridging = 0) {
  fs::create_directories(dir / "frames");
  SyntheticDcb dcb;
  dcb.noise_v = 1e-6;
  dcb.fail_fraction = 0.02;
  dic::FrameGeometry g;
  g.pixels = true;
  g.pixel_size = 0.05e-3;
  g.y_down = true;
  g.crack_plane_y = 512;
  g.notch_root_x = 300;
  for (int k = 0; k <= 40; ++k) {
    char name[64];
    std::snprintf(name, sizeof name, "dcb_%04d_0.csv", k);
    write_frame((dir / "frames" / name).string(),
                dcb.frame(crack(k) - a0, std::min(1.0, (k + 1) / 8.0), seed + k), g, Out::vic);
  }
  std::ofstream m(dir / "machine.csv");
  m << "Time (s),Extension (mm),Load (N)\n";
  for (int i = 0; i <= 405; ++i)
    m << 0.1 * i << "," << opening(0.1 * i, bridging) * 1e3 << "," << load(0.1 * i, bridging)
      << "\n";
}

const char* scene = R"(set Output directory = out
set Run = dic, reduce
subsection Specimen
  set Width = 20
  set Height = 10
  set Length = 200
  set Initial crack = 50
end
subsection DIC
  set Frames = frames/dcb_*_0.csv
  set Format = vic
  set Coordinates = px
  set Pixel size = 0.05
  set Y axis = down
  set Crack plane y = 512
  set Notch root x = 300
  set Growth direction = +x
  set Frame rate = 1
  set First frame time = 0
  set Strain threshold = 0.01
  set Extensometer gauge length = 2
end
subsection Test
  set Files = machine.csv
  set Columns = time_s: Time (s), opening_mm: Extension (mm), load_N: Load (N)
end
)";

} // namespace

TEST(AppDic, SceneRunsDicThenReduceOnItsRecord) {
  const fs::path dir = work("dic_scene");
  fs::remove_all(dir);
  write_test(dir);
  std::ofstream(dir / "scene.prm") << scene;
  const std::string cmd = "cd '" + dir.string() + "' && '" + FIBERBRIDGE_BIN +
                          "' run scene.prm > stdout.txt 2> stderr.txt";
  ASSERT_EQ(std::system(cmd.c_str()), 0) << "see " << (dir / "stderr.txt");
  const Json s = read_json(dir / "out" / "summary.json");
  ASSERT_TRUE(s.contains("dic"));
  EXPECT_EQ(s["dic"]["frames_read"], 41);
  EXPECT_EQ(s["dic"]["frames_used"], 41);
  EXPECT_EQ(s["dic"]["layout"], "vic");
  EXPECT_GT(s["dic"]["points_failed"].get<double>(), 0);
  EXPECT_TRUE(s["dic"].contains("wall_time_s"));
  // The record reduce read is dic's: one row per frame inside the machine's 0-40.5 s.
  const CsvTable rec = CsvTable::read((dir / "out" / "dic_record.csv").string());
  EXPECT_EQ(rec.n_rows(), 41u);
  const auto a = rec.numeric("a_mm");
  EXPECT_DOUBLE_EQ(a.front(), 50); // not open to 1 % at the root yet: a = a0
  // The crack ran 16 mm in the model; the rule lags the model's tip by a few mm
  // (docs/dic_tip_rule.md: 3.5 mm for this opening shape, 1 %, a 5-point window).
  EXPECT_NEAR(a.back(), 50 + 16 - 3.5, 1.0);
  ASSERT_TRUE(s.contains("reduce"));
  // R by direct energy from the DIC crack lengths: the lag is constant once the zone's shape is
  // steady, so the growth and R are the model's R = 300 J/m^2. The plateau mean over the last
  // third of the growth: 10 % for the rule's tip noise (sd ~0.05 mm per reading over 1 mm
  // windows) and the frames' 1 s sampling of the load.
  const double plateau = s["reduce"]["mean"]["energy"]["plateau_J_m2"].get<double>();
  EXPECT_NEAR(plateau, R, 0.1 * R);
  // The three plots a person looks at first.
  for (const char* png : {"dic_strain_profiles.png", "dic_crack_and_root.png", "dic_field.png"})
    EXPECT_TRUE(fs::exists(dir / "out" / png) || !std::system("command -v gnuplot >/dev/null"))
        << png;
}

TEST(AppDic, CommandLineWritesTheRecord) {
  const fs::path dir = work("dic_cli");
  fs::remove_all(dir);
  write_test(dir);
  const auto r = run("dic_cli_run",
                     "dic " + (dir / "frames").string() + "/dcb_00*_0.csv --record " +
                         (dir / "machine.csv").string() +
                         " --columns 'time_s: Time (s), opening_mm: Extension (mm), load_N: Load "
                         "(N)' --coordinates px --pixel-size 0.05 --y-axis down --crack-plane-y "
                         "512 --notch-root-x 300 --initial-crack 50 --out out");
  ASSERT_EQ(r.exit_code, 0) << r.err;
  const CsvTable rec = CsvTable::read((work("dic_cli_run") / "out" / "dic_record.csv").string());
  EXPECT_EQ(rec.n_rows(), 41u);
  EXPECT_TRUE(rec.has_column("delta_root_sd_mm"));
}

TEST(AppDic, BadInputFailsCleanly) {
  const fs::path dir = work("dic_bad");
  fs::remove_all(dir);
  write_test(dir);
  std::string bad = scene;
  bad.replace(bad.find("Crack plane y = 512"), 19, "Crack plane y = 5000");
  std::ofstream(dir / "scene.prm") << bad;
  std::string cmd = "cd '" + dir.string() + "' && '" + FIBERBRIDGE_BIN +
                    "' run scene.prm > stdout.txt 2> stderr.txt";
  EXPECT_NE(std::system(cmd.c_str()), 0);
  std::ifstream in(dir / "stderr.txt");
  std::stringstream err;
  err << in.rdbuf();
  EXPECT_NE(err.str().find("no point within 1.5 point spacings"), std::string::npos) << err.str();
  EXPECT_FALSE(fs::exists(dir / "out" / "summary.json"));
  // A frame without the strain column: file and line named.
  std::ofstream(dir / "frames" / "dcb_0041_0.csv")
      << "\"x\", \"y\", \"u\", \"v\", \"sigma\"\n1, 2, 3, 4, 0\n";
  std::ofstream(dir / "scene.prm") << scene;
  EXPECT_NE(std::system(cmd.c_str()), 0);
  std::ifstream in2(dir / "stderr.txt");
  std::stringstream err2;
  err2 << in2.rdbuf();
  EXPECT_NE(err2.str().find("dcb_0041_0.csv:1: missing column 'eyy'"), std::string::npos)
      << err2.str();
}

// DIC sets in a campaign's manifest (issue 33 item 1): three specimens, each a folder with its
// frames and machine record (the generator above, other noise seeds, R rising from 300 to 500
// J/m^2 over the first mm of growth), run through the DIC step with the DIC section's settings and
// reduced as raw records into one group with a law; a DIC set beside an R(delta) table in one
// group is refused naming both lines (one group, one kind of input).
TEST(AppDic, CampaignManifestTakesDicSets) {
  const fs::path dir = work("dic_campaign");
  fs::remove_all(dir);
  for (int k = 1; k <= 3; ++k)
    write_test(dir / ("set" + std::to_string(k)), 100u * k, 200);
  // J_tip and delta_c per row (the seed fixed delta_c per material): the DIC rule's tip lag
  // (docs/dic_tip_rule.md) and the direct-energy window put the first R(delta_root) readings on
  // the plateau already (R within 3 % of 490 J/m^2 from delta_root = 0.017 mm on), so no
  // initiation can be read off the curve, and the 41 frames' direct energy wobbles by 2 % at the
  // end, above the automatic steady-state band.
  std::ofstream(dir / "manifest.csv")
      << "file,material,cycles,specimen,j_tip_J_m2,delta_c_mm\n"
         "set1,X,0,s1,300,0.2\nset2,X,0,s2,300,0.2\nset3,X,0,s3,300,0.2\n";
  // The scene of the tests above (the DIC section's settings; Test/Files and Frames now inside
  // each set's folder) running the campaign instead of dic, reduce.
  std::string campaign = scene;
  campaign.replace(campaign.find("set Run = dic, reduce"), 21, "set Run = campaign");
  campaign += "subsection Campaign\n  set Manifest = manifest.csv\n  set Bootstrap samples = 50\n"
              "  set Reference materials =\nend\n"
              "subsection Fit\n  set Delta 1 = 0.02\n  set Delta 2 = 0.08\nend\n";
  std::ofstream(dir / "scene.prm") << campaign;
  const std::string cmd = "cd '" + dir.string() + "' && '" + FIBERBRIDGE_BIN +
                          "' run scene.prm > stdout.txt 2> stderr.txt";
  ASSERT_EQ(std::system(cmd.c_str()), 0) << "see " << (dir / "stderr.txt");
  const Json s = read_json(dir / "out" / "summary.json")["campaign"];
  ASSERT_EQ(s["groups"].size(), 1u);
  const auto& g = s["groups"][0];
  EXPECT_EQ(g["n_specimens"], 3);
  // The specimens' input kind is the DIC set, each with its record beside the tables.
  const CsvTable spec = CsvTable::read((dir / "out" / "campaign_specimens.csv").string());
  ASSERT_EQ(spec.n_rows(), 3u);
  for (int k = 1; k <= 3; ++k)
    EXPECT_TRUE(fs::exists(dir / "out" / ("campaign_dic_X_c0_s" + std::to_string(k) + ".csv")));
  // Each record is the one `dic, reduce` reads (same rows as SceneRunsDicThenReduceOnItsRecord:
  // one per frame inside the machine's 0-40.5 s, a from a0 = 50 mm).
  const CsvTable rec = CsvTable::read((dir / "out" / "campaign_dic_X_c0_s2.csv").string());
  EXPECT_EQ(rec.n_rows(), 41u);
  EXPECT_DOUBLE_EQ(rec.numeric("a_mm").front(), 50);
  // Initiation and plateau: the model's 300 and 500 J/m^2 (R's rise is complete to 0.05 % at the
  // last frame's delta_root = 0.31 mm), 10 % as in the scene test above (the rule's tip noise and
  // the frames' 1 s sampling of the load); the group has its law with intervals.
  ASSERT_TRUE(g["G_ss_J_m2"].is_number()) << g.dump();
  EXPECT_NEAR(g["G_ss_J_m2"].get<double>(), R + 200, 0.1 * (R + 200)) << g.dump();
  EXPECT_NEAR(g["J_tip_J_m2"].get<double>(), R, 0.1 * R) << g.dump();
  EXPECT_TRUE(g["trilinear"]["sigma1_kPa"].is_number()) << g.dump();
  EXPECT_EQ(g["ci"]["G_ss_J_m2"].size(), 2u);

  // One group, one kind of input: a DIC set beside an R(delta) table.
  std::ofstream(dir / "manifest.csv")
      << "file,material,cycles,specimen\nset1,X,0,s1\n"
      << source("data/campaign_synthetic/PVA_c0_s1.csv") << ",X,0,s2\n";
  fs::remove_all(dir / "out");
  EXPECT_NE(std::system(cmd.c_str()), 0);
  std::ifstream in(dir / "stderr.txt");
  std::stringstream err;
  err << in.rdbuf();
  EXPECT_NE(err.str().find("manifest.csv:3"), std::string::npos) << err.str();
  EXPECT_NE(err.str().find("manifest.csv:2"), std::string::npos) << err.str();
  EXPECT_NE(err.str().find("one kind of input"), std::string::npos) << err.str();

  // A DIC set needs DIC/Frames (inside each set's folder): said with the manifest line, no table.
  std::ofstream(dir / "manifest.csv") << "file,material,cycles,specimen\nset1,X,0,s1\n";
  std::string no_frames = campaign;
  no_frames.replace(no_frames.find("set Frames = frames/dcb_*_0.csv"), 31, "set Frames =");
  std::ofstream(dir / "scene.prm") << no_frames;
  fs::remove_all(dir / "out");
  EXPECT_NE(std::system(cmd.c_str()), 0);
  std::ifstream in2(dir / "stderr.txt");
  std::stringstream err2;
  err2 << in2.rdbuf();
  EXPECT_NE(err2.str().find("manifest.csv:2: DIC set 'set1': DIC/Frames must name the frames"),
            std::string::npos)
      << err2.str();
  EXPECT_FALSE(fs::exists(dir / "out" / "campaign_table1.csv"));
}

namespace {

void replace_once(std::string& text, const std::string& from, const std::string& to) {
  const auto at = text.find(from);
  ASSERT_NE(at, std::string::npos) << from;
  text.replace(at, from.size(), to);
}

/// The data rows of a dic_record.csv (the comment lines name the door, the rows must not differ).
std::vector<std::string> record_rows(const fs::path& p) {
  std::ifstream in(p);
  std::vector<std::string> rows;
  for (std::string line; std::getline(in, line);)
    if (!line.empty() && line[0] != '#')
      rows.push_back(line);
  return rows;
}

} // namespace

// One chain, one door (issue 39 item 3): the machine record is read as `reduce` reads a record.
// The header 'Time (s)' is matched by the map 'time_s: Time' (the old DIC reader wanted the header
// in full), and a German testXpert-style export of the same record (';', decimal commas, kN) gives
// the same test record. A DIC set in a campaign's manifest gives the record the scene's `dic`
// gives.
TEST(AppDic, MachineRecordAndDicSetReadAsReduceReads) {
  const fs::path dir = work("dic_one_door");
  fs::remove_all(dir);
  write_test(dir / "set1", 100, 200);
  write_test(dir / "set2", 200, 200);
  {
    // The plain record's numbers (as written, 6 digits), the load in kN.
    const CsvTable plain_machine = CsvTable::read((dir / "set1" / "machine.csv").string());
    const auto t = plain_machine.numeric("Time (s)"), x = plain_machine.numeric("Extension (mm)"),
               p = plain_machine.numeric("Load (N)");
    std::ofstream m(dir / "set1" / "maschine.csv");
    m << "Zeit (s);Standardweg (mm);Standardkraft (kN)\r\n";
    for (std::size_t i = 0; i < t.size(); ++i) {
      std::ostringstream row;
      row << std::setprecision(15) << t[i] << ";" << x[i] << ";" << p[i] / 1e3;
      std::string text = row.str();
      std::replace(text.begin(), text.end(), '.', ',');
      m << text << "\r\n";
    }
  }
  const auto run_in = [&](const std::string& scene_text, const std::string& out) {
    std::ofstream(dir / "scene.prm") << scene_text;
    const std::string cmd = "cd '" + dir.string() + "' && '" + FIBERBRIDGE_BIN +
                            "' run scene.prm --set 'Output directory=" + out +
                            "' > stdout.txt 2> stderr.txt";
    return std::system(cmd.c_str());
  };
  std::string plain = scene;
  replace_once(plain, "frames/dcb_*_0.csv", "set1/frames/dcb_*_0.csv");
  replace_once(plain, "set Files = machine.csv", "set Files = set1/machine.csv");
  replace_once(plain, "time_s: Time (s), opening_mm: Extension (mm), load_N: Load (N)",
               "time_s: Time, opening_mm: Extension, load_N: Load");
  ASSERT_EQ(run_in(plain, "plain"), 0) << "see " << (dir / "stderr.txt");
  std::string german = plain;
  replace_once(german, "set Files = set1/machine.csv", "set Files = set1/maschine.csv");
  replace_once(german, "time_s: Time, opening_mm: Extension, load_N: Load",
               "time_s: Zeit, opening_mm: Standardweg, load_N: Standardkraft");
  ASSERT_EQ(run_in(german, "german"), 0) << "see " << (dir / "stderr.txt");
  const auto a = record_rows(dir / "plain" / "dic_record.csv");
  const CsvTable ta = CsvTable::read((dir / "plain" / "dic_record.csv").string());
  const CsvTable tb = CsvTable::read((dir / "german" / "dic_record.csv").string());
  ASSERT_EQ(ta.n_rows(), 41u);
  ASSERT_EQ(tb.n_rows(), ta.n_rows());
  // The German file holds the same numbers (the load in kN to 15 digits): the record agrees to
  // its 10 printed digits (1e-9 of the value).
  for (const char* c : {"time_s", "opening_mm", "load_N", "a_mm", "delta_root_mm"}) {
    const auto x = ta.numeric(c), y = tb.numeric(c);
    for (std::size_t i = 0; i < x.size(); ++i)
      EXPECT_NEAR(y[i], x[i], 1e-9 * std::abs(x[i]) + 1e-12) << c << " row " << i;
  }
  // The campaign's DIC set: the same rows, to the digit.
  std::ofstream(dir / "manifest.csv") << "file,material,cycles,specimen,j_tip_J_m2,delta_c_mm\n"
                                         "set1,X,0,s1,300,0.2\nset2,X,0,s2,300,0.2\n";
  std::string campaign = scene;
  replace_once(campaign, "set Run = dic, reduce", "set Run = campaign");
  replace_once(campaign, "time_s: Time (s), opening_mm: Extension (mm), load_N: Load (N)",
               "time_s: Time, opening_mm: Extension, load_N: Load");
  campaign += "subsection Campaign\n  set Manifest = manifest.csv\n  set Bootstrap samples = 20\n"
              "  set Reference materials =\nend\n"
              "subsection Fit\n  set Delta 1 = 0.02\n  set Delta 2 = 0.08\nend\n";
  ASSERT_EQ(run_in(campaign, "campaign"), 0) << "see " << (dir / "stderr.txt");
  EXPECT_EQ(record_rows(dir / "campaign" / "campaign_dic_X_c0_s1.csv"), a);
}
