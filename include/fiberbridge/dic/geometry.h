#pragma once
// The frame in the specimen's crack coordinates: s along the growth direction from the initial
// notch root, n normal to the crack plane (towards the upper arm), both in metres, with the
// displacements in the same directions. This is where pixels become metres (Pixel size), a y axis
// pointing down (image coordinates: VIC, DICe) is turned up, and a crack growing towards -x is
// mirrored; a normal strain is unchanged by those reflections.
#include "fiberbridge/dic/frame.h"

#include <cstddef>
#include <string>
#include <vector>

namespace fiberbridge::dic {

struct FrameGeometry {
  bool pixels = false;      ///< coordinates and displacements in pixels
  double pixel_size = NAN;  ///< [m] per pixel when pixels
  bool y_down = false;      ///< the frames' y axis points down (image coordinates)
  double crack_plane_y = 0; ///< in the frames' coordinates (mm or px)
  double notch_root_x = 0;  ///< in the frames' coordinates (mm or px)
  int growth_sign = +1;     ///< +1: the crack grows towards +x; -1: towards -x

  /// Metres per unit of the frames' coordinates and displacements.
  double scale() const;
  /// Frame coordinates (file units) of a point at (s, n) in crack coordinates [m].
  double frame_x(double s) const;
  double frame_y(double n) const;
};

struct PlaneFrame {
  std::string source;
  double time = NAN;                     ///< the frame's time column [s], if any
  std::vector<double> s, n, us, vn, eyy; ///< [m], [m], [m], [m], fraction
  std::vector<unsigned char> valid;      ///< 0: failed (or not placeable: no coordinates)
  std::size_t n_failed = 0;
};

PlaneFrame to_crack_coordinates(const RawFrame& raw, const FrameGeometry& geometry);

/// The median distance from a point to its nearest neighbour [m] (points with coordinates, failed
/// or not: the grid's step, not where correlation worked). Uses at most 400 sample points.
/// ComputationError for fewer than 2 points or coincident points only.
double point_spacing(const PlaneFrame& frame);

} // namespace fiberbridge::dic
