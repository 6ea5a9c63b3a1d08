// The DIC section (dic_step.h): declarations beside the parse that reads them back.
#include "fiberbridge/app/scene/dic_section.h"
#include "fiberbridge/core/error.h"
#include "fiberbridge/core/units.h"
#include "fiberbridge/dic/layouts.h"

#include <sstream>

namespace fiberbridge::app {

using units::mm;

void DicSection::declare_parameters(dealii::ParameterHandler& prm) {
  prm.declare_entry("Frames", "", dealii::Patterns::Anything(),
                    "DIC frames, one file per image: a glob or a comma-separated list, relative "
                    "to the scene; ordered by the image number in the names.");
  prm.declare_entry("Format", "auto", dealii::Patterns::Selection("auto|" + dic::layout_names("|")),
                    "Frame layout: " + dic::layout_descriptions() + "; auto detects it.");
  prm.declare_entry("Columns", "", dealii::Patterns::Anything(),
                    "Optional map of our frame columns (x, y, u, v, eyy, valid, time_s) to the "
                    "files' headers, as Test/Columns, e.g. 'eyy: e_yy, valid: sigma'.");
  prm.declare_entry("Coordinates", "mm", dealii::Patterns::Selection("mm|px"),
                    "Units of the frames' coordinates and displacements; px needs Pixel size.");
  prm.declare_entry("Pixel size", "0", dealii::Patterns::Double(0),
                    "mm per pixel when Coordinates = px.");
  prm.declare_entry("Y axis", "up", dealii::Patterns::Selection("up|down"),
                    "Direction of the frames' y axis (image coordinates point down).");
  prm.declare_entry("Crack plane y", "0", dealii::Patterns::Double(),
                    "y of the crack plane in the frames' coordinates (mm or px).");
  prm.declare_entry("Notch root x", "0", dealii::Patterns::Double(),
                    "x of the initial notch root in the frames' coordinates (mm or px).");
  prm.declare_entry("Growth direction", "+x", dealii::Patterns::Selection("+x|-x"),
                    "Direction in which the crack grows in the frames.");
  prm.declare_entry("Crack plane points", "", dealii::Patterns::Anything(),
                    "Optional 'x0, y0, x1, y1' in the frames' coordinates: the notch root and a "
                    "point on the crack plane ahead of it (a specimen not level in the image, up "
                    "to 10 degrees); replaces Notch root x, Crack plane y and Growth direction.");
  prm.declare_entry("Frame rate", "1", dealii::Patterns::Double(0), "Images per second (Hz).");
  prm.declare_entry("First frame time", "0", dealii::Patterns::Double(),
                    "Time of the first frame on the machine record's clock (s).");
  prm.declare_entry("Frame time source", "auto",
                    dealii::Patterns::Selection("auto|column|name|index"),
                    "How frames get their times: column (the frames' time_s column), name (the "
                    "image number in the names over the frame rate), index (the order over the "
                    "frame rate); auto: column, else name, else index.");
  prm.declare_entry("Strain threshold", "0.01", dealii::Patterns::Double(0),
                    "Crack-normal strain on the crack plane at the tip (the paper's 1 %).");
  prm.declare_entry("Extensometer gauge length", "2", dealii::Patterns::Double(0),
                    "Distance between the virtual extensometer's points, centred on the crack "
                    "plane at the initial notch root (mm).");
  prm.declare_entry("Extensometer points", "9", dealii::Patterns::Integer(4, 100),
                    "Nearest valid points in each extensometer point's least-squares fit.");
}

void DicSection::parse_parameters(dealii::ParameterHandler& prm) {
  frames = prm.get("Frames");
  format = prm.get("Format");
  columns = prm.get("Columns");
  pixels = prm.get("Coordinates") == "px";
  pixel_size = prm.get_double("Pixel size") * mm;
  y_down = prm.get("Y axis") == "down";
  crack_plane_y = prm.get_double("Crack plane y");
  notch_root_x = prm.get_double("Notch root x");
  growth_sign = prm.get("Growth direction") == "-x" ? -1 : +1;
  crack_plane_points = prm.get("Crack plane points");
  frame_rate = prm.get_double("Frame rate");
  first_frame_time = prm.get_double("First frame time");
  frame_time_source = prm.get("Frame time source");
  threshold = prm.get_double("Strain threshold");
  gauge_length = prm.get_double("Extensometer gauge length") * mm;
  points_per_fit = prm.get_integer("Extensometer points");
  if (pixels && !(pixel_size > 0))
    throw InputError("DIC/Pixel size: Coordinates = px needs a positive pixel size (mm)");
  if (!(frame_rate > 0))
    throw InputError("DIC/Frame rate must be positive");
  if (!(threshold > 0))
    throw InputError("DIC/Strain threshold must be positive");
  if (!(gauge_length > 0))
    throw InputError("DIC/Extensometer gauge length must be positive");
}

dic::DicOptions DicSection::options() const {
  dic::DicOptions o;
  o.read.layout = dic::parse_layout(format, "DIC/Format");
  o.read.columns = dic::FrameColumnMap::parse(columns, "DIC/Columns");
  o.read.pixel_coordinates = pixels;
  o.geometry.pixels = pixels;
  o.geometry.pixel_size = pixel_size;
  o.geometry.y_down = y_down;
  o.geometry.crack_plane_y = crack_plane_y;
  o.geometry.notch_root_x = notch_root_x;
  o.geometry.growth_sign = growth_sign;
  if (crack_plane_points.find_first_not_of(" \t") != std::string::npos) {
    double p[4];
    std::istringstream in(crack_plane_points);
    char comma;
    if (!(in >> p[0] >> comma >> p[1] >> comma >> p[2] >> comma >> p[3]) || !(in >> std::ws).eof())
      throw InputError("DIC/Crack plane points: expected 'x0, y0, x1, y1', got '" +
                       crack_plane_points + "'");
    o.geometry.set_from_points(p[0], p[1], p[2], p[3], "DIC/Crack plane points");
  }
  o.tip.threshold = threshold;
  o.clock.frame_rate = frame_rate;
  o.clock.first_frame_time = first_frame_time;
  o.clock.source = dic::parse_frame_time_source(frame_time_source, "DIC/Frame time source");
  o.gauge_length = gauge_length;
  o.points_per_fit = points_per_fit;
  return o;
}

} // namespace fiberbridge::app
