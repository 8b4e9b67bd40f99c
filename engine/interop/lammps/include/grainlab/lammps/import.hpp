#pragma once
// A LAMMPS granular run read back into grainlab's outputs (docs/lammps.md): the `dump custom`
// and `dump local` frames of each timestep, streamed one frame of each at a time, analysed with
// grainlab's own estimators (contact stress, fabric and anisotropies, θσ by Eq. 7, ω against the
// cell's strain-rate direction, coordination, void ratio) into DIR/series.csv,
// DIR/histograms.csv, DIR/frames/STEP.csv (particle frames for replay), DIR/particles_final.csv
// and DIR/contacts_final.csv (the last frame's, in grainlab's columns) and DIR/summary.json
// ("origin": "lammps").
#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "grainlab/lammps/frame_contacts.hpp"

namespace grainlab {
struct Sample;
}

namespace grainlab::lammps {

/// Sees each frame as the import analyses it, to keep it somewhere else too (the server's
/// database: `grainlab import lammps --db`). Called in timestep order while the import runs, so
/// before it is known to succeed: an observer that stores must undo its work if importLammps
/// throws.
class ImportObserver {
 public:
  virtual ~ImportObserver() = default;
  /// `row` is series.csv's row (its histograms, when the frame has contacts, in row.histograms);
  /// `frame` the frame's discs (ascending LAMMPS id) and contacts.
  virtual void onFrame(const Sample& row, const FrameContacts& frame) = 0;
};

struct ImportOptions {
  LocalColumns columns;
  /// s per LAMMPS step, for the time column; unset: export.json beside the first dump, if any
  /// (whose start_time_s, the clock of a specimen exported --from a prepared run, is added).
  std::optional<double> timestep;
  /// kg/m³, for the kinetic energy (discs of mass ρπr²); unset: export.json's, if any.
  std::optional<double> density;
  /// A particle frame every this many frames (0: none; the last frame is always particles_final.csv).
  int framesEvery = 1;
  int histogramBins = 18;
  ImportObserver* observer = nullptr;  ///< not owned; may be null
};

struct ImportReport {
  std::int64_t frames = 0;
  std::int64_t firstTimestep = -1, lastTimestep = -1;
  int particles = 0;            ///< in the last frame
  std::string warning;          ///< a truncated last frame: what was cut, the frames before kept
  double seconds = 0;           ///< wall time of the import
};

/// The dumps may be given in any order and split over several files each (concatenated in the
/// order given); each file holds one kind of frame. Writes into `outDir` only when the import
/// succeeds (through a temporary folder renamed at the end): malformed input throws DumpError
/// ("FILE:LINE: reason") and leaves nothing. A dump that ends inside its last frame is not an
/// error: the frames before it are imported and the report's warning says what was cut.
ImportReport importLammps(const std::vector<std::string>& dumps, const std::string& outDir,
                          const ImportOptions& options = {});

}  // namespace grainlab::lammps
