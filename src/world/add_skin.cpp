// Skins: a render mesh bound to a body's tets (skin/skin.h). Bound once, in the body's rest
// frame, to the internal node numbering, which later meshes added to the body leave as it is:
// the binding stays valid. A skin is the body's data (checkpoints keep it) that no step reads.
#include "common/error.h"
#include "mesh/mesh_check.h"
#include "world/world.h"

namespace lfem {

uint32_t World::add_skin(BodyHandle handle, const double* positions, uint32_t vertex_count,
                         const uint32_t* triangles, uint32_t triangle_count) {
    Body& body = bodies_.get(handle);
    check_triangles(triangles, triangle_count, vertex_count, nullptr, "vertex", "vertices");  // (render triangles may be slivers)
    if (body.ref.tet_count() == 0)
        throw Error(Status::invalid_argument, "a skin is bound to tets: give the body a tet mesh first "
                                           "(lfem_body_add_mesh)");
    SkinTets tets;
    tets.X = body.ref.X;
    tets.tets = body.ref.tets;
    tets.nodes_per_tet = body.ref.nodes_per_tet;
    // A vertex counts as just outside within one mean boundary edge of the nearest tet: the
    // gap a render mesh drawn a little proud of a coarse simulation mesh leaves.
    Skin skin = bind_skin(tets, positions, vertex_count, triangles, triangle_count, body.ref.surface.edge_length);
    body.skins.reserve(body.skins.size() + 1);  // the only allocation: before any change
    body.skins.push_back(std::move(skin));
    return uint32_t(body.skins.size() - 1);
}

}  // namespace lfem
