// VTK XML writers: .vtu frames (ASCII UnstructuredGrid) and the .pvd collection.
//
// Numbers are printed with %.17g so a frame read back gives the same doubles. The .pvd is
// rewritten whole after every frame through a temporary file and a rename: a reader (or a
// crash) never sees a half-written collection.
#include "mesh/vtk_writer.h"

#include <cerrno>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <string>
#include <utility>

#include "common/error.h"

namespace lfem {
namespace {

constexpr int kVtkTetra = 10;           // VTK cell type of the linear tetrahedron
constexpr int kVtkQuadraticTetra = 24;  // and of the 10-node one

[[noreturn]] void io_error(const std::string& path, const char* action, int error_number) {
    throw Error(Status::io_error, "cannot " + std::string(action) + " '" + path +
                                   "': " + std::strerror(error_number));
}

// A FILE* that is closed on every path; close() reports write errors (disk full shows up at
// the final flush).
class OutputFile {
public:
    explicit OutputFile(std::string path) : path_(std::move(path)) {
        file_ = std::fopen(path_.c_str(), "wb");
        if (!file_) io_error(path_, "open for writing", errno);
    }
    ~OutputFile() {
        if (file_) std::fclose(file_);
    }
    OutputFile(const OutputFile&) = delete;
    OutputFile& operator=(const OutputFile&) = delete;

