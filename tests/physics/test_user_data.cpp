// lfem_body_get_user_data returns the lfem_body_def.user_data the body was created with (lfem.h:
// "nullable, returned by lfem_body_get_user_data"): the same pointer, for every kind of body,
// through steps and other bodies' creation and destruction, NULL by default and after a
// checkpoint is loaded ("user_data pointers are not saved (NULL after loading)"). Bad input is
// refused with the documented status, leaving the output and the world as they were.
#include <cstdint>
#include <cstdio>
#include <string>

#include "physics/lfem_test_util.h"

using namespace lfem_test;

namespace {

struct Entity {
    int id;
};

void* user_data(lfem_world* w, lfem_body b) {
    void* out = reinterpret_cast<void*>(uintptr_t(0xbad));  // overwritten on success
    EXPECT_EQ(lfem_body_get_user_data(w, b, &out), LFEM_OK) << lfem_last_error();
    return out;
}

}  // namespace

TEST(UserData, RoundTripsForEveryKindOfBody) {
    World w;
    Entity ball{1}, wall{2}, crate{3};
    Mesh mesh, wall_mesh, crate_mesh, plain_mesh;
    make_box_mesh(mesh, 0.1, 0.1, 0.1, 1, 1, 1, 0.0, 0.0, 1.0);
    lfem_body_def def = lfem_body_def_default();
    EXPECT_EQ(def.user_data, nullptr);  // the default
    def.user_data = &ball;
    const lfem_body deformable = add_body(w, def, mesh);
    make_box_mesh(wall_mesh, 1.0, 1.0, 0.1, 1, 1, 1, -0.5, -0.5, -0.1);
    lfem_body_def static_def = lfem_body_def_default();
    static_def.type = LFEM_BODY_STATIC;
    static_def.user_data = &wall;
    const lfem_body floor = add_body(w, static_def, wall_mesh);
    make_box_mesh(crate_mesh, 0.1, 0.1, 0.1, 1, 1, 1, 0.5, 0.0, 1.0);
    lfem_body_def rigid_def = lfem_body_def_default();
    rigid_def.type = LFEM_BODY_RIGID;
    rigid_def.user_data = &crate;
    const lfem_body rigid = add_body(w, rigid_def, crate_mesh);
    lfem_body_def kinematic_def = lfem_body_def_default();  // shapes only, no mesh
    kinematic_def.type = LFEM_BODY_KINEMATIC;
    // An entity id cast to a pointer, as engines store them: lfem keeps the value, it never
    // reads through it.
    kinematic_def.user_data = reinterpret_cast<void*>(uintptr_t(42));
    lfem_body kinematic{};
    ASSERT_EQ(lfem_body_create(w, &kinematic_def, &kinematic), LFEM_OK) << lfem_last_error();
    lfem_shape_def sphere = lfem_shape_def_default();
    sphere.type = LFEM_SHAPE_SPHERE;
    sphere.radius = 0.05;
    sphere.center[0] = -0.5;
    sphere.center[2] = 1.0;
    ASSERT_EQ(lfem_body_add_shape(w, kinematic, &sphere, nullptr), LFEM_OK) << lfem_last_error();
    make_box_mesh(plain_mesh, 0.1, 0.1, 0.1, 1, 1, 1, 0.0, 0.5, 1.0);
    const lfem_body plain = add_body(w, lfem_body_def_default(), plain_mesh);

    auto check = [&](const char* when) {
        EXPECT_EQ(user_data(w, deformable), &ball) << when;
        EXPECT_EQ(user_data(w, floor), &wall) << when;
        EXPECT_EQ(user_data(w, rigid), &crate) << when;
        EXPECT_EQ(user_data(w, kinematic), reinterpret_cast<void*>(uintptr_t(42))) << when;
        EXPECT_EQ(user_data(w, plain), nullptr) << when;
    };
    check("after creation");
    // The definition was copied: changing it later changes nothing.
    def.user_data = &crate;
    check("after the definition changed");
    for (int i = 0; i < 10; ++i) ASSERT_EQ(lfem_world_step(w, 0.02), LFEM_OK) << lfem_last_error();
    check("after stepping");
    // Another body destroyed, and one created after it with its own user data.
    Entity newcomer{4};
    ASSERT_EQ(lfem_body_destroy(w, plain), LFEM_OK) << lfem_last_error();
    Mesh new_mesh;
    make_box_mesh(new_mesh, 0.1, 0.1, 0.1, 1, 1, 1, 0.0, -0.5, 1.0);
    lfem_body_def new_def = lfem_body_def_default();
    new_def.user_data = &newcomer;
    const lfem_body reborn = add_body(w, new_def, new_mesh);
    EXPECT_EQ(user_data(w, reborn), &newcomer);
    EXPECT_EQ(ball.id + wall.id + crate.id + newcomer.id, 10);  // lfem never wrote through them
    const lfem_body live[] = {deformable, floor, rigid, kinematic};
    for (lfem_body b : live) ASSERT_TRUE(lfem_body_is_valid(w, b));
    EXPECT_EQ(user_data(w, deformable), &ball);
    EXPECT_EQ(user_data(w, kinematic), reinterpret_cast<void*>(uintptr_t(42)));

    // A checkpoint keeps the bodies (and their handles) but not the pointers.
    if (!LFEM_WITH_IO) GTEST_SKIP() << "built without checkpoint files (LFEM_WITH_IO=OFF)";
    const std::string path = ::testing::TempDir() + "lfem_user_data.ckpt";
    ASSERT_EQ(lfem_world_save(w, path.c_str()), LFEM_OK) << lfem_last_error();
    lfem_world* loaded = nullptr;
    ASSERT_EQ(lfem_world_load(path.c_str(), &loaded), LFEM_OK) << lfem_last_error();
    for (lfem_body b : {deformable, floor, rigid, kinematic, reborn}) EXPECT_EQ(user_data(loaded, b), nullptr);
    lfem_world_destroy(loaded);
    std::remove(path.c_str());
}

