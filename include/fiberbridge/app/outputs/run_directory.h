#pragma once
// An output directory's life: created, marked incomplete while a run writes into it, and given
// its summary.json last, so that a killed run never leaves an old summary looking current.
#include "fiberbridge/core/summary.h"

#include <string>

namespace fiberbridge::app {

/// Name of the file that marks an output directory as holding no complete run.
inline constexpr const char* incomplete_marker = "RUN_INCOMPLETE.txt";
/// At the start of a run: writes the incomplete marker, then removes a stale summary.json (so a
/// failed or killed run never leaves an old one looking current) and leftover *.partial files.
void remove_stale_summary(const std::string& out_dir);
/// The end of a successful run: writes summary.json (atomically), then removes the incomplete
/// marker. Every command that writes a summary ends through here.
void write_run_summary(const std::string& out_dir, const Json& summary);
/// Creates the directory (and parents); InputError when impossible.
void ensure_directory(const std::string& dir);

} // namespace fiberbridge::app
