#pragma once
// Writes a run as a ParaView time series (scene "output": {"vtk": true, "vtk_every": K}):
//   DIR/vtk/particles_NNNN.vtp  the particles: points 0..N-1 are the centroids in id order, a
//                               vertex cell per disc, a polygon cell per polygon (its corners
//                               follow the centroids as extra points);
//   DIR/vtk/contacts_NNNN.vtp   one line per contact, from centroid i to centroid j (to the
//                               contact point for a wall);
//   DIR/vtk/cell_NNNN.vtp       a run in a periodic cell: the cell's outline, a closed line
//                               through 0, h1, h1 + h2, h2 (cell data h1, h2, area); a contact
//                               across an edge is drawn to the image of j that i touches;
//   DIR/vtk/run.pvd             the frames with their simulation times (cell.pvd: the outlines).
// VTK XML PolyData with raw appended binary data (little-endian, UInt64 block headers).
// A frame is written at every K-th sample and at the end. run.pvd is rewritten after the
// first frame, then at most every few seconds, and at the end: ParaView can open a run that
// is still going, and the collection costs no disk flush per frame (ext4 flushes a file
// renamed over an old one). It reads the world, never changes it.
#include <cstdint>
#include <string>
#include <vector>

#include "grainlab/contact.hpp"
#include "grainlab/run.hpp"

namespace grainlab {

class VtkWriter : public RunObserver {
 public:
  /// `directory` is the run's output directory; the files go to directory/vtk.
  /// `every` (≥ 1): a frame at every `every`-th sample.
  VtkWriter(std::string directory, int every);
  void onStart(const Scene&, const World&) override;
  void onSample(const Sample&, const World&) override;
  /// Checkpoints: the frames written so far.
  void persistOutput(StateArchive& a) override;
  /// Frames written after the checkpoint are removed (they are written again).
  void onResume(const Scene&, const World&) override;
  void onFinish(const RunSummary&, const World&) override;

  /// Writes one frame of the world as it is now (the run calls it; public for tests).
  void writeFrame(const World& world);

  int frames() const { return static_cast<int>(frames_.size()); }
  std::uint64_t bytesWritten() const { return bytes_; }
  /// s of wall time spent writing frames (to compare with the run's wall time).
  double writeSeconds() const { return seconds_; }

 private:
  void writeCollection() const;

  std::string dir_;
  int every_;
  std::int64_t samples_ = 0;
  std::int64_t lastFrameStep_ = -1;
  std::vector<std::pair<double, int>> frames_;  // (time, frame number)
  std::vector<ContactRecord> contacts_;
  std::uint64_t bytes_ = 0;
  double seconds_ = 0;
  double collectionWrittenAt_ = -1;  // steady clock (s) when run.pvd was last written
};

}  // namespace grainlab
