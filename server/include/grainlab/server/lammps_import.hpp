#pragma once
// `grainlab import lammps DUMPS... --out DIR --db FILE`: a LAMMPS run imported as without --db
// (into DIR) and kept in the server's database as a run like any other, its origin "lammps":
// the series, the rose diagrams' histograms, replay frames with force chains, the discs' shapes.
// Safe beside a server running on the same file (as `grainlab import DIR`).
#include <cstdint>
#include <string>
#include <vector>

#include "grainlab/lammps/import.hpp"

namespace grainlab::server {

struct LammpsRunImport {
  std::int64_t runId = 0;
  lammps::ImportReport report;
};

/// `name` is the run's name in the list (empty: "lammps/" and DIR's folder name). A replay frame
/// is kept every `options.framesEvery` frames and the last. Throws what lammps::importLammps
/// throws, and std::invalid_argument when the dumps carry no clock (no --timestep and no
/// export.json beside them): then neither DIR nor a run is left.
LammpsRunImport importLammpsRun(const std::vector<std::string>& dumps, const std::string& outDir,
                                const std::string& db, lammps::ImportOptions options, std::string name = {});

}  // namespace grainlab::server
