#pragma once
// The command line of `fiberbridge` (docs/design.md section 5, "Command line"): run, extract,
// rank, forward, synth, reduce, parameters, help.
#include <string>
#include <vector>

namespace fiberbridge::app {

/// Runs one command line (the arguments after the program name) on this MPI rank. Returns 0 on
/// success, 1 on an error (one line on stderr; input and option errors are found identically on
/// every rank and printed by rank 0 alone, others carry the rank), 2 for an unknown command and
/// 1 for no command at all (usage printed).
int run_command_line(std::vector<std::string> args, unsigned rank);

} // namespace fiberbridge::app
