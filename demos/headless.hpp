// Headless mode: step a scene with no display and write PNG frames plus a contact sheet.
#pragma once

#include "options.hpp"

namespace perpdot::demo {

// Frame f shows the world after f·every steps (frame 0 is the initial state), framed by
// fitCamera() on the initial world. Returns the exit status: 0 ok, 1 runtime failure, 2 bad input.
int runHeadless(const Options& options);

}  // namespace perpdot::demo
