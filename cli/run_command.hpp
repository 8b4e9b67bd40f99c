#pragma once
// `grainlab run` and `grainlab resume`: one scene headless, into a directory, with a
// checkpoint kept there so that a run stopped by a signal or a crash can be continued.
#include <string>
#include <vector>

namespace grainlab {

int runCommand(const std::vector<std::string>& args);
int resumeCommand(const std::vector<std::string>& args);

}  // namespace grainlab