// lfem.h: a null pointer where one is required is LFEM_INVALID_ARGUMENT, a stale or foreign
// handle LFEM_INVALID_HANDLE, and on failure "the world, the body and every output argument are
// left exactly as they were".
TEST(UserData, RefusesBadInputAndLeavesTheOutputAlone) {
    World w, other;
    Entity e{7};
    Mesh mesh, doomed_mesh, other_mesh;
    make_box_mesh(mesh, 0.1, 0.1, 0.1, 1, 1, 1);
    lfem_body_def def = lfem_body_def_default();
    def.user_data = &e;
    const lfem_body body = add_body(w, def, mesh);
    make_box_mesh(doomed_mesh, 0.1, 0.1, 0.1, 1, 1, 1, 1.0, 0.0, 0.0);
    const lfem_body doomed = add_body(w, def, doomed_mesh);
    ASSERT_EQ(lfem_body_destroy(w, doomed), LFEM_OK) << lfem_last_error();
    make_box_mesh(other_mesh, 0.1, 0.1, 0.1, 1, 1, 1);
    add_body(other, lfem_body_def_default(), other_mesh);
    const lfem_body alien = add_body(other, def, other_mesh);  // the other world's second slot, as doomed's here
    ASSERT_EQ(lfem_world_step(w, 0.01), LFEM_OK) << lfem_last_error();
    const std::vector<unsigned char> before = fingerprint(w, {body, doomed});

    void* const sentinel = reinterpret_cast<void*>(uintptr_t(0x5e17));
    const struct {
        lfem_world* world;
        lfem_body body;
        lfem_status expected;
        const char* what;
    } cases[] = {{nullptr, body, LFEM_INVALID_ARGUMENT, "null world"},
                 {w, doomed, LFEM_INVALID_HANDLE, "stale handle"},
                 {w, lfem_body{0, 0}, LFEM_INVALID_HANDLE, "null handle"},
                 {w, alien, LFEM_INVALID_HANDLE, "foreign handle"}};
    for (const auto& c : cases) {
        void* out = sentinel;
        EXPECT_EQ(lfem_body_get_user_data(c.world, c.body, &out), c.expected) << c.what;
        EXPECT_STRNE(lfem_last_error(), "") << c.what;
        EXPECT_EQ(out, sentinel) << c.what << " wrote the output";
        EXPECT_EQ(before, fingerprint(w, {body, doomed})) << c.what << " changed the world";
    }
    EXPECT_EQ(lfem_body_get_user_data(w, body, nullptr), LFEM_INVALID_ARGUMENT) << "null out";
    EXPECT_STRNE(lfem_last_error(), "");
    EXPECT_EQ(before, fingerprint(w, {body, doomed})) << "null out changed the world";
    EXPECT_EQ(user_data(w, body), &e);  // and the good call still answers
    EXPECT_EQ(e.id, 7);
}

