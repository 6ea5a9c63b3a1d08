#pragma once
// Where the DCB model keeps its checkpoint (DcbModel::write_checkpoint and
// resume_from_checkpoint; docs/design.md section 5, "Checkpoints and --resume"). The file is the
// model's whole state that carries from one step to the next, bit for bit, so that a run resumed
// from it gives the uninterrupted run's results to the last bit: particles, time and step
// counters, the energy ledger, crack particles and segments with their damage history, the
// growth criterion's J window, the load-line opening and the load's moving average, the R curve
// so far and the VTU files written. The grid is rebuilt by every step, and the thread team's
// chunks do not depend on the number of threads (work_team.h), so neither is saved. The inputs
// the result depends on (DcbModel::inputs) are stored with it: a checkpoint written for other
// inputs is refused, naming the first input that differs.
#include <string>

namespace fiberbridge::mpm {

/// Format version of the file: raised whenever its layout or the meaning of a saved value
/// changes.
inline constexpr unsigned checkpoint_version = 2; // 2: the probe keeps step times

/// The checkpoint of a run into `output_dir`: <output_dir>/resume/mpm_state.bin.
std::string checkpoint_path(const std::string& output_dir);

} // namespace fiberbridge::mpm
