// Named scenes written once and reused by the stability tests, the benchmarks (rigidlab-cli bench) and the samples:
// towers, pyramids, mass ratios, card houses, slopes, drops, tumbling bodies and projectiles.
#pragma once

#include "scene/Scene.h"

#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace rl::scenes {

// A 40 x 1 x 40 m anchor box whose top face is y = 0.
BodyDef floorBox(const std::string& name = "Floor");
BodyDef sphere(const std::string& name, Real radius, const Vec3& position); // dynamic, of the default material
// A dynamic box of the default material with the given half extents.
BodyDef box(const std::string& name, const Vec3& half, const Vec3& position, const Quat& orientation = identityQuat());

Scene stack(int cubes);                                 // unit cubes stacked exactly touching on the floor
Scene pyramid(int base);                                // 2D pyramid of unit cubes: base + (base-1) + ... + 1
Scene massRatio(Real light = 1.0, Real heavy = 1000.0); // a heavy cube resting on a light one (0.5 m cubes)
Scene slabOnTwoCubes();                                 // 20 x 1 x 20 m slab on two unit cubes
Scene cardHouse(int levels = 5, Real friction = 0.7);   // 2 mm x 0.4 m cards: 5 levels = 40 cards
// The same with the cards leaning tiltDegrees from the vertical and the A-frames' apexes `spacing` m apart (at 0.4 m,
// a card's length, the flat cards lie end to end; closer, neighbouring flat cards lie in each other). One level is a
// single A-frame on the floor.
Scene cardHouse(int levels, Real friction, Real tiltDegrees, Real spacing);
Scene jenga(int layers = 30);              // three 0.75 x 0.15 x 0.25 m blocks per layer, crossed
Scene slope(Real degrees, Real friction);  // a block resting on an inclined anchor; body 1 is the block
Scene drop(Real height, Real restitution); // a sphere of radius 0.1 m whose bottom starts `height` above the floor
Scene tumbling(int axis, Real spin = 4.0); // a T-handle hull spun about principal axis 0, 1 or 2; no gravity
Scene randomBoxes(int count, unsigned seed = 1); // boxes of random size and orientation dropped on a floor
// 1,000 boxes of random sides 0.3-0.8 m and random turns in a 10 x 10 x 10 grid `spacing` apart, the lowest layer
// `height` up, over a floor: the layout of tests/data/acceptance/boxes1000.obj (1.6 m apart from 1 m, there with the
// boxes also moved by up to 5 cm across).
Scene boxGrid(unsigned seed, Real spacing, Real height);
Scene coincidentBoxes();                       // two identical boxes in the same place
Scene busy(unsigned seed = 7);                 // mixed spheres and boxes, restitution and friction, inside walls
Scene bullet(Real offset, Real speed = 300.0); // a 0.1 m cube shot at a 5 cm anchor wall; offset shifts the start
Scene spinningPlank(Real spin = 50.0);         // a thin plank spinning at `spin` rad/s, moving towards a thin wall
// A 0.1 m steel cube shot at 1 m height at a free-standing 5 cm x 2 m x 2 m wall on the floor (body 1; the shot is
// body 2); offset shifts the start back from 2 m before the wall.
Scene shotAtStandingWall(Real offset, Real speed = 100.0);
// Two 0.1 m steel cubes flying at each other at `speed` each, no gravity; offset shifts the first one's start back.
Scene headOnShots(Real offset, Real speed = 100.0);
Scene scalingGrid(int count); // `count` cubes on a floor in a grid, some resting, some falling

// Names for rigidlab-cli bench: "stack20", "pyramid20", "large_pyramid" (base 100), "pyramid90" (base 90, the wall that
// Box3D's own large_pyramid benchmark steps), "boxes1000", "scale1k", "scale4k", "scale16k" ... (see names()).
std::vector<std::string> names();
std::optional<Scene> byName(std::string_view name);

} // namespace rl::scenes
