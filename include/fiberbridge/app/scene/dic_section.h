#pragma once
// The scene's DIC section: the frames' layout, the crack plane, the tip rule and the virtual
// extensometer, declared beside the parse that reads them back (scene/dic_section.cc).
#include "fiberbridge/dic/dic_analysis.h"

#include <deal.II/base/parameter_handler.h>

#include <string>

namespace fiberbridge::app {

/// The scene's DIC section (section.h convention). Lengths in the frames' coordinates stay in
/// their units (mm or px); the rest SI after parsing.
struct DicSection {
  std::string frames;  ///< glob(s) or list, as written
  std::string format;  ///< auto | vic | dice | gom | plain
  std::string columns; ///< our frame column names mapped to the files' headers
  bool pixels = false;
  double pixel_size = 0; ///< [m] per pixel
  bool y_down = false;
  double crack_plane_y = 0, notch_root_x = 0; ///< frames' coordinates
  int growth_sign = +1;
  std::string crack_plane_points; ///< "x0, y0, x1, y1" (overrides the three above) or empty
  double frame_rate = 1, first_frame_time = 0; ///< [Hz], [s]
  std::string frame_time_source;               ///< auto | column | name | index
  double threshold = 0.01;
  double gauge_length = 2e-3; ///< [m]
  int points_per_fit = 9;

  static void declare_parameters(dealii::ParameterHandler& prm);
  void parse_parameters(dealii::ParameterHandler& prm);
  /// The analysis options (frame layout, geometry, rule, clock); InputError naming DIC/<key>.
  dic::DicOptions options() const;
};

} // namespace fiberbridge::app
