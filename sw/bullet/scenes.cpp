#include "sw/bullet/scenes.h"

#include "models/common/user_text.h"

#include <BulletCollision/CollisionShapes/btConvexHullShape.h>

#include <algorithm>
#include <cmath>
#include <random>
#include <stdexcept>

#include "sw/scene/spheres.h"

namespace cdvp {

namespace {

const btVector3 kGravity(0, btScalar(-9.81), 0);

// Rows of the largest pyramid of at most n boxes (rows (rows + 1) / 2 <= n).
uint32_t pyramid_rows(uint32_t n) {
    uint32_t rows = 0;
    while (static_cast<uint64_t>(rows + 1) * (rows + 2) / 2 <= n) ++rows;
    return rows;
}

constexpr uint32_t kColumnSide = 10;  // boxes and mixed fall in layers of 10 x 10
constexpr uint32_t kStackHeight = 10;

uint32_t layers(uint32_t n) { return (n + kColumnSide * kColumnSide - 1) / (kColumnSide * kColumnSide); }

void add_ground(BulletWorld& world) {
    btCollisionShape* plane = world.keep_shape(std::make_unique<btStaticPlaneShape>(btVector3(0, 1, 0), 0));
    world.add_body(plane, 0, btTransform::getIdentity());
}

btTransform placed(const btVector3& origin, const btQuaternion& rotation = btQuaternion::getIdentity()) {
    return btTransform(rotation, origin);
}

btQuaternion random_rotation(std::mt19937_64& rng) {
    std::normal_distribution<double> normal;
    btQuaternion q(btScalar(normal(rng)), btScalar(normal(rng)), btScalar(normal(rng)), btScalar(normal(rng)));
    return q.normalized();
}

void build_pyramid(BulletWorld& world, uint32_t objects) {
    add_ground(world);
    btCollisionShape* box = world.keep_shape(std::make_unique<btBoxShape>(btVector3(0.5f, 0.5f, 0.5f)));
    const uint32_t rows = pyramid_rows(objects);
    for (uint32_t row = 0; row < rows; ++row) {
        const uint32_t count = rows - row;
        for (uint32_t k = 0; k < count; ++k) {
            const btScalar x = btScalar(k) - btScalar(count - 1) / 2;
            world.add_body(box, 1, placed(btVector3(x, btScalar(row) + 0.5f, 0)));
        }
    }
    btCollisionShape* ball = world.keep_shape(std::make_unique<btSphereShape>(1.5f));
    btRigidBody* projectile = world.add_body(ball, 40, placed(btVector3(0, btScalar(rows) / 3 + 1, 12)));
    projectile->setLinearVelocity(btVector3(0, 2, -25));
}

// Body k of a scene dropped in columns: kColumnSide x kColumnSide a layer,
// layers 'spacing' apart from 'floor' up, each placed with a small jitter.
btVector3 column_origin(uint32_t k, float floor, float spacing, std::uniform_real_distribution<double>& jitter,
                        std::mt19937_64& rng) {
    const uint32_t layer = k / (kColumnSide * kColumnSide);
    const uint32_t x = k % kColumnSide, z = (k / kColumnSide) % kColumnSide;
    return btVector3(btScalar(x) - 4.5f + btScalar(jitter(rng)), floor + spacing * btScalar(layer),
                     btScalar(z) - 4.5f + btScalar(jitter(rng)));
}

void build_boxes(BulletWorld& world, uint32_t objects, std::mt19937_64& rng) {
    add_ground(world);
    btCollisionShape* box = world.keep_shape(std::make_unique<btBoxShape>(btVector3(0.4f, 0.4f, 0.4f)));
    std::uniform_real_distribution<double> jitter(-0.05, 0.05);
    for (uint32_t k = 0; k < objects; ++k) {
        const btVector3 origin = column_origin(k, 0.5f, 1.1f, jitter, rng);
        world.add_body(box, 1, placed(origin, btQuaternion(btVector3(0, 1, 0), btScalar(jitter(rng)))));
    }
}

void build_mixed(BulletWorld& world, uint32_t objects, std::mt19937_64& rng) {
    add_ground(world);
    std::vector<btCollisionShape*> shapes;
    shapes.push_back(world.keep_shape(std::make_unique<btSphereShape>(0.4f)));
    shapes.push_back(world.keep_shape(std::make_unique<btBoxShape>(btVector3(0.35f, 0.3f, 0.4f))));
    shapes.push_back(world.keep_shape(std::make_unique<btCapsuleShape>(0.25f, 0.5f)));
    auto hull = std::make_unique<btConvexHullShape>();
    std::uniform_real_distribution<double> coordinate(-0.45, 0.45);
    for (int k = 0; k < 12; ++k) {
        hull->addPoint(btVector3(btScalar(coordinate(rng)), btScalar(coordinate(rng)), btScalar(coordinate(rng))),
                       false);
    }
    hull->recalcLocalAabb();
    shapes.push_back(world.keep_shape(std::move(hull)));
    std::uniform_real_distribution<double> jitter(-0.1, 0.1);
    for (uint32_t k = 0; k < objects; ++k) {
        const btVector3 origin = column_origin(k, 1.0f, 1.2f, jitter, rng);
        world.add_body(shapes[k % shapes.size()], 1, placed(origin, random_rotation(rng)));
    }
}

void build_stacks(BulletWorld& world, uint32_t objects) {
    add_ground(world);
    btCollisionShape* box = world.keep_shape(std::make_unique<btBoxShape>(btVector3(0.5f, 0.5f, 0.5f)));
    for (uint32_t k = 0; k < objects; ++k) {
        const uint32_t tower = k / kStackHeight, level = k % kStackHeight;
        world.add_body(box, 1, placed(btVector3(3.0f * btScalar(tower), 0.5f + btScalar(level), 0)));
    }
}

// The paper's application in Bullet: the spheres of place_spheres() (same seed,
// same start as `cdvp run --scene spheres`) in a cube of six static walls.
void build_spheres(BulletWorld& world, uint32_t objects, uint64_t seed) {
    world.world().setGravity(btVector3(0, 0, 0));
    SpheresConfig config;
    config.objects = objects;
    config.seed = seed;
    const SpheresPlacement placement = place_spheres(config);
    const auto edge = btScalar(placement.edge);
    const btScalar thickness = 1;
    btCollisionShape* wall = world.keep_shape(
        std::make_unique<btBoxShape>(btVector3(edge / 2 + thickness, edge / 2 + thickness, thickness / 2)));
    const btVector3 centre(edge / 2, edge / 2, edge / 2);
    const btScalar offset = edge / 2 + thickness / 2;
    const btQuaternion facing[3] = {btQuaternion(btVector3(0, 1, 0), SIMD_HALF_PI),
                                    btQuaternion(btVector3(1, 0, 0), SIMD_HALF_PI), btQuaternion::getIdentity()};
    for (int axis = 0; axis < 3; ++axis) {
        for (btScalar side : {btScalar(-1), btScalar(1)}) {
            btVector3 origin = centre;
            origin[axis] += side * offset;
            world.add_body(wall, 0, placed(origin, facing[axis]))->setRestitution(1);
        }
    }
    for (const SphereState& sphere : placement.spheres) {
        btCollisionShape* shape = world.keep_shape(std::make_unique<btSphereShape>(btScalar(sphere.radius)));
        const auto r = btScalar(sphere.radius);
        btRigidBody* body = world.add_body(
            shape, r * r * r,
            placed(btVector3(btScalar(sphere.centre[0]), btScalar(sphere.centre[1]), btScalar(sphere.centre[2]))));
        body->setLinearVelocity(btVector3(btScalar(sphere.velocity[0]), btScalar(sphere.velocity[1]),
                                          btScalar(sphere.velocity[2])));
        body->setRestitution(1);
        body->setFriction(0);
        body->setActivationState(DISABLE_DEACTIVATION);
    }
}

uint32_t objects_of(const SceneSpec& spec) {
    const uint32_t objects = spec.objects == 0 ? default_objects(spec.name) : spec.objects;
    if (objects > kMaxSceneObjects) {
        throw std::invalid_argument("a scene of " + std::to_string(objects) + " objects; at most " +
                                    std::to_string(kMaxSceneObjects));
    }
    return objects;
}

}  // namespace

const std::vector<std::string>& bullet_scene_names() {
    static const std::vector<std::string> names = {"pyramid", "boxes", "mixed", "stack", "bullet-spheres"};
    return names;
}

bool is_bullet_scene(const std::string& name) {
    const auto& names = bullet_scene_names();
    return std::find(names.begin(), names.end(), name) != names.end();
}

std::optional<std::string> bullet_scene_refusal(const std::string& name) {
    // The old name of Bullet's spheres, now cdvp run's alone.
    if (name == "spheres") {
        return std::string("'spheres' is cdvp run's scene, stepped by the paper's application; Bullet's spheres, "
                           "with the six walls of their cube, are 'bullet-spheres'");
    }
    if (!is_bullet_scene(name)) return "expected one of " + bullet_scene_list() + ", got '" + excerpt(name) + "'";
    return std::nullopt;
}

std::string describe(const SceneSpec& spec) {
    return spec.name + " objects=" + std::to_string(objects_of(spec)) + " seed=" + std::to_string(spec.seed);
}

std::string bullet_scene_defaults() {
    std::string list;
    for (const std::string& name : bullet_scene_names()) {
        list += (list.empty() ? "" : ", ") + name + " " + std::to_string(default_objects(name));
    }
    return list;
}

std::string bullet_scene_list() {
    std::string list;
    for (const std::string& name : bullet_scene_names()) list += (list.empty() ? "" : ", ") + name;
    return list;
}

uint32_t default_objects(const std::string& name) {
    if (name == "pyramid") return 120;
    if (name == "boxes") return 3000;
    if (name == "mixed") return 500;
    if (name == "stack") return 50;
    if (name == "bullet-spheres") return 500;
    throw std::invalid_argument("unknown scene '" + name + "'; expected one of " + bullet_scene_list());
}

SceneLayout scene_layout(const SceneSpec& spec) {
    const uint32_t n = objects_of(spec);
    const auto height = [](uint32_t rows, btScalar pitch) { return btScalar(rows) * pitch + 10; };
    SceneLayout layout;
    if (spec.name == "pyramid") {
        const uint32_t rows = pyramid_rows(n);
        const btScalar reach = btScalar(rows) + 20;
        layout = {rows * (rows + 1) / 2 + 2, btVector3(-reach, -5, -reach), btVector3(reach, height(rows, 1), reach)};
    } else if (spec.name == "boxes" || spec.name == "mixed") {
        const btScalar reach = 40 + btScalar(layers(n)) / 4;
        layout = {n + 1, btVector3(-reach, -5, -reach), btVector3(reach, height(layers(n), 1.2f), reach)};
    } else if (spec.name == "stack") {
        const btScalar length = 3.0f * btScalar((n + kStackHeight - 1) / kStackHeight);
        layout = {n + 1, btVector3(-15, -5, -15), btVector3(length + 15, btScalar(kStackHeight) + 15, 15)};
    } else if (spec.name == "bullet-spheres") {
        SpheresConfig config;
        config.objects = n;
        const auto edge = btScalar(place_spheres(config).edge);
        layout = {n + 6, btVector3(-2, -2, -2), btVector3(edge + 2, edge + 2, edge + 2)};
    } else {
        default_objects(spec.name);  // throws, naming the scenes
    }
    return layout;
}

std::unique_ptr<BulletWorld> make_scene_world(const SceneSpec& spec, BroadphaseKind kind, BoardLink* link) {
    const SceneLayout layout = scene_layout(spec);
    auto world =
        std::make_unique<BulletWorld>(make_broadphase(kind, layout.world_min, layout.world_max, layout.proxies, link));
    world->world().setGravity(kGravity);
    std::mt19937_64 rng(spec.seed);
    const uint32_t n = objects_of(spec);
    if (spec.name == "pyramid") build_pyramid(*world, n);
    if (spec.name == "boxes") build_boxes(*world, n, rng);
    if (spec.name == "mixed") build_mixed(*world, n, rng);
    if (spec.name == "stack") build_stacks(*world, n);
    if (spec.name == "bullet-spheres") build_spheres(*world, n, spec.seed);
    return world;
}

}  // namespace cdvp
