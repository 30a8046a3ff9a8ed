// C shim of the ParaView time series: gathers every body of a world into one frame. Without
// LFEM_WITH_IO the entry points check their arguments and answer LFEM_UNSUPPORTED.
#include <string>
#include <vector>

#include "api/handles.h"
#if LFEM_WITH_IO
#include "mesh/vtk_writer.h"
#endif

using namespace lfem;
using namespace lfem::api;

#if LFEM_WITH_IO
struct lfem_vtk_series {
    explicit lfem_vtk_series(std::string path) : series(std::move(path)) {}
    PvdSeries series;
};

namespace {

// One body's arrays in the caller's numbering (node_ordering.h), so that point and cell ids
// match the API's node and tet indices.
struct FrameArrays {
    std::vector<double> positions, velocities, stresses;
    std::vector<uint32_t> tets;
};

FrameArrays frame_arrays(const World& w, const Body& b) {
    const Numbering& numbering = b.numbering();
    const uint32_t n = b.node_count(), t = b.tet_count();
    FrameArrays out;
    std::vector<double> internal(3 * std::size_t(n));
    w.synchronized_velocities(b, internal.data());
    out.velocities.resize(internal.size());
    numbering.nodes_to_api(internal.data(), n, out.velocities.data());
    out.positions.resize(internal.size());
    numbering.nodes_to_api(b.positions(), n, out.positions.data());
    std::vector<double> stress(t, 0.0);
    w.von_mises_stress(b, stress.data());
    out.stresses.resize(t);
    numbering.tets_to_api(stress.data(), t, out.stresses.data());
    out.tets.resize(b.tets().size());
    numbering.tet_nodes_to_api(b.tets().data(), t, b.nodes_per_tet(), out.tets.data());
    return out;
}

void write_frame(PvdSeries& series, const World& w) {
    std::vector<FrameArrays> arrays;  // live until the frame is written
    std::vector<VtkPiece> pieces;
    w.bodies().for_each([&](const Body& b, uint32_t index) {
        if (!b.has_mesh()) return;
        arrays.push_back(frame_arrays(w, b));
        VtkPiece p;
        p.node_count = b.node_count();
        p.tet_count = b.tet_count();
        p.nodes_per_tet = b.nodes_per_tet();
        p.body_index = index;
        pieces.push_back(p);
    });
    // Pointers are taken only now: the vectors above no longer reallocate.
    for (std::size_t i = 0; i < pieces.size(); ++i) {
        pieces[i].positions = arrays[i].positions.data();
        pieces[i].tets = arrays[i].tets.data();
        pieces[i].velocities = arrays[i].velocities.data();
        pieces[i].von_mises = arrays[i].stresses.data();
    }
    write_vtu(series.next_frame_path(), pieces);
    series.add_frame(w.counters().time);
}

}  // namespace
#else
struct lfem_vtk_series {};  // never created in this build
#endif

extern "C" {

LFEM_API lfem_status lfem_vtk_series_create(const char* pvd_path, lfem_vtk_series** out) {
    return guard(__func__, [&] {
        require_pointer(pvd_path, "pvd_path");
        require_pointer(out, "out");
        require(pvd_path[0] != '\0', "pvd_path is empty");
#if LFEM_WITH_IO
        *out = new lfem_vtk_series(pvd_path);
#else
        unsupported("the VTK writer", "LFEM_WITH_IO");
#endif
    });
}

LFEM_API lfem_status lfem_vtk_series_write_frame(lfem_vtk_series* series, const lfem_world* world) {
    return guard(__func__, [&] {
        require_pointer(series, "series");
        const World& w = world_of(world);
#if LFEM_WITH_IO
        write_frame(series->series, w);
#else
        (void)w;
        unsupported("the VTK writer", "LFEM_WITH_IO");
#endif
    });
}

LFEM_API void lfem_vtk_series_destroy(lfem_vtk_series* series) { delete series; }

}  // extern "C"
