#pragma once
// Which process writes the shared output files. Under `mpirun -np N fiberbridge run SCENE.prm`
// every rank runs the scene (each needs the fitted law, the parameters, ...), but the shared files
// (CSV, JSON, text reports, gnuplot PNGs, parameters_used.prm) must be written once: the
// program switches output off on ranks > 0 at start-up, and the core writers
// (write_file_atomically, and through it CsvWriter and write_json_atomically; run_gnuplot) do
// nothing while it is off. Files that are per rank by design (the VTU pieces of a distributed
// FEM run) do not go through these writers. Default: on (a serial program writes).
namespace fiberbridge {

void set_output_enabled(bool enabled);
bool output_enabled();

} // namespace fiberbridge
