// C shim of the ParaView time series: gathers every body of a world into one frame. Without
// LFEM_WITH_IO the entry points check their arguments and answer LFEM_UNSUPPORTED.
#include <string>
#include <vector>

#include "api/handles.h"
#include "fem/internal_forces.h"
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
#else
struct lfem_vtk_series {};  // never created in this build

extern "C" {

LFEM_API lfem_status lfem_vtk_series_create(const char* pvd_path, lfem_vtk_series** out) {
    return guard(__func__, [&] {
        require_pointer(pvd_path, "pvd_path");
        require_pointer(out, "out");
        require(pvd_path[0] != '\0', "pvd_path is empty");
        unsupported("the VTK writer", "LFEM_WITH_IO");
    });
}

LFEM_API lfem_status lfem_vtk_series_write_frame(lfem_vtk_series* series, const lfem_world* world) {
    return guard(__func__, [&] {
        require_pointer(series, "series");
        world_of(world);
        unsupported("the VTK writer", "LFEM_WITH_IO");
    });
}

LFEM_API void lfem_vtk_series_destroy(lfem_vtk_series* series) { delete series; }

}  // extern "C"
#endif

#if LFEM_WITH_IO
extern "C" {

LFEM_API lfem_status lfem_vtk_series_create(const char* pvd_path, lfem_vtk_series** out) {
    return guard(__func__, [&] {
        require_pointer(pvd_path, "pvd_path");
        require_pointer(out, "out");
        require(pvd_path[0] != '\0', "pvd_path is empty");
        *out = new lfem_vtk_series(pvd_path);
    });
}

LFEM_API lfem_status lfem_vtk_series_write_frame(lfem_vtk_series* series, const lfem_world* world) {
    return guard(__func__, [&] {
        require_pointer(series, "series");
        const World& w = world_of(world);
        // Per-body arrays live here until the frame is written, in the caller's numbering
        // (node_ordering.h), so that point and cell ids match the API's node and tet indices.
        std::vector<std::vector<double>> positions, velocities, stresses;
        std::vector<std::vector<uint32_t>> tets;
        std::vector<VtkPiece> pieces;
        w.for_each_body([&](const Body& b, uint32_t index) {
            if (!b.has_mesh()) return;
            const Numbering& numbering = b.ref.numbering;
            const uint32_t n = b.ref.node_count(), t = b.ref.tet_count();
            std::vector<double> internal(b.state.x.size());
            w.synchronized_velocities(b, internal.data());
            velocities.emplace_back(internal.size());
            numbering.nodes_to_api(internal.data(), n, velocities.back().data());
            positions.emplace_back(internal.size());
            numbering.nodes_to_api(b.state.x.data(), n, positions.back().data());
            std::vector<double> stress(t, 0.0);
            if (b.is_deformable()) compute_von_mises(b, b.state, stress.data());
            stresses.emplace_back(t);
            numbering.tets_to_api(stress.data(), t, stresses.back().data());
            tets.emplace_back(b.ref.tets.size());
            numbering.tet_nodes_to_api(b.ref.tets.data(), t, tets.back().data());
            VtkPiece p;
            p.node_count = n;
            p.tet_count = t;
            p.body_index = index;
            pieces.push_back(p);
        });
        // Pointers are taken only now: the vectors above no longer reallocate.
        for (std::size_t i = 0; i < pieces.size(); ++i) {
            pieces[i].positions = positions[i].data();
            pieces[i].tets = tets[i].data();
            pieces[i].velocities = velocities[i].data();
            pieces[i].von_mises = stresses[i].data();
        }
        write_vtu(series->series.next_frame_path(), pieces);
        series->series.add_frame(w.counters().time);
    });
}

LFEM_API void lfem_vtk_series_destroy(lfem_vtk_series* series) { delete series; }

}  // extern "C"
#endif
