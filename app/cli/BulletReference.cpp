#include "BulletReference.h"

#ifdef RL_HAVE_BULLET
#include "scene/BodyProperties.h"

#include <algorithm>
#include <btBulletDynamicsCommon.h>
#include <vector>
#endif

namespace rl::bench {

#ifdef RL_HAVE_BULLET

namespace {

btVector3 toBt(const Vec3& v) {
    return btVector3(static_cast<btScalar>(v.x), static_cast<btScalar>(v.y), static_cast<btScalar>(v.z));
}

btQuaternion toBt(const Quat& q) {
    return btQuaternion(static_cast<btScalar>(q.x), static_cast<btScalar>(q.y), static_cast<btScalar>(q.z),
                        static_cast<btScalar>(q.w));
}

// Bullet combines materials through global callbacks; these carry the current scene's rules to them.
CombineRule gFrictionRule = CombineRule::GeometricMean;
CombineRule gRestitutionRule = CombineRule::Max;

btScalar combinedFriction(const btCollisionObject* a, const btCollisionObject* b) {
    return static_cast<btScalar>(combine(gFrictionRule, a->getFriction(), b->getFriction()));
}

btScalar combinedRestitution(const btCollisionObject* a, const btCollisionObject* b) {
    return static_cast<btScalar>(combine(gRestitutionRule, a->getRestitution(), b->getRestitution()));
}

} // namespace

// Members are destroyed in reverse order: the world goes first, while the bodies, shapes, solver, broadphase and
// dispatcher it refers to are still alive.
struct BulletReference::Impl {
    btDefaultCollisionConfiguration configuration;
    btCollisionDispatcher dispatcher{&configuration};
    btDbvtBroadphase broadphase;
    btSequentialImpulseConstraintSolver solver;
    std::vector<std::unique_ptr<btCollisionShape>> shapes;
    std::vector<std::unique_ptr<btRigidBody>> bodies;
    btDiscreteDynamicsWorld world{&dispatcher, &broadphase, &solver, &configuration};
    btScalar dt = btScalar(1.0 / 60.0);

    ~Impl() {
        for (auto& body : bodies)
            world.removeRigidBody(body.get());
    }
};

bool BulletReference::available() {
    return true;
}

std::string BulletReference::description() {
    const int version = btGetVersion();
    return "Bullet " + std::to_string(version / 100) + "." + std::to_string(version % 100) + " (" +
           (sizeof(btScalar) == sizeof(double) ? "double" : "float") +
           "), btDbvtBroadphase + btSequentialImpulseConstraintSolver, " +
           std::to_string(btContactSolverInfo().m_numIterations) + " iterations";
}

BulletReference::BulletReference() : m(std::make_unique<Impl>()) {}
BulletReference::~BulletReference() = default;

std::unique_ptr<BulletReference> BulletReference::create(const Scene& scene, bool keepAwake, std::string* error) {
    std::unique_ptr<BulletReference> out(new BulletReference());
    Impl& bw = *out->m;
    bw.dt = static_cast<btScalar>(1.0 / scene.world.fps);
    bw.world.setGravity(toBt(scene.world.gravity));
    gFrictionRule = scene.world.frictionCombine;
    gRestitutionRule = scene.world.restitutionCombine;
    gCalculateCombinedFrictionCallback = combinedFriction;
    gCalculateCombinedRestitutionCallback = combinedRestitution;

    for (const BodyDef& body : scene.bodies) {
        Result<BodyProperties> props = computeBodyProperties(scene, body);
        if (!props) {
            if (error)
                *error = props.error().toString();
            return nullptr;
        }
        std::unique_ptr<btCollisionShape> shape;
        Vec3 origin = body.position; // box and sphere: the shape origin is the centre of mass
        switch (body.shape.type) {
        case ShapeType::Box:
            shape = std::make_unique<btBoxShape>(toBt(body.shape.halfExtents));
            break;
        case ShapeType::Sphere:
            shape = std::make_unique<btSphereShape>(static_cast<btScalar>(body.shape.radius));
            break;
        case ShapeType::Hull:
        case ShapeType::Mesh: {
            const Vec3 comShape = glm::inverse(body.orientation) * (props->com - body.position);
            auto hull = std::make_unique<btConvexHullShape>();
            for (const Vec3& v : props->hull.vertices)
                hull->addPoint(toBt(v - comShape), false);
            hull->recalcLocalAabb();
            shape = std::move(hull);
            origin = props->com;
            break;
        }
        }
        const MaterialDef material = scene.effectiveMaterial(body);
        const btScalar mass = body.anchor ? btScalar(0) : static_cast<btScalar>(props->mass);
        btVector3 inertia(0, 0, 0);
        if (!body.anchor)
            shape->calculateLocalInertia(mass, inertia);
        btRigidBody::btRigidBodyConstructionInfo info(mass, nullptr, shape.get(), inertia);
        info.m_startWorldTransform = btTransform(toBt(body.orientation), toBt(origin));
        info.m_friction = static_cast<btScalar>(material.friction);
        info.m_restitution = static_cast<btScalar>(material.restitution);
        auto rb = std::make_unique<btRigidBody>(info);
        if (!body.anchor) {
            rb->setLinearVelocity(toBt(body.velocity));
            rb->setAngularVelocity(toBt(body.angularVelocity));
            if (keepAwake)
                rb->setActivationState(DISABLE_DEACTIVATION);
        }
        bw.world.addRigidBody(rb.get());
        bw.shapes.push_back(std::move(shape));
        bw.bodies.push_back(std::move(rb));
    }
    return out;
}

void BulletReference::step() {
    m->world.stepSimulation(m->dt, 0);
}

int BulletReference::awakeBodies() const {
    int awake = 0;
    for (const auto& rb : m->bodies)
        awake += !rb->isStaticObject() && rb->isActive() ? 1 : 0;
    return awake;
}

int BulletReference::contactPoints() const {
    int points = 0;
    for (int i = 0; i < m->dispatcher.getNumManifolds(); ++i) {
        const btPersistentManifold* manifold = m->dispatcher.getManifoldByIndexInternal(i);
        for (int k = 0; k < manifold->getNumContacts(); ++k)
            points += manifold->getContactPoint(k).getDistance() <= 0 ? 1 : 0;
    }
    return points;
}

double BulletReference::highestDynamicY() const {
    double top = -1e300;
    for (const auto& rb : m->bodies)
        if (!rb->isStaticObject())
            top = std::max(top, static_cast<double>(rb->getCenterOfMassPosition().y()));
    return top;
}

#else // no Bullet in this build

struct BulletReference::Impl {};

bool BulletReference::available() {
    return false;
}

std::string BulletReference::description() {
    return "Bullet not built in (libbullet-dev was not found when this build was configured)";
}

BulletReference::BulletReference() = default;
BulletReference::~BulletReference() = default;

std::unique_ptr<BulletReference> BulletReference::create(const Scene&, bool, std::string* error) {
    if (error)
        *error = description();
    return nullptr;
}

void BulletReference::step() {}
int BulletReference::awakeBodies() const {
    return 0;
}
int BulletReference::contactPoints() const {
    return 0;
}
double BulletReference::highestDynamicY() const {
    return 0.0;
}

#endif

} // namespace rl::bench
