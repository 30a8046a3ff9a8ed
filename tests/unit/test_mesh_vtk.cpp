// VTK output: a frame of a small box is read back (minimally: attributes and DataArrays) and
// the .pvd lists it with its time and a file name relative to the .pvd's folder; 10-node tets
// are quadratic cells.
#include <gtest/gtest.h>
#include <unistd.h>

#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

#include "common/error.h"
#include "mesh/mesh_builders.h"
#include "mesh/quadratic_mesh.h"
#include "mesh/vtk_writer.h"

namespace lfem {
namespace {

namespace fs = std::filesystem;

// A fresh folder per test, removed afterwards.
class VtkOutput : public ::testing::Test {
protected:
    void SetUp() override {
        dir_ = fs::temp_directory_path() /
               ("lfem_vtk_" + std::to_string(::getpid()) + "_" +
                ::testing::UnitTest::GetInstance()->current_test_info()->name());
        fs::remove_all(dir_);
        fs::create_directories(dir_);
    }
    void TearDown() override { fs::remove_all(dir_); }
    fs::path dir_;
};

std::string read_text(const fs::path& path) {
    std::ifstream in(path);
    std::stringstream s;
    s << in.rdbuf();
    return s.str();
}

std::size_t count_of(const std::string& text, const std::string& what) {
    std::size_t n = 0;
    for (std::size_t at = text.find(what); at != std::string::npos; at = text.find(what, at + 1))
        ++n;
    return n;
}

// The numbers inside the n-th <DataArray ... Name="name" ...> of the file.
std::vector<double> data_array(const std::string& text, const std::string& name, int n = 0) {
    std::size_t at = 0;
    for (int i = 0; i <= n; ++i) {
        at = text.find("Name=\"" + name + "\"", i == 0 ? 0 : at + 1);
        if (at == std::string::npos) return {};
    }
    const std::size_t begin = text.find('>', at) + 1;
    const std::size_t end = text.find("</DataArray>", begin);
    std::istringstream in(text.substr(begin, end - begin));
    std::vector<double> values;
    for (double v; in >> v;) values.push_back(v);
    return values;
}

// The numbers of the n-th DataArray without a Name (the Points).
std::vector<double> points_array(const std::string& text) {
    const std::size_t points = text.find("<Points>");
    const std::size_t begin = text.find('>', text.find("<DataArray", points)) + 1;
    const std::size_t end = text.find("</DataArray>", begin);
    std::istringstream in(text.substr(begin, end - begin));
    std::vector<double> values;
    for (double v; in >> v;) values.push_back(v);
    return values;
}

TetMesh small_box() {
    const double size[3] = {0.1, 0.2, 0.3};
    const uint32_t cells[3] = {2, 1, 1};
    return build_box(size, cells);
}

TEST_F(VtkOutput, FrameAndCollection) {
    const TetMesh m = small_box();
    ASSERT_EQ(m.node_count(), 12u);
    ASSERT_EQ(m.tet_count(), 12u);
    std::vector<double> velocity(m.positions.size()), stress(m.tet_count());
    for (std::size_t i = 0; i < velocity.size(); ++i) velocity[i] = 0.1 * double(i) - 1.0 / 3.0;
    for (std::size_t t = 0; t < stress.size(); ++t) stress[t] = 1e6 * double(t) + 0.5;

    PvdSeries series((dir_ / "run.pvd").string());
    EXPECT_EQ(series.frame_count(), 0u);
    EXPECT_EQ(series.next_frame_path(), (dir_ / "run_000000.vtu").string());

    VtkPiece piece;
    piece.positions = m.positions.data();
    piece.node_count = m.node_count();
    piece.tets = m.tets.data();
    piece.tet_count = m.tet_count();
    piece.velocities = velocity.data();
    piece.von_mises = stress.data();
    piece.body_index = 3;
    write_vtu(series.next_frame_path(), {piece});
    series.add_frame(0.25);
    EXPECT_EQ(series.frame_count(), 1u);

    const std::string vtu = read_text(dir_ / "run_000000.vtu");
    EXPECT_NE(vtu.find("<VTKFile type=\"UnstructuredGrid\" version=\"0.1\""), std::string::npos);
    EXPECT_NE(vtu.find("NumberOfPoints=\"12\" NumberOfCells=\"12\""), std::string::npos);
    EXPECT_EQ(count_of(vtu, "<Piece"), 1u);
    EXPECT_EQ(points_array(vtu), m.positions) << "positions survive the round trip exactly";
    EXPECT_EQ(data_array(vtu, "velocity"), velocity);
    EXPECT_EQ(data_array(vtu, "von_mises"), stress);
    EXPECT_EQ(data_array(vtu, "body"), std::vector<double>(12, 3.0));
    const std::vector<double> connectivity = data_array(vtu, "connectivity");
    ASSERT_EQ(connectivity.size(), 48u);
    for (std::size_t i = 0; i < 48; ++i) EXPECT_EQ(connectivity[i], double(m.tets[i]));
    const std::vector<double> offsets = data_array(vtu, "offsets");
    ASSERT_EQ(offsets.size(), 12u);
    for (std::size_t t = 0; t < 12; ++t) EXPECT_EQ(offsets[t], 4.0 * double(t + 1));
    EXPECT_EQ(data_array(vtu, "types"), std::vector<double>(12, 10.0));  // VTK_TETRA

    std::string pvd = read_text(dir_ / "run.pvd");
    EXPECT_NE(pvd.find("<VTKFile type=\"Collection\" version=\"0.1\""), std::string::npos);
    EXPECT_NE(pvd.find("<DataSet timestep=\"0.25\" part=\"0\" file=\"run_000000.vtu\"/>"),
              std::string::npos)
        << pvd;
    EXPECT_FALSE(fs::exists(dir_ / "run.pvd.tmp"));

    EXPECT_EQ(series.next_frame_path(), (dir_ / "run_000001.vtu").string());
    write_vtu(series.next_frame_path(), {piece});
    series.add_frame(0.5);
    pvd = read_text(dir_ / "run.pvd");
    EXPECT_EQ(count_of(pvd, "<DataSet"), 2u);
    const std::size_t first = pvd.find("file=\"run_000000.vtu\"");
    const std::size_t second =
        pvd.find("<DataSet timestep=\"0.5\" part=\"0\" file=\"run_000001.vtu\"/>");
    ASSERT_NE(second, std::string::npos) << pvd;
    EXPECT_LT(first, second);
    EXPECT_NE(pvd.find("</Collection>\n</VTKFile>"), std::string::npos);
}

TEST_F(VtkOutput, PiecesShareTheirArrays) {
    const TetMesh m = small_box();
    std::vector<double> velocity(m.positions.size(), 1.5);
    VtkPiece moving{m.positions.data(),
                    m.node_count(),
                    m.tets.data(),
                    m.tet_count(),
                    velocity.data(),
                    nullptr,
                    0};
    VtkPiece still{
        m.positions.data(), m.node_count(), m.tets.data(), m.tet_count(), nullptr, nullptr, 1};
    const fs::path path = dir_ / "two.vtu";
    write_vtu(path.string(), {moving, still});
    const std::string vtu = read_text(path);
    EXPECT_EQ(count_of(vtu, "<Piece NumberOfPoints=\"12\" NumberOfCells=\"12\">"), 2u);
    EXPECT_EQ(data_array(vtu, "velocity", 0), velocity);
    EXPECT_EQ(data_array(vtu, "velocity", 1), std::vector<double>(velocity.size(), 0.0));
    EXPECT_EQ(data_array(vtu, "body", 1), std::vector<double>(12, 1.0));
    EXPECT_EQ(count_of(vtu, "von_mises"), 0u);
}

TEST_F(VtkOutput, UnwritablePlacesAreIoErrors) {
    const std::string missing = (dir_ / "no_such_folder" / "frame.vtu").string();
    try {
        write_vtu(missing, {});
        ADD_FAILURE() << "no error";
    } catch (const Error& e) {
        EXPECT_EQ(e.status(), Status::io_error);
        EXPECT_NE(std::string(e.what()).find(missing), std::string::npos) << e.what();
        EXPECT_NE(std::string(e.what()).find("No such file or directory"), std::string::npos);
    }
    PvdSeries series((dir_ / "no_such_folder" / "run.pvd").string());
    try {
        series.add_frame(0.0);
        ADD_FAILURE() << "no error";
    } catch (const Error& e) {
        EXPECT_EQ(e.status(), Status::io_error) << e.what();
        EXPECT_NE(std::string(e.what()).find("run.pvd"), std::string::npos) << e.what();
    }
}

TEST_F(VtkOutput, FailedFrameChangesNothing) {
    const fs::path folder = dir_ / "gone";
    fs::create_directories(folder);
    PvdSeries series((folder / "run.pvd").string());
    series.add_frame(1.0);
    fs::remove_all(folder);
    EXPECT_THROW(series.add_frame(2.0), Error);
    EXPECT_EQ(series.frame_count(), 1u);
    EXPECT_EQ(series.next_frame_path(), (folder / "run_000001.vtu").string());
    // Once the folder is back, the series carries on with the right frames.
    fs::create_directories(folder);
    series.add_frame(3.0);
    const std::string pvd = read_text(folder / "run.pvd");
    EXPECT_EQ(count_of(pvd, "<DataSet"), 2u);
    EXPECT_NE(pvd.find("timestep=\"3\" part=\"0\" file=\"run_000001.vtu\""), std::string::npos)
        << pvd;
}

// 10-node tets go out as VTK_QUADRATIC_TETRA (24), ten points each in lfem's node order, which
// is VTK's (common/quadratic_tet_nodes.h).
TEST_F(VtkOutput, QuadraticTetsAreCellType24) {
    const TetMesh m = make_quadratic(small_box());
    VtkPiece piece;
    piece.positions = m.positions.data();
    piece.node_count = m.node_count();
    piece.tets = m.tets.data();
    piece.tet_count = m.tet_count();
    piece.nodes_per_tet = 10;
    const fs::path path = dir_ / "quadratic.vtu";
    write_vtu(path.string(), {piece});
    const std::string vtu = read_text(path);
    const std::vector<double> connectivity = data_array(vtu, "connectivity");
    ASSERT_EQ(connectivity.size(), 10u * m.tet_count());
    for (std::size_t i = 0; i < connectivity.size(); ++i) EXPECT_EQ(connectivity[i], double(m.tets[i]));
    const std::vector<double> offsets = data_array(vtu, "offsets");
    ASSERT_EQ(offsets.size(), m.tet_count());
    for (std::size_t t = 0; t < offsets.size(); ++t) EXPECT_EQ(offsets[t], 10.0 * double(t + 1));
    EXPECT_EQ(data_array(vtu, "types"), std::vector<double>(m.tet_count(), 24.0));
    EXPECT_EQ(points_array(vtu), m.positions);
}

}  // namespace
}  // namespace lfem