    template <class... Args>
    void print(const char* format, Args... args) {
        if (std::fprintf(file_, format, args...) < 0) io_error(path_, "write", errno);
    }
    void text(const char* s) {
        if (std::fputs(s, file_) == EOF) io_error(path_, "write", errno);
    }
    void close() {
        const bool failed = std::ferror(file_) != 0;
        const int saved = errno;
        const int closed = std::fclose(file_);
        file_ = nullptr;
        if (failed) io_error(path_, "write", saved ? saved : EIO);
        if (closed != 0) io_error(path_, "write", errno);
    }

private:
    std::string path_;
    std::FILE* file_ = nullptr;
};

// Writes `count` rows of `width` doubles; a missing array (nullptr) is written as zeros so
// that every piece of a frame carries the same arrays, which ParaView expects.
void write_doubles(OutputFile& out, const double* values, std::size_t count, int width) {
    for (std::size_t row = 0; row < count; ++row) {
        for (int c = 0; c < width; ++c)
            out.print(c == 0 ? "          %.17g" : " %.17g",
                      values ? values[width * row + c] : 0.0);
        out.text("\n");
    }
}

void write_piece(OutputFile& out, const VtkPiece& p, bool with_velocity, bool with_stress) {
    out.print("    <Piece NumberOfPoints=\"%u\" NumberOfCells=\"%u\">\n", unsigned(p.node_count),
              unsigned(p.tet_count));
    if (with_velocity) {
        out.text("      <PointData Vectors=\"velocity\">\n");
        out.text(
            "        <DataArray type=\"Float64\" Name=\"velocity\" NumberOfComponents=\"3\" "
            "format=\"ascii\">\n");
        write_doubles(out, p.velocities, p.node_count, 3);
        out.text("        </DataArray>\n      </PointData>\n");
    }
    out.text(with_stress ? "      <CellData Scalars=\"von_mises\">\n" : "      <CellData>\n");
    if (with_stress) {
        out.text("        <DataArray type=\"Float64\" Name=\"von_mises\" format=\"ascii\">\n");
        write_doubles(out, p.von_mises, p.tet_count, 1);
        out.text("        </DataArray>\n");
    }
    out.text("        <DataArray type=\"Int32\" Name=\"body\" format=\"ascii\">\n");
    for (uint32_t t = 0; t < p.tet_count; ++t) out.print("          %d\n", int32_t(p.body_index));
    out.text("        </DataArray>\n      </CellData>\n");

    out.text(
        "      <Points>\n        <DataArray type=\"Float64\" NumberOfComponents=\"3\" "
        "format=\"ascii\">\n");
    write_doubles(out, p.positions, p.node_count, 3);
    out.text("        </DataArray>\n      </Points>\n");

    out.text(
        "      <Cells>\n        <DataArray type=\"Int64\" Name=\"connectivity\" "
        "format=\"ascii\">\n");
    for (uint32_t t = 0; t < p.tet_count; ++t) {
        const uint32_t* tet = p.tets + std::size_t(p.nodes_per_tet) * t;
        out.text("         ");
        for (uint32_t a = 0; a < p.nodes_per_tet; ++a) out.print(" %u", unsigned(tet[a]));
        out.text("\n");
    }
    out.text("        </DataArray>\n");
    out.text("        <DataArray type=\"Int64\" Name=\"offsets\" format=\"ascii\">\n");
    for (uint32_t t = 0; t < p.tet_count; ++t)
        out.print("          %llu\n", (unsigned long long)(p.nodes_per_tet * (t + 1ull)));
    out.text("        </DataArray>\n");
    out.text("        <DataArray type=\"UInt8\" Name=\"types\" format=\"ascii\">\n");
    const int type = p.nodes_per_tet == 10 ? kVtkQuadraticTetra : kVtkTetra;
    for (uint32_t t = 0; t < p.tet_count; ++t) out.print("          %d\n", type);
    out.text("        </DataArray>\n      </Cells>\n    </Piece>\n");
}

// Pieces come from the library itself; a broken one is a bug, caught before the file is
// touched so a bad call leaves no half-written frame.
void check_piece(const VtkPiece& p, std::size_t index) {
    const std::string name = "vtk piece " + std::to_string(index);
    if ((p.node_count > 0 && !p.positions) || (p.tet_count > 0 && !p.tets))
        throw Error(Status::invalid_argument, name + " lacks its positions or tets");
    if (p.nodes_per_tet != 4 && p.nodes_per_tet != 10)
        throw Error(Status::invalid_argument, name + " has tets of " + std::to_string(p.nodes_per_tet) + " nodes");
    for (std::size_t i = 0; i < std::size_t(p.nodes_per_tet) * p.tet_count; ++i)
        if (p.tets[i] >= p.node_count)
            throw Error(Status::invalid_argument, name + " has a tet node index out of range");
}

// Escapes a file name for an XML attribute value.
std::string xml_attribute(const std::string& s) {
    std::string out;
    for (char c : s) {
        switch (c) {
            case '&': out += "&amp;"; break;
            case '<': out += "&lt;"; break;
            case '>': out += "&gt;"; break;
            case '"': out += "&quot;"; break;
            case '\'': out += "&apos;"; break;
            default: out += c;
        }
    }
    return out;
}

// "_000123.vtu": the frame part of a frame's file name.
std::string frame_suffix(std::size_t frame) {
    char suffix[32];
    std::snprintf(suffix, sizeof suffix, "_%06zu.vtu", frame);
    return suffix;
}

// Writes the collection file listing frames 0..times.size()-1, through a temporary file and
// a rename so the .pvd on disk is always complete.
void write_collection(const std::string& pvd_path, const std::vector<double>& times) {
    const std::string temporary = pvd_path + ".tmp";
    OutputFile out(temporary);
    try {
        out.text(
            "<?xml version=\"1.0\"?>\n"
            "<VTKFile type=\"Collection\" version=\"0.1\" byte_order=\"LittleEndian\">\n"
            "  <Collection>\n");
        const std::string stem = std::filesystem::path(pvd_path).stem().string();
        for (std::size_t f = 0; f < times.size(); ++f)
            out.print("    <DataSet timestep=\"%.17g\" part=\"0\" file=\"%s\"/>\n", times[f],
                      xml_attribute(stem + frame_suffix(f)).c_str());
        out.text("  </Collection>\n</VTKFile>\n");
        out.close();
    } catch (...) {
        std::remove(temporary.c_str());  // no stray half-written file
        throw;
    }
    if (std::rename(temporary.c_str(), pvd_path.c_str()) != 0) {
        const int saved = errno;
        std::remove(temporary.c_str());
        io_error(pvd_path, "replace", saved);
    }
}

}  // namespace

void write_vtu(const std::string& path, const std::vector<VtkPiece>& pieces) {
    bool with_velocity = false, with_stress = false;
    for (std::size_t i = 0; i < pieces.size(); ++i) {
        check_piece(pieces[i], i);
        with_velocity = with_velocity || pieces[i].velocities;
        with_stress = with_stress || pieces[i].von_mises;
    }
    OutputFile out(path);
    try {
        out.text(
            "<?xml version=\"1.0\"?>\n"
            "<VTKFile type=\"UnstructuredGrid\" version=\"0.1\" byte_order=\"LittleEndian\">\n"
            "  <UnstructuredGrid>\n");
        if (pieces.empty()) {
            // A frame without bodies is still a valid grid: one empty piece.
            write_piece(out, VtkPiece{}, false, false);
        }
        for (const VtkPiece& piece : pieces) write_piece(out, piece, with_velocity, with_stress);
        out.text("  </UnstructuredGrid>\n</VTKFile>\n");
        out.close();
    } catch (...) {
        std::remove(path.c_str());  // a truncated frame is worse than none
        throw;
    }
}

// Nothing is written yet: a bad folder shows up as an IO error of the first frame (the C shim
// and its tests rely on creation succeeding).
PvdSeries::PvdSeries(std::string pvd_path) : pvd_path_(std::move(pvd_path)) {}

std::string PvdSeries::next_frame_path() const {
    const std::filesystem::path pvd(pvd_path_);
    return (pvd.parent_path() / (pvd.stem().string() + frame_suffix(times_.size()))).string();
}

void PvdSeries::add_frame(double time) {
    if (!std::isfinite(time)) throw Error(Status::invalid_argument, "frame time is not finite");
    times_.push_back(time);
    try {
        write_collection(pvd_path_, times_);
    } catch (...) {
        times_.pop_back();  // a failed call leaves the series as it was
        throw;
    }
}

}  // namespace lfem