// lfem_body_set_user_id: an opaque 64-bit number, 0 at creation, any value (all 64 bits), on
// every kind of body, kept by a checkpoint (where the user data pointers are not).
TEST(UserData, AUserIdIsKeptByACheckpoint) {
    World w;
    Mesh mesh;
    make_box_mesh(mesh, 0.1, 0.1, 0.1, 1, 1, 1, 0.0, 0.0, 1.0);
    const lfem_body soft = add_body(w, lfem_body_def_default(), mesh);
    lfem_body_def rigid_def = lfem_body_def_default();
    rigid_def.type = LFEM_BODY_RIGID;
    const lfem_body rigid = add_body(w, rigid_def, mesh);
    const lfem_body floor = add_plane_floor(w);
    uint64_t id = 7;
    ASSERT_EQ(lfem_body_get_user_id(w, soft, &id), LFEM_OK) << lfem_last_error();
    EXPECT_EQ(id, 0u);
    const uint64_t ids[3] = {0xFFFFFFFFFFFFFFFFull, 0x8000000000000001ull, 42};
    const lfem_body bodies[3] = {soft, rigid, floor};
    for (int k = 0; k < 3; ++k) ASSERT_EQ(lfem_body_set_user_id(w, bodies[k], ids[k]), LFEM_OK) << lfem_last_error();
    ASSERT_EQ(lfem_world_step(w, 0.01), LFEM_OK) << lfem_last_error();
    for (int k = 0; k < 3; ++k) {
        ASSERT_EQ(lfem_body_get_user_id(w, bodies[k], &id), LFEM_OK);
        EXPECT_EQ(id, ids[k]);
    }
    // Bad input: refused, the output and the ids untouched.
    ASSERT_EQ(lfem_body_destroy(w, rigid), LFEM_OK);
    id = 5;
    EXPECT_EQ(lfem_body_get_user_id(w, rigid, &id), LFEM_INVALID_HANDLE);
    EXPECT_EQ(lfem_body_set_user_id(w, rigid, 1), LFEM_INVALID_HANDLE);
    EXPECT_EQ(lfem_body_set_user_id(nullptr, soft, 1), LFEM_INVALID_ARGUMENT);
    EXPECT_EQ(lfem_body_get_user_id(w, soft, nullptr), LFEM_INVALID_ARGUMENT);
    EXPECT_EQ(id, 5u);
    if (!LFEM_WITH_IO) GTEST_SKIP() << "built without checkpoint files (LFEM_WITH_IO=OFF)";
    const std::string path = ::testing::TempDir() + "lfem_user_id.ckpt";
    ASSERT_EQ(lfem_world_save(w, path.c_str()), LFEM_OK) << lfem_last_error();
    lfem_world* loaded = nullptr;
    ASSERT_EQ(lfem_world_load(path.c_str(), &loaded), LFEM_OK) << lfem_last_error();
    for (int k : {0, 2}) {
        ASSERT_EQ(lfem_body_get_user_id(loaded, bodies[k], &id), LFEM_OK) << lfem_last_error();
        EXPECT_EQ(id, ids[k]);
    }
    lfem_world_destroy(loaded);
    std::remove(path.c_str());
}
