// VTK XML output that ParaView opens: one .vtu unstructured grid per frame and a .pvd
// collection that lists the frames with their times.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

namespace lfem {

// One body's worth of cells in a frame. Pointers are borrowed for the duration of the call.
struct VtkPiece {
    const double* positions = nullptr;   // 3 per node
    uint32_t node_count = 0;
    const uint32_t* tets = nullptr;      // nodes_per_tet per tet
    uint32_t tet_count = 0;
    const double* velocities = nullptr;  // 3 per node, nullable
    const double* von_mises = nullptr;   // 1 per tet, nullable
    uint32_t body_index = 0;             // written as cell data "body"
    uint32_t nodes_per_tet = 4;          // 4 (VTK_TETRA) or 10 (VTK_QUADRATIC_TETRA, whose node
                                         // order is lfem's, common/quadratic_tet_nodes.h)
};

// Writes one .vtu file (ASCII, one <Piece> per body). Throws Error(Status::io_error) when the
// file cannot be written.
void write_vtu(const std::string& path, const std::vector<VtkPiece>& pieces);

// The .pvd collection of a time series.
class PvdSeries {
public:
    explicit PvdSeries(std::string pvd_path);
    // The .vtu path for the next frame, beside the .pvd: <stem>_<000123>.vtu
    std::string next_frame_path() const;
    // Record that the frame at next_frame_path() was written at `time` and rewrite the .pvd
    // (so the collection is valid after every frame). Throws Error(Status::io_error).
    void add_frame(double time);
    uint32_t frame_count() const { return uint32_t(times_.size()); }

private:
    std::string pvd_path_;
    std::vector<double> times_;
};

}  // namespace lfem
