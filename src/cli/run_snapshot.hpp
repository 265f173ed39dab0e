// `perpdot run … --save-at K FILE` and `--load FILE`: a run file holds the World snapshot and
// how many steps of the scene were taken, so a loaded run continues with the right actions.
#pragma once

#include <optional>
#include <string>
#include <vector>

#include "cli/commands.hpp"
#include "perpdot/scene.hpp"

namespace perpdot::cli {

struct SaveAt {
    int step = 0;
    std::string path;
};

// Splits "--save-at K FILE" off the arguments (the shared Flags take one value per flag) and
// returns the rest; UsageError if K or FILE is missing or K is not an integer >= 0.
std::vector<std::string> takeSaveAt(Args args, std::optional<SaveAt>& saveAt);

void saveRun(const std::string& path, const SceneWorld& built);
// Restores the world and the step count; Error naming the file if it cannot be read or is corrupt.
void loadRun(const std::string& path, SceneWorld& built);

}  // namespace perpdot::cli
