#pragma once
// The paper's Figs. 6-15 and the rose diagrams, rebuilt from the runs: for each figure the
// CSV behind it (long format: one row per assembly and sample) and its charts as SVG.
#include <span>
#include <string>
#include <vector>

#include "grainlab/studies/paper/assembly_result.hpp"
#include "grainlab/studies/paper/csv_table.hpp"

namespace grainlab::report {

/// One chart of a figure, rendered twice: for inline use in HTML and as a standalone .svg file.
struct FigurePanel {
  std::string name;        ///< file stem, e.g. "fig07b"
  std::string inlineSvg;
  std::string fileSvg;
};

struct Figure {
  std::string id;          ///< "fig06" ... "fig15", "roses"; the CSV is <id>.csv
  std::string title;       ///< e.g. "Fig. 7. Circular particles: anisotropy ..."
  std::string caption;     ///< what is shown and how it was measured
  CsvTable data{{}};
  std::vector<FigurePanel> panels;
};

/// Figs. 6-15 then the rose diagrams, from whichever assemblies completed (a figure whose
/// assemblies are all missing still comes, with a header-only CSV and empty charts).
std::vector<Figure> paperFigures(std::span<const AssemblyResult> runs);

}  // namespace grainlab::report
