// The built-in scene `mover_course`: what a character mover meets in a platform game, laid out
// left to right, for the viewer's player mover (A/D walk, W jumps) and the mover's scene tests.
#pragma once

#include "perpdot/feature_scenes.hpp"
#include "perpdot/scene.hpp"

namespace perpdot {

Scene moverCourse();
// The player mover's start and definition, and the moving platform's turn-back script.
SceneBehaviour moverCourseBehaviour();

}  // namespace perpdot
