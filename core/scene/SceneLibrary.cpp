#include "scene/SceneLibrary.h"

#include <cmath>
#include <random>

namespace rl::scenes {

BodyDef box(const std::string& name, const Vec3& half, const Vec3& position, const Quat& orientation) {
    BodyDef b;
    b.name = name;
    b.shape.type = ShapeType::Box;
    b.shape.halfExtents = half;
    b.position = position;
    b.orientation = orientation;
    return b;
}

namespace {

BodyDef anchorBox(const std::string& name, const Vec3& half, const Vec3& position,
                  const Quat& orientation = identityQuat()) {
    BodyDef b = box(name, half, position, orientation);
    b.anchor = true;
    return b;
}

std::string numbered(const std::string& base, int i) {
    return base + "." + std::to_string(i);
}

} // namespace

BodyDef sphere(const std::string& name, Real radius, const Vec3& position) {
    BodyDef b;
    b.name = name;
    b.shape.type = ShapeType::Sphere;
    b.shape.radius = radius;
    b.position = position;
    return b;
}

BodyDef floorBox(const std::string& name) {
    return anchorBox(name, Vec3(20.0, 0.5, 20.0), Vec3(0.0, -0.5, 0.0));
}

Scene stack(int cubes) {
    Scene s;
    s.bodies.push_back(floorBox());
    for (int i = 0; i < cubes; ++i)
        s.bodies.push_back(box(numbered("Cube", i), Vec3(0.5), Vec3(0.0, 0.5 + i, 0.0)));
    return s;
}

Scene pyramid(int base) {
    Scene s;
    s.bodies.push_back(floorBox());
    if (base > 40)
        s.bodies[0].shape.halfExtents = Vec3(base, 0.5, 20.0);
    int n = 0;
    for (int row = 0; row < base; ++row) {
        const int count = base - row;
        for (int k = 0; k < count; ++k) {
            const Real x = (k - 0.5 * (count - 1)) * 1.0;
            s.bodies.push_back(box(numbered("Cube", n++), Vec3(0.5), Vec3(x, 0.5 + row, 0.0)));
        }
    }
    return s;
}

Scene massRatio(Real light, Real heavy) {
    Scene s;
    s.bodies.push_back(floorBox());
    s.bodies.push_back(box("Light", Vec3(0.25), Vec3(0.0, 0.25, 0.0)));
    s.bodies.back().mass = light;
    s.bodies.push_back(box("Heavy", Vec3(0.25), Vec3(0.0, 0.75, 0.0)));
    s.bodies.back().mass = heavy;
    return s;
}

Scene slabOnTwoCubes() {
    Scene s;
    s.bodies.push_back(floorBox());
    s.bodies.push_back(box("Left", Vec3(0.5), Vec3(-8.0, 0.5, 0.0)));
    s.bodies.push_back(box("Right", Vec3(0.5), Vec3(8.0, 0.5, 0.0)));
    s.bodies.push_back(box("Slab", Vec3(10.0, 0.5, 10.0), Vec3(0.0, 1.5, 0.0)));
    return s;
}

Scene cardHouse(int levels, Real friction) {
    // Between A-frame apexes on one level: a card's length, so that the flat cards bridging them lie end to end, each
    // end on the top edge of one leaning card. (At 0.34 m neighbouring flat cards lay 6 cm into each other, 2 mm
    // deep, from the first step: at 48 substeps the house fell, at 24 its cards moved 8 mm; 0.14 and 0.24 mm now.)
    return cardHouse(levels, friction, 18.0, 0.4);
}

Scene cardHouse(int levels, Real friction, Real tiltDegrees, Real spacing) {
    Scene s;
    s.materials.push_back({"Card", 700.0, friction, 0.0});
    s.bodies.push_back(floorBox());
    s.bodies.back().material = "Card";
    const Real half = 0.2, thick = 0.001, width = 0.15; // 0.4 m tall, 2 mm thick, 0.3 m wide cards
    const Real tilt = glm::radians(tiltDegrees);
    const Real lean = half * std::sin(tilt), rise = half * std::cos(tilt);
    // The leaning cards' highest corners (their outer top edges) are 2 rise + 2 thick sin(tilt) above the base.
    const Real frameHeight = 2.0 * rise + 2.0 * thick * std::sin(tilt);
    int n = 0;
    Real base = 0.0;
    for (int level = 0; level < levels; ++level) {
        const int frames = levels - level;
        const Real x0 = -0.5 * (frames - 1) * spacing;
        for (int f = 0; f < frames; ++f) {
            const Real apex = x0 + f * spacing;
            // Two cards leaning on each other: tops meet at the apex, feet apart.
            const Real dx = lean + thick / std::cos(tilt);
            const Real y = base + rise + thick * std::sin(tilt);
            s.bodies.push_back(box(numbered("Card", n++), Vec3(thick, half, width), Vec3(apex - dx, y, 0.0),
                                   glm::angleAxis(-tilt, Vec3(0, 0, 1))));
            s.bodies.back().material = "Card";
            s.bodies.push_back(box(numbered("Card", n++), Vec3(thick, half, width), Vec3(apex + dx, y, 0.0),
                                   glm::angleAxis(tilt, Vec3(0, 0, 1))));
            s.bodies.back().material = "Card";
        }
        base += frameHeight;
        // Flat cards bridging neighbouring apexes carry the next level.
        for (int f = 0; f + 1 < frames; ++f) {
            const Real x = x0 + (f + 0.5) * spacing;
            s.bodies.push_back(box(numbered("Card", n++), Vec3(half, thick, width), Vec3(x, base + thick, 0.0)));
            s.bodies.back().material = "Card";
        }
        base += 2.0 * thick;
    }
    return s;
}

Scene jenga(int layers) {
    Scene s;
    s.materials.push_back({"Maple", 700.0, 0.5, 0.0});
    s.bodies.push_back(floorBox());
    const Vec3 half(0.375, 0.075, 0.125); // 0.75 x 0.15 x 0.25 m: a Jenga block scaled 10x
    int n = 0;
    for (int layer = 0; layer < layers; ++layer) {
        const bool alongX = layer % 2 == 0;
        const Real y = half.y + layer * 2.0 * half.y;
        for (int k = -1; k <= 1; ++k) {
            const Real offset = k * 2.0 * half.z;
            const Vec3 pos = alongX ? Vec3(0.0, y, offset) : Vec3(offset, y, 0.0);
            const Quat q = alongX ? identityQuat() : glm::angleAxis(0.5 * kPi, Vec3(0, 1, 0));
            s.bodies.push_back(box(numbered("Block", n++), half, pos, q));
            s.bodies.back().material = "Maple";
        }
    }
    return s;
}

Scene slope(Real degrees, Real friction) {
    Scene s;
    s.materials.push_back({"Test", 1000.0, friction, 0.0});
    const Quat tilt = glm::angleAxis(glm::radians(degrees), Vec3(0, 0, 1));
    // Ramp: a 20 x 1 x 4 m slab tilted about z; its top face passes through the origin.
    const Vec3 normal = tilt * Vec3(0, 1, 0);
    s.bodies.push_back(anchorBox("Ramp", Vec3(10.0, 0.5, 2.0), -0.5 * normal, tilt));
    s.bodies.back().material = "Test";
    s.bodies.push_back(box("Block", Vec3(0.25), 0.25 * normal, tilt));
    s.bodies.back().material = "Test";
    return s;
}

Scene drop(Real height, Real restitution) {
    Scene s;
    s.materials.push_back({"Bouncy", 1000.0, 0.5, restitution});
    s.bodies.push_back(floorBox());
    s.bodies.back().material = "Bouncy";
    s.bodies.push_back(sphere("Ball", 0.1, Vec3(0.0, height + 0.1, 0.0)));
    s.bodies.back().material = "Bouncy";
    return s;
}

Scene tumbling(int axis, Real spin) {
    Scene s;
    s.world.gravity = Vec3(0.0);
    // A T-handle: a 0.8 m bar with a 0.6 m stem, as one convex hull of their corners. Its three principal moments
    // differ, so the intermediate axis is unstable (the Dzhanibekov effect).
    BodyDef t;
    t.name = "THandle";
    t.shape.type = ShapeType::Hull;
    const Real bx = 0.4, by = 0.05, bz = 0.05, sx = 0.05, sy = 0.3, sz = 0.05;
    for (int i = 0; i < 8; ++i) {
        const Vec3 sign((i & 1) ? 1 : -1, (i & 2) ? 1 : -1, (i & 4) ? 1 : -1);
        t.shape.points.push_back(Vec3(bx, by, bz) * sign + Vec3(0, sy, 0));
        t.shape.points.push_back(Vec3(sx, sy, sz) * sign);
    }
    // The principal axes of this hull are x, y, z by symmetry; which one is intermediate is found at run time
    // by the test from the inertia. Spin about the requested axis with a tiny perturbation.
    Vec3 w(0.0);
    w[axis] = spin;
    w += Vec3(1e-3, 1e-3, 1e-3) * spin;
    t.angularVelocity = w;
    s.bodies.push_back(t);
    return s;
}

Scene randomBoxes(int count, unsigned seed) {
    Scene s;
    s.bodies.push_back(floorBox());
    std::mt19937 rng(seed);
    std::uniform_real_distribution<Real> size(0.15, 0.4), unit(-1.0, 1.0), angle(0.0, 2.0 * kPi);
    const int side = static_cast<int>(std::ceil(std::sqrt(count / 4.0)));
    for (int i = 0; i < count; ++i) {
        const int layer = i / (side * side), cell = i % (side * side);
        const Vec3 pos((cell % side - 0.5 * side) * 1.0 + 0.1 * unit(rng), 1.0 + layer * 1.0,
                       (cell / side - 0.5 * side) * 1.0 + 0.1 * unit(rng));
        const Vec3 axis = glm::normalize(Vec3(unit(rng), unit(rng), unit(rng)) + Vec3(0, 0, 1e-6));
        s.bodies.push_back(
            box(numbered("Box", i), Vec3(size(rng), size(rng), size(rng)), pos, glm::angleAxis(angle(rng), axis)));
    }
    return s;
}

Scene boxGrid(unsigned seed, Real spacing, Real height) {
    Scene s;
    s.bodies.push_back(floorBox());
    std::mt19937 rng(seed);
    std::uniform_real_distribution<Real> side(0.3, 0.8), unit(-1.0, 1.0), angle(0.0, 2.0 * kPi);
    for (int i = 0; i < 1000; ++i) {
        const Vec3 at((i % 10 - 4.5) * spacing, height + (i / 100) * spacing, ((i / 10) % 10 - 4.5) * spacing);
        const Vec3 axis = glm::normalize(Vec3(unit(rng), unit(rng), unit(rng)) + Vec3(0.0, 0.0, 1e-6));
        const Vec3 half = 0.5 * Vec3(side(rng), side(rng), side(rng));
        s.bodies.push_back(box("Box" + std::to_string(i), half, at, glm::angleAxis(angle(rng), axis)));
    }
    return s;
}

Scene coincidentBoxes() {
    Scene s;
    s.world.gravity = Vec3(0.0);
    s.bodies.push_back(box("A", Vec3(0.5), Vec3(0.0)));
    s.bodies.push_back(box("B", Vec3(0.5), Vec3(0.0)));
    return s;
}

Scene busy(unsigned seed) {
    Scene s;
    s.materials.push_back({"Lively", 800.0, 0.4, 0.5});
    s.bodies.push_back(floorBox());
    // Four walls keep everything in a 6 x 6 m pen.
    s.bodies.push_back(anchorBox("WallA", Vec3(3.5, 2.0, 0.25), Vec3(0.0, 2.0, 3.25)));
    s.bodies.push_back(anchorBox("WallB", Vec3(3.5, 2.0, 0.25), Vec3(0.0, 2.0, -3.25)));
    s.bodies.push_back(anchorBox("WallC", Vec3(0.25, 2.0, 3.0), Vec3(3.25, 2.0, 0.0)));
    s.bodies.push_back(anchorBox("WallD", Vec3(0.25, 2.0, 3.0), Vec3(-3.25, 2.0, 0.0)));
    std::mt19937 rng(seed);
    std::uniform_real_distribution<Real> unit(-1.0, 1.0), size(0.15, 0.35);
    for (int i = 0; i < 60; ++i) {
        const Vec3 pos((i % 6 - 2.5) * 0.9, 0.6 + (i / 36) * 1.2 + 0.6 * ((i / 6) % 2), ((i / 6) % 6 - 2.5) * 0.9);
        BodyDef b = i % 2 ? sphere(numbered("Ball", i), size(rng), pos)
                          : box(numbered("Box", i), Vec3(size(rng), size(rng), size(rng)), pos);
        b.material = "Lively";
        b.velocity = Vec3(unit(rng), unit(rng), unit(rng)) * 3.0;
        b.angularVelocity = Vec3(unit(rng), unit(rng), unit(rng)) * 2.0;
        s.bodies.push_back(b);
    }
    return s;
}

Scene bullet(Real offset, Real speed) {
    Scene s;
    s.world.gravity = Vec3(0.0);
    s.materials.push_back({"Steelish", 7850.0, 0.5, 0.0});
    s.bodies.push_back(anchorBox("Wall", Vec3(0.025, 2.0, 2.0), Vec3(0.0, 0.0, 0.0)));
    s.bodies.push_back(box("Shot", Vec3(0.05), Vec3(-1.0 - offset, 0.0, 0.0)));
    s.bodies.back().material = "Steelish";
    s.bodies.back().velocity = Vec3(speed, 0.0, 0.0);
    return s;
}

Scene spinningPlank(Real spin) {
    Scene s;
    s.world.gravity = Vec3(0.0);
    s.bodies.push_back(anchorBox("Wall", Vec3(0.025, 2.0, 2.0), Vec3(0.0, 0.0, 0.0)));
    s.bodies.push_back(box("Plank", Vec3(0.5, 0.05, 0.1), Vec3(-1.0, 0.0, 0.0)));
    s.bodies.back().angularVelocity = Vec3(0.0, 0.0, spin);
    s.bodies.back().velocity = Vec3(3.0, 0.0, 0.0);
    return s;
}

Scene shotAtStandingWall(Real offset, Real speed) {
    Scene s;
    s.materials.push_back({"Steelish", 7850.0, 0.5, 0.0});
    s.bodies.push_back(floorBox());
    s.bodies.push_back(box("Wall", Vec3(0.025, 1.0, 1.0), Vec3(0.0, 1.0, 0.0)));
    s.bodies.push_back(box("Shot", Vec3(0.05), Vec3(-2.0 - offset, 1.0, 0.0)));
    s.bodies.back().material = "Steelish";
    s.bodies.back().velocity = Vec3(speed, 0.0, 0.0);
    return s;
}

Scene headOnShots(Real offset, Real speed) {
    Scene s;
    s.world.gravity = Vec3(0.0);
    s.materials.push_back({"Steelish", 7850.0, 0.5, 0.0});
    s.bodies.push_back(box("Left", Vec3(0.05), Vec3(-1.5 - offset, 0.0, 0.0)));
    s.bodies.back().velocity = Vec3(speed, 0.0, 0.0);
    s.bodies.push_back(box("Right", Vec3(0.05), Vec3(1.5, 0.0, 0.0)));
    s.bodies.back().velocity = Vec3(-speed, 0.0, 0.0);
    for (BodyDef& b : s.bodies)
        b.material = "Steelish";
    return s;
}

Scene scalingGrid(int count) {
    Scene s;
    const int side = static_cast<int>(std::ceil(std::sqrt(count / 2.0)));
    BodyDef floor = floorBox();
    floor.shape.halfExtents = Vec3(side * 0.6 + 2.0, 0.5, side * 0.6 + 2.0);
    s.bodies.push_back(floor);
    for (int i = 0; i < count; ++i) {
        const int layer = i / (side * side), cell = i % (side * side);
        s.bodies.push_back(
            box(numbered("Cube", i), Vec3(0.25),
                Vec3((cell % side - 0.5 * side) * 1.2, 0.25 + layer * 0.6, (cell / side - 0.5 * side) * 1.2)));
    }
    return s;
}

std::vector<std::string> names() {
    return {"stack20", "stack40", "pyramid20", "large_pyramid", "pyramid90", "boxes1000", "card_house",
            "jenga",   "scale1k", "scale2k",   "scale4k",       "scale8k",   "scale16k"};
}

std::optional<Scene> byName(std::string_view name) {
    if (name == "stack20")
        return stack(20);
    if (name == "stack40")
        return stack(40);
    if (name == "pyramid20")
        return pyramid(20);
    if (name == "large_pyramid")
        return pyramid(100);
    if (name == "pyramid90") // Box3D's benchmark "large_pyramid": 4,095 cubes, for a comparison on the same machine
        return pyramid(90);
    if (name == "boxes1000")
        return randomBoxes(1000);
    if (name == "card_house")
        return cardHouse();
    if (name == "jenga")
        return jenga();
    if (name == "scale1k")
        return scalingGrid(1000);
    if (name == "scale2k")
        return scalingGrid(2000);
    if (name == "scale4k")
        return scalingGrid(4000);
    if (name == "scale8k")
        return scalingGrid(8000);
    if (name == "scale16k")
        return scalingGrid(16000);
    return std::nullopt;
}

} // namespace rl::scenes
