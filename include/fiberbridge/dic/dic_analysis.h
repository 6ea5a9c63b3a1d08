#pragma once
// DIC frames to crack length and notch-root opening, frame by frame (the paper's measuring step,
// seed section 2.2): read every frame (in parallel), put it in crack coordinates, check it against
// the first frame, find the tip by the threshold rule and read the extensometer; then track the
// tip in image order, the crack never healing. Every frame that cannot give a reading says why in
// its notes and is left out; nothing is silently skipped or carried over.
#include "fiberbridge/dic/crack_tip.h"
#include "fiberbridge/dic/dic_record.h"
#include "fiberbridge/dic/extensometer.h"
#include "fiberbridge/dic/frame.h"
#include "fiberbridge/dic/frame_set.h"
#include "fiberbridge/dic/geometry.h"

#include <map>
#include <string>
#include <vector>

namespace fiberbridge::dic {

struct DicOptions {
  FrameReadOptions read;
  FrameGeometry geometry;
  TipRule tip;
  FrameClock clock;
  double gauge_length = 2e-3; ///< [m] extensometer, centred on the crack plane
  int points_per_fit = 9;     ///< extensometer: nearest valid points per material point
  unsigned threads = 0;       ///< frames read and analysed in parallel; 0: the hardware's
};

struct FrameResult {
  FrameFile file;
  double time = NAN; ///< [s] on the machine's clock
  std::size_t n_points = 0, n_failed = 0;
  TipReading tip; ///< this frame's own reading
  ExtensometerReading extensometer;
  double s_tip = NAN, s_tip_sd = NAN; ///< [m] the tracked tip (never behind an earlier one)
  bool used = false;                  ///< tip and extensometer both read
  std::vector<std::string> notes;
  PlaneProfile profile;
};

struct DicAnalysis {
  std::vector<FrameResult> frames;
  double spacing = NAN; ///< [m] point spacing of the first frame
  Layout layout = Layout::plain;
  std::map<std::string, std::string> columns_used;
  double strain_factor = 1;
  FrameTimeSource time_source = FrameTimeSource::automatic;
  std::size_t points_used = 0, points_failed = 0;
  std::size_t frames_used = 0;
  double wall_time_s = 0;
};

/// Throws InputError for a frame that cannot be read (naming file:line) and for frames out of
/// time order; a frame that reads but gives no reading is a note (FrameResult::notes).
DicAnalysis analyse_frames(const std::vector<FrameFile>& files, const DicOptions& options);

/// One row per used frame inside the machine record's time span: a = a0 + the tracked tip's
/// shift, delta_root, and the machine's opening and load interpolated at the frame's time.
/// `notes` receives what was left out.
std::vector<DicRecordRow> match_to_machine(const DicAnalysis& analysis,
                                           const MachineRecord& machine, double initial_crack,
                                           std::vector<std::string>& notes);

} // namespace fiberbridge::dic
