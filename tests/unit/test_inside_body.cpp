// Whether a node lies inside a deformable body (contact/node_face.h, inside_near): in one of the
// tets around the corners of a face it lies behind. Lying behind a face's plane is not enough:
// above a thin plate a point lies behind the plate's far face, and is outside it.
//
// The body: a plate 1 x 1 x 0.1 m of 2 x 2 x 1 cells, its top at z = 0.1, as contact sees it
// (its tets, boundary triangles and the tets around each surface node).
#include <gtest/gtest.h>

#include <vector>

#include "contact/contact_body.h"
#include "contact/node_face.h"
#include "mesh/boundary.h"
#include "mesh/mesh_builders.h"
#include "mesh/surface.h"

namespace {

using lfem::ContactBody;
using lfem::Vec3;

struct Plate {
    lfem::TetMesh mesh;
    lfem::Surface surface;
    ContactBody body;

    Plate() {
        const double size[3] = {1.0, 1.0, 0.1};
        const uint32_t cells[3] = {2, 2, 1};
        mesh = lfem::build_box(size, cells);
        surface.triangles = lfem::extract_boundary_triangles(mesh.tets.data(), mesh.tet_count());
        lfem::compute_surface_data(mesh.positions.data(), mesh.node_count(), surface);
        lfem::compute_node_triangles(mesh.node_count(), surface);
        lfem::compute_node_elements(mesh.tets.data(), mesh.tet_count(), 4, mesh.node_count(), surface);
        body.triangles = surface.triangles.data();
        body.triangle_count = surface.triangle_count();
        body.node_triangle_begin = surface.node_triangle_begin.data();
        body.node_triangles = surface.node_triangles.data();
        body.elements = mesh.tets.data();
        body.element_stride = 4;
        body.node_element_begin = surface.node_element_begin.data();
        body.node_elements = surface.node_elements.data();
        body.x = mesh.positions.data();
        body.x_start = mesh.positions.data();
        body.total_nodes = mesh.node_count();
        body.edge_length = surface.edge_length;
    }

    // The boundary triangle whose plane is z = height and whose box holds (x, y): a face of
    // the top (0.1) or the bottom (0).
    const uint32_t* face_at(double x, double y, double height) const {
        for (uint32_t t = 0; t < body.triangle_count; ++t) {
            const uint32_t* q = &surface.triangles[3 * t];
            bool level = true;
            double lo[2] = {1e9, 1e9}, hi[2] = {-1e9, -1e9};
            for (int v = 0; v < 3; ++v) {
                const double* p = &mesh.positions[3 * q[v]];
                level = level && p[2] == height;
                for (int k = 0; k < 2; ++k) lo[k] = std::min(lo[k], p[k]), hi[k] = std::max(hi[k], p[k]);
            }
            if (level && x >= lo[0] && x <= hi[0] && y >= lo[1] && y <= hi[1]) return q;
        }
        return nullptr;
    }
};

TEST(InsideBody, APointInsideTheTetsUnderAFaceIsInside) {
    Plate plate;
    lfem::ContactBody other;  // the node belongs to another body
    const uint32_t* top = plate.face_at(0.3, 0.2, 0.1);
    ASSERT_NE(top, nullptr);
    // 1 mm below the top face (1 % of the plate's thickness): inside, come in through the top.
    EXPECT_TRUE(lfem::inside_near(other, 0, plate.body, top, Vec3(0.3, 0.2, 0.099)));
    // The same point seen from the bottom face it lies above, 9.9 cm behind its plane: inside.
    const uint32_t* bottom = plate.face_at(0.3, 0.2, 0.0);
    ASSERT_NE(bottom, nullptr);
    EXPECT_TRUE(lfem::inside_near(other, 0, plate.body, bottom, Vec3(0.3, 0.2, 0.099)));
}

TEST(InsideBody, APointBehindAFacesPlaneButOutsideTheBodyIsNot) {
    Plate plate;
    lfem::ContactBody other;
    const uint32_t* bottom = plate.face_at(0.3, 0.2, 0.0);
    ASSERT_NE(bottom, nullptr);
    // 1 cm above the plate: behind the bottom face's plane by 11 cm, yet outside the plate.
    EXPECT_FALSE(lfem::inside_near(other, 0, plate.body, bottom, Vec3(0.3, 0.2, 0.11)));
    // On the top face itself, and 1e-5 m in (1e-4 of the thickness, within what a resting
    // contact leaves, 1e-3 of the tet's height): not counted as inside.
    EXPECT_FALSE(lfem::inside_near(other, 0, plate.body, bottom, Vec3(0.3, 0.2, 0.1)));
    EXPECT_FALSE(lfem::inside_near(other, 0, plate.body, bottom, Vec3(0.3, 0.2, 0.1 - 1e-5)));
}

TEST(InsideBody, ABodysOwnNodeIsNeverInsideItsOwnTets) {
    Plate plate;
    // A surface node of the plate itself, at its own position: it lies on its own tets (their
    // corner), which are left out; in no other tet.
    const uint32_t* top = plate.face_at(0.3, 0.2, 0.1);
    ASSERT_NE(top, nullptr);
    const uint32_t node = top[0];
    EXPECT_FALSE(lfem::inside_near(plate.body, node, plate.body, top, lfem::position(plate.mesh.positions.data(), node)));
}

}  // namespace
