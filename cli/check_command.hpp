#pragma once
// `grainlab check SCENE.json | --preset NAME`: is the scene valid, and what will it cost?
// Parses it (an error names the field and the reason, exit 2), builds its world as a run
// would (the specimen generated, its first forces computed) and prints the particle count
// and the estimated steps and wall time. Nothing is written.
#include <string>
#include <vector>

namespace grainlab {

int checkCommand(const std::vector<std::string>& args);

}  // namespace grainlab
