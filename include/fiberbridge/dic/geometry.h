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
  /// [rad] the crack plane's angle to the frames' x axis (y up, counter-clockwise for +x growth):
  /// a specimen not quite level in the image. The strain read stays the frames' eyy, which is
  /// the crack-normal strain to within tilt^2 and 2 tilt exy (exy ~ 0 on the plane of a
  /// symmetric DCB); set_from_points() refuses tilts over 10 degrees.
  double tilt = 0;

  /// The root and the plane from two marked points in the frames' coordinates: the notch root
  /// (x0, y0) and a point (x1, y1) on the crack plane ahead of it. InputError naming `where` for
  /// coincident points or a plane tilted more than 10 degrees from the frames' x axis.
  void set_from_points(double x0, double y0, double x1, double y1, const std::string& where);

  /// Metres per unit of the frames' coordinates and displacements.
  double scale() const;
  /// Frame coordinates (file units) of a point at (s, n) in crack coordinates [m].
  double frame_x(double s, double n = 0) const;
  double frame_y(double n, double s = 0) const;
  /// Unit vectors of s and n in the frames' coordinates with y up.
  void axes(double& sx, double& sy, double& nx, double& ny) const;
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
