/// @file
/// The engine's whole public API (the perpdot::core library). The tooling layers' headers are
/// included on their own: perpdot/scene.hpp, perpdot/feature_scenes.hpp (perpdot::scene) and
/// perpdot/crosscheck.hpp (perpdot::crosscheck).
#pragma once

#include "perpdot/body.hpp"
#include "perpdot/debug_draw.hpp"
#include "perpdot/error.hpp"
#include "perpdot/events.hpp"
#include "perpdot/ids.hpp"
#include "perpdot/joints.hpp"
#include "perpdot/math.hpp"
#include "perpdot/portable_math.hpp"
#include "perpdot/queries.hpp"
#include "perpdot/shapes.hpp"
#include "perpdot/state_hash.hpp"
#include "perpdot/world.hpp"
