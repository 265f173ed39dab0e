// Everything in perpdot's public API.
#pragma once

#include "perpdot/body.hpp"
#include "perpdot/crosscheck.hpp"
#include "perpdot/debug_draw.hpp"
#include "perpdot/error.hpp"
#include "perpdot/events.hpp"
#include "perpdot/feature_scenes.hpp"
#include "perpdot/ids.hpp"
#include "perpdot/joints.hpp"
#include "perpdot/math.hpp"
#include "perpdot/queries.hpp"
#include "perpdot/scene.hpp"
#include "perpdot/shapes.hpp"
#include "perpdot/state_hash.hpp"
#include "perpdot/world.hpp"
