// perpdot-demo's command line.
#pragma once

#include <string>
#include <vector>

#include "perpdot/debug_draw.hpp"

namespace perpdot::demo {

inline constexpr const char* usage =
    "usage:\n"
    "  perpdot-demo [SCENE|FILE] [--size WxH] [--exit-after FRAMES] [--show LIST]\n"
    "  perpdot-demo --headless SCENE|FILE --frames N --out DIR [--every K] [--size WxH] [--show LIST]\n"
    "                [--no-crosscheck]\n"
    "  perpdot-demo --list\n"
    "LIST: comma-separated debug layers among shapes,com,velocities,aabbs,contacts,impulses,joints\n"
    "      (default shapes,joints)\n";

struct Options {
    bool headless = false;
    bool list = false;
    bool help = false;
    std::string scene;         // built-in name or .json path; empty: the first built-in scene
    int frames = 0;            // headless: how many PNG frames
    int every = 1;             // headless: steps between frames
    std::string outDir;        // headless: where frame_0000.png ... go
    int width = 0, height = 0; // 0: the mode's default
    int exitAfter = 0;         // windowed: quit after this many frames (0: never)
    bool crosscheck = true;    // headless: also run the scene in Box2D and print the drift
    DebugDrawOptions draw;
};

// Throws UsageError on anything malformed.
struct UsageError {
    std::string message;
};
Options parseOptions(const std::vector<std::string>& args);

}  // namespace perpdot::demo
