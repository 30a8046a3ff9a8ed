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
        // Per-body arrays live here until the frame is written.
        std::vector<std::vector<double>> velocities, stresses;
        std::vector<VtkPiece> pieces;
        w.for_each_body([&](const Body& b, uint32_t index) {
            if (!b.has_mesh()) return;
            velocities.emplace_back(b.state.x.size());
            w.synchronized_velocities(b, velocities.back().data());
            stresses.emplace_back(b.ref.tet_count(), 0.0);
            if (b.is_deformable()) compute_von_mises(b, b.state, stresses.back().data());
            VtkPiece p;
            p.positions = b.state.x.data();
            p.node_count = b.ref.node_count();
            p.tets = b.ref.tets.data();
            p.tet_count = b.ref.tet_count();
            p.body_index = index;
            pieces.push_back(p);
        });
        // Pointers are taken only now: the vectors above no longer reallocate.
        for (std::size_t i = 0; i < pieces.size(); ++i) {
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
