// DcbModel's checkpoints (mpm/checkpoint.h): what is saved, in which order, and how a checkpoint
// is tied to the inputs of the run that wrote it.
#include "fiberbridge/mpm/checkpoint.h"

#include "fiberbridge/core/binary_archive.h"
#include "fiberbridge/core/csv.h"
#include "fiberbridge/core/error.h"
#include "fiberbridge/core/format.h"
#include "fiberbridge/core/output_guard.h"
#include "fiberbridge/law/law_fingerprint.h"
#include "fiberbridge/mpm/dcb.h"
#include "fiberbridge/result/numerical_fault.h"

#include <filesystem>
#include <map>

namespace fiberbridge::mpm {

namespace {

const char* magic = "fiberbridge MPM checkpoint";

std::string number(double v, const char* unit) {
  return law::exact_number(v, unit);
}

} // namespace

std::string checkpoint_path(const std::string& output_dir) {
  return output_dir + "/resume/mpm_state.bin";
}

std::vector<std::pair<std::string, std::string>> DcbModel::inputs() const {
  // Every input the result depends on, under the scene key that sets it (values in SI units).
  // Not here: MPM/Threads (results are the same for any count, work_team.h) and the run
  // control (checkpoint interval, resume).
  const MpmParameters& p = prm_;
  return {
      {"Specimen/Length", number(spec_.length, "m")},
      {"Specimen/Width", number(spec_.width, "m")},
      {"Specimen/Height", number(spec_.height, "m")},
      {"Specimen/Initial crack", number(spec_.initial_crack, "m")},
      {"Material/E_L", number(mat_.E_L, "Pa")},
      {"Material/E_T", number(mat_.E_T, "Pa")},
      {"Material/G_LT", number(mat_.G_LT, "Pa")},
      {"Material/nu_LT", number(mat_.nu_LT, "")},
      {"Material/Plane", mat_.plane_stress ? "stress" : "strain"},
      {"Material/Density", number(mat_.density, "kg/m^3")},
      {"Material/E_R over E_L", number(mat_.E_R_over_E_L, "")},
      {"Material/nu_LR", number(mat_.nu_LR, "")},
      {"Material/nu_RT", number(mat_.nu_RT, "")},
      {"Cohesive law", law::law_fingerprint(user_law_)},
      {"Cohesive law/J tip", number(j_tip_, "J/m^2")},
      {"MPM/Cell size", number(p.cell_size, "m")},
      {"MPM/Particles per cell", std::to_string(p.particles_per_cell)},
      {"MPM/CFL factor", number(p.cfl, "")},
      {"MPM/PIC fraction", number(p.pic_fraction, "")},
      {"MPM/Loading periods", number(p.loading_periods, "")},
      {"MPM/Ramp periods", number(p.ramp_periods, "")},
      {"MPM/Growth step", std::to_string(p.growth_step_cells)},
      {"MPM/J window periods", number(p.j_window_periods, "")},
      {"MPM/Tip J domain", number(p.tip_j_cells, "")},
      {"MPM/End ligament", number(p.end_ligament, "m")},
      {"MPM/Steady growth", number(p.steady_growth, "m")},
      {"MPM/Steady state window", number(p.steady_state_window, "m")},
      {"MPM/Plateau tolerance", number(p.plateau_tolerance, "")},
      {"MPM/Maximum steps", std::to_string(p.max_steps)},
      {"MPM/VTU every advances", std::to_string(p.vtu_every_advances)},
  };
}

double DcbModel::session_seconds() const {
  return running_ ? std::chrono::duration<double>(std::chrono::steady_clock::now() - session_start_)
                        .count()
                  : 0.0;
}

void DcbModel::write_checkpoint() const {
  // A run without an output directory keeps nothing; an MPI rank that does not write keeps
  // nothing either (core/output_guard.h).
  if (out_dir_.empty() || !output_enabled())
    return;
  BinaryWriter w(magic, checkpoint_version);
  w.put(inputs());
  w.put(opening_);
  w.put(load_);
  w.put(rcurve_);
  w.put(max_kinetic_ratio_);
  w.put(earlier_wall_seconds_ + session_seconds());
  solver_->save_state(w);
  crack_->save_state(w);
  growth_->save_state(w);
  w.put(vtu_ ? vtu_->written() : std::vector<std::pair<double, std::string>>{});
  const std::string path = checkpoint_path(out_dir_);
  std::error_code ec;
  std::filesystem::create_directories(std::filesystem::path(path).parent_path(), ec);
  if (ec)
    throw InputError(path + ": cannot create the checkpoint's directory (" + ec.message() + ")");
  write_file_atomically(path, w.finish());
}

bool DcbModel::resume_from_checkpoint() {
  const std::string path = checkpoint_path(out_dir_);
  if (out_dir_.empty() || !std::filesystem::exists(path))
    return false;
  BinaryReader in(read_file_bytes(path), magic, checkpoint_version, path);
  std::vector<std::pair<std::string, std::string>> saved_list;
  in.get(saved_list);
  const std::map<std::string, std::string> saved(saved_list.begin(), saved_list.end());
  const std::string afresh = "; run without --resume to start afresh (the checkpoint is then "
                             "replaced)";
  for (const auto& [key, value] : inputs()) {
    const auto it = saved.find(key);
    if (it == saved.end())
      throw InputError(path + ": written without the input " + key + afresh);
    if (it->second != value)
      throw InputError(path + ": written for other inputs: " + key + " was " + it->second +
                       ", the scene now gives " + value + afresh);
  }
  if (saved.size() != inputs().size())
    throw InputError(path + ": names inputs this version does not know" + afresh);
  in.get(opening_);
  in.get(load_);
  in.get(rcurve_);
  in.get(max_kinetic_ratio_);
  in.get(earlier_wall_seconds_);
  solver_->load_state(in);
  crack_->load_state(in);
  growth_->load_state(in);
  std::vector<std::pair<double, std::string>> written;
  in.get(written);
  in.expect_end();
  if (vtu_)
    vtu_->set_written(std::move(written));
  // The diagnosis context counts the restored advances as accepted (numerical_fault.h).
  for (const auto& p : rcurve_)
    result::check_rcurve_point(p);
  resumed_ = true;
  const ExplicitSolver& s = *solver_;
  const std::string what = "resumed from the checkpoint " + path + " at step " +
                           std::to_string(s.steps()) + " (t = " + fmt(s.time() * 1e3) + " ms, " +
                           std::to_string(rcurve_.size()) + " tip advances)";
  notes_.push_back(what);
  if (progress_)
    progress_("mpm: " + what);
  return true;
}

} // namespace fiberbridge::mpm
