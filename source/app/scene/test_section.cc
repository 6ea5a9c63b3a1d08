// The Test section (test_section.h): declarations beside the parse that reads them back.
#include "fiberbridge/app/scene/test_section.h"

#include "fiberbridge/app/scene/scene_reader.h"
#include "fiberbridge/core/error.h"
#include "fiberbridge/core/format.h"
#include "fiberbridge/core/units.h"

#include <filesystem>
#include <sstream>

namespace fiberbridge::app {

using units::mm;

void TestSection::declare_parameters(dealii::ParameterHandler& prm) {
  prm.declare_entry("Files", "", dealii::Patterns::Anything(),
                    "Comma-separated raw DCB records (replicates), relative to the scene.");
  prm.declare_entry("Columns", "", dealii::Patterns::Anything(),
                    "Our column names mapped to the files' headers, e.g. 'time_s: Time (s), "
                    "opening_mm: Extension (mm), load_N: Load (N), a_mm: Crack length (mm)'; "
                    "optional a_mm, delta_root_mm, record. A header may be named with or "
                    "without its unit ('opening_mm: Extension' matches 'Extension (mm)'); the "
                    "file's unit converts it. Empty: the files use our names. The files' layout "
                    "(delimiter, decimal comma, preamble, units row) is detected.");
  prm.declare_entry("Encoding", "auto", dealii::Patterns::Anything(),
                    "Text encoding of the files: auto (UTF-8, UTF-16 with or without a "
                    "byte-order mark, or the most plausible of windows-1252, windows-1250, "
                    "Shift-JIS, GB18030 and EUC-KR, detected from the content; docs/design.md "
                    "section 6) or an iconv name such as CP1250, CP932, GBK, EUC-KR, UTF-16LE.");
  prm.declare_entry("Crack length", "auto", dealii::Patterns::Selection("auto|measured|equivalent"),
                    "Where crack lengths come from: auto (the a_mm column when the file has one), "
                    "measured (a_mm required) or equivalent (R against the equivalent crack "
                    "length from the compliance; readings, when the file has them, give a0 and "
                    "are shown beside), as --crack-length.");
  prm.declare_entry("Use specimen initial crack", "false", dealii::Patterns::Bool(),
                    "a0 = Specimen/Initial crack; false: each record's first crack reading.");
  prm.declare_entry("Smoothing window", "0", dealii::Patterns::Double(0),
                    "Window in crack length of the direct-energy slope fits in mm; 0: chosen "
                    "from the data at each reading (docs/design.md section 6, reduce).");
  prm.declare_entry("Large displacement correction", "true", dealii::Patterns::Bool(),
                    "ASTM D5528 / ISO 15024 F and N on MBT, CC, MCC.");
  prm.declare_entry("Pin to arm mid-plane", "0", dealii::Patterns::Double(0),
                    "l1 of D5528/ISO 15024 in mm; 0: half the arm thickness (hinges).");
  prm.declare_entry("Pin to block edge", "0", dealii::Patterns::Double(0),
                    "l2 of D5528/ISO 15024 in mm (end blocks); 0: no blocks (l2 = 0 in N).");
  prm.declare_entry("Crack back tolerance", "1", dealii::Patterns::Double(0),
                    "Crack readings may fall this far (mm) below the longest earlier reading "
                    "(tracking noise) and are held at it; further is an error.");
  prm.declare_entry("Plateau fraction", "0.333333", dealii::Patterns::Double(0.01, 1),
                    "The plateau is the mean over this last fraction of the crack extension.");
}

void TestSection::parse_parameters(dealii::ParameterHandler& prm) {
  files = split_list(prm.get("Files"), ',');
  columns = prm.get("Columns");
  crack_length = prm.get("Crack length");
  encoding = prm.get("Encoding");
  crack_back_tolerance = prm.get_double("Crack back tolerance") * mm;
  use_specimen_initial_crack = prm.get_bool("Use specimen initial crack");
  smoothing_window = prm.get_double("Smoothing window") * mm;
  large_displacement_correction = prm.get_bool("Large displacement correction");
  plateau_fraction = prm.get_double("Plateau fraction");
  pin_to_arm_midplane = prm.get_double("Pin to arm mid-plane") * mm;
  pin_to_block_edge = prm.get_double("Pin to block edge") * mm;
}

std::vector<std::string> TestSection::resolved_files(const std::string& scene_file) const {
  std::vector<std::string> paths;
  for (const auto& f : files) {
    const std::string path = resolve_scene_path(f, scene_file);
    if (!std::filesystem::exists(path))
      throw InputError(scene_file + ": Test/Files: record '" + f + "' not found");
    paths.push_back(path);
  }
  return paths;
}

analysis::RecordReadOptions TestSection::read_options(const std::string& scene_file) const {
  return chain_options(scene_file, specimen::Specimen::unknown(), specimen::Material{}).read;
}

analysis::RecordChainOptions TestSection::chain_options(const std::string& scene_file,
                                                        const specimen::Specimen& s,
                                                        const specimen::Material& m) const {
  analysis::RecordChainOptions o;
  o.read.columns = analysis::RecordColumnMap::parse(columns, scene_file + ": Test/Columns");
  o.read.crack_back_tolerance = crack_back_tolerance;
  o.read.encoding = encoding == "auto" ? "" : encoding;
  analysis::set_crack_length(o, crack_length, scene_file + ": Test/Crack length");
  o.specimen.width = s.width;
  o.specimen.height = s.height;
  o.specimen.length = s.length;
  if (use_specimen_initial_crack)
    o.specimen.initial_crack = s.initial_crack;
  o.specimen.pin_to_arm_midplane = pin_to_arm_midplane > 0 ? pin_to_arm_midplane : NAN;
  o.specimen.pin_to_block_edge = pin_to_block_edge > 0 ? pin_to_block_edge : NAN;
  o.reduce.large_displacement_correction = large_displacement_correction;
  o.reduce.plateau_fraction = plateau_fraction;
  o.reduce.smoothing_window = smoothing_window > 0 ? smoothing_window : NAN;
  // CBBM (equivalent crack, docs/design.md section 6): the arms' G13 and E22. Without crack
  // readings a0 comes from the Specimen.
  o.reduce.shear_modulus = m.G_LT;
  o.reduce.transverse_modulus = m.E_T;
  o.reduce.initial_crack_without_readings = s.initial_crack;
  return o;
}

} // namespace fiberbridge::app
