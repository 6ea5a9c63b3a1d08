#pragma once
// Which files are the frames, in which order, and when each image was taken on the testing
// machine's clock.
#include <cmath>
#include <string>
#include <vector>

namespace fiberbridge::dic {

/// The frames named by `list`: comma-separated paths or glob patterns (a pattern that matches
/// nothing, or a path that does not exist, is an InputError naming `where`). Relative entries are
/// tried as given, then against `base_dir` (the scene's folder).
std::vector<std::string> expand_frame_list(const std::string& list, const std::string& base_dir,
                                           const std::string& where);

struct FrameFile {
  std::string path;
  long number = -1; ///< the image number in the file's name; -1 when names carry none
};

/// The files ordered by the number in their names: the run of digits that differs between the
/// files (VIC-3D's dcb_0012_0.csv: 12, the last _0 is the camera; DICe_solution_12.txt: 12).
/// Names without such a number keep the order given. Two files with the same number are an
/// InputError naming both.
std::vector<FrameFile> order_frames(const std::vector<std::string>& paths,
                                    const std::string& where);

enum class FrameTimeSource { automatic, column, name, index };
FrameTimeSource parse_frame_time_source(const std::string& text, const std::string& where);
const char* frame_time_source_name(FrameTimeSource source);

struct FrameClock {
  FrameTimeSource source = FrameTimeSource::automatic;
  double frame_rate = 1;       ///< [Hz]
  double first_frame_time = 0; ///< [s] the first frame's time on the machine's clock
};

/// Each frame's time on the machine's clock: the first frame at first_frame_time; then by the
/// frames' time column (its differences), the image numbers in the names over the frame rate
/// (missing images leave gaps), or the order over the frame rate. automatic: column when every
/// frame has one, else names when they carry numbers, else the order. `column_times` holds the
/// frames' time column values (NaN when absent). Frames out of time order are an InputError naming
/// both files. Returns the source actually used through `used`.
std::vector<double> frame_times(const std::vector<FrameFile>& files,
                                const std::vector<double>& column_times, const FrameClock& clock,
                                FrameTimeSource& used);

} // namespace fiberbridge::dic
