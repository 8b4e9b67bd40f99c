#pragma once
// grainlab export lammps / grainlab import lammps (docs/lammps.md).
#include <string>
#include <vector>

namespace grainlab {

/// `export lammps (SCENE | --preset NAME) [--from DIR[:STAGE]] --out DIR [...]`; args after "lammps".
int exportLammpsCommand(const std::vector<std::string>& args);
/// `import lammps DUMPS... --out DIR [...]`; args after "lammps".
int importLammpsCommand(const std::vector<std::string>& args);

}  // namespace grainlab
