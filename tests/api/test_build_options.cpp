// Build options that leave parts out (LFEM_WITH_CCD, LFEM_WITH_IO): in a build without a part,
// every call that needs it answers LFEM_UNSUPPORTED with a message naming the option, after
// checking its arguments, and changes nothing; in a full build the same calls work.
#include <cstdio>
#include <string>

#include "physics/lfem_test_util.h"

using namespace lfem_test;

namespace {

void expect_unsupported(lfem_status s, const char* option, const char* what) {
    EXPECT_EQ(s, LFEM_UNSUPPORTED) << what << ": " << lfem_last_error();
    EXPECT_NE(std::string(lfem_last_error()).find(option), std::string::npos)
        << what << ": the message should name " << option << ": " << lfem_last_error();
}

}  // namespace

TEST(BuildOptions, UnsupportedHasItsOwnStatusString) {
    EXPECT_EQ(int(LFEM_UNSUPPORTED), 9);
    EXPECT_EQ(std::string(lfem_status_string(LFEM_UNSUPPORTED)),
              "LFEM_UNSUPPORTED: this build leaves the feature out");
}

TEST(BuildOptions, ConvexHullsNeedLibccd) {
    World w;
    lfem_body_def d = lfem_body_def_default();
    d.type = LFEM_BODY_STATIC;
    lfem_body ground{};
    ASSERT_EQ(lfem_body_create(w, &d, &ground), LFEM_OK);
    const double pts[] = {0, 0, 0, 1, 0, 0, 0, 1, 0, 0, 0, 1};
    lfem_shape_def hull = lfem_shape_def_default();
    hull.type = LFEM_SHAPE_CONVEX_HULL;
    hull.points = pts;
    hull.point_count = 4;
    const lfem_status s = lfem_body_add_shape(w, ground, &hull, NULL);
    if (LFEM_WITH_CCD) {
        EXPECT_EQ(s, LFEM_OK) << lfem_last_error();
    } else {
        expect_unsupported(s, "LFEM_WITH_CCD", "add a convex hull");
        // Refused after the argument checks: a bad hull is still an invalid argument.
        hull.point_count = 3;
        EXPECT_EQ(lfem_body_add_shape(w, ground, &hull, NULL), LFEM_INVALID_ARGUMENT);
        // The closed-form shapes stay.
        const lfem_shape_def plane = lfem_shape_def_default();
        EXPECT_EQ(lfem_body_add_shape(w, ground, &plane, NULL), LFEM_OK) << lfem_last_error();
    }
}

TEST(BuildOptions, FileInputAndOutputNeedIo) {
    World w;
    Mesh m;
    make_box_mesh(m, 0.1, 0.1, 0.1, 1, 1, 1);
    add_body(w, lfem_body_def_default(), m);
    const std::string dir = ::testing::TempDir();
    const std::string ckpt = dir + "lfem_build_options.ckpt", pvd = dir + "lfem_build_options.pvd";
    const std::string msh = std::string(LFEM_TEST_DATA_DIR) + "/cube_v22.msh";
    lfem_mesh* loaded_mesh = nullptr;
    lfem_world* loaded = nullptr;
    lfem_vtk_series* series = nullptr;
    if (LFEM_WITH_IO) {
        EXPECT_EQ(lfem_mesh_load_gmsh(msh.c_str(), &loaded_mesh), LFEM_OK) << lfem_last_error();
        EXPECT_EQ(lfem_world_save(w, ckpt.c_str()), LFEM_OK) << lfem_last_error();
        EXPECT_EQ(lfem_world_load(ckpt.c_str(), &loaded), LFEM_OK) << lfem_last_error();
        EXPECT_EQ(lfem_vtk_series_create(pvd.c_str(), &series), LFEM_OK) << lfem_last_error();
        std::remove(ckpt.c_str());
    } else {
        expect_unsupported(lfem_mesh_load_gmsh(msh.c_str(), &loaded_mesh), "LFEM_WITH_IO", "load Gmsh");
        expect_unsupported(lfem_world_save(w, ckpt.c_str()), "LFEM_WITH_IO", "save a checkpoint");
        expect_unsupported(lfem_world_load(ckpt.c_str(), &loaded), "LFEM_WITH_IO", "load a checkpoint");
        expect_unsupported(lfem_vtk_series_create(pvd.c_str(), &series), "LFEM_WITH_IO", "VTK series");
        // Nothing was created or written.
        EXPECT_EQ(loaded_mesh, nullptr);
        EXPECT_EQ(loaded, nullptr);
        EXPECT_EQ(series, nullptr);
        EXPECT_EQ(std::fopen(ckpt.c_str(), "rb"), nullptr);
        // Argument checks come first.
        EXPECT_EQ(lfem_world_save(w, nullptr), LFEM_INVALID_ARGUMENT);
        EXPECT_EQ(lfem_mesh_load_gmsh(nullptr, &loaded_mesh), LFEM_INVALID_ARGUMENT);
    }
    lfem_mesh_destroy(loaded_mesh);
    lfem_world_destroy(loaded);
    lfem_vtk_series_destroy(series);
}
