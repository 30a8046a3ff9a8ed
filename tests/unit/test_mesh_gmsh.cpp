// Gmsh reader: the same hand-written cube in formats 2.2 and 4.1 gives the same mesh, and
// every malformed file is refused with Status::io_error naming the offending line.
#include <gtest/gtest.h>
#include <unistd.h>

#include <cstdio>
#include <filesystem>
#include <fstream>
#include <string>

#include "common/error.h"
#include "mesh/gmsh_reader.h"
#include "mesh/mesh_check.h"
#include "test_mesh_helpers.h"

namespace lfem {
namespace {

std::string data(const std::string& name) { return std::string(LFEM_TEST_DATA_DIR) + "/" + name; }

// The cube files (tests/data/cube_v22.msh, cube_v41.msh): corners tagged 10..80, node 99 and
// node 5 unused by tets, tets listed as below (tags), the last one negatively oriented.
void expect_cube(const TetMesh& m) {
    ASSERT_EQ(m.node_count(), 8u);
    ASSERT_EQ(m.tet_count(), 5u);
    EXPECT_NO_THROW(
        check_tet_mesh(m.positions.data(), m.node_count(), m.tets.data(), m.tet_count()));
    EXPECT_NEAR(test::mesh_volume(m), 1.0, 1e-15);
    // Dense numbering follows the tags: 10 -> 0, 20 -> 1, ... 80 -> 7.
    const double corners[8][3] = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {1, 1, 0},
                                  {0, 0, 1}, {1, 0, 1}, {0, 1, 1}, {1, 1, 1}};
    for (uint32_t n = 0; n < 8; ++n)
        for (int i = 0; i < 3; ++i) EXPECT_EQ(m.positions[3 * n + i], corners[n][i]);
    // File tets (20 40 10 60) (30 10 40 70) (50 10 70 60) (80 40 60 70) are positive and kept
    // as listed; (10 40 60 70) is negative and gets its last two nodes swapped.
    const std::vector<uint32_t> expected = {1, 3, 0, 5, 2, 0, 3, 6, 4, 0,
                                            6, 5, 7, 3, 5, 6, 0, 3, 6, 5};
    EXPECT_EQ(m.tets, expected);
}

TEST(GmshReader, Format22) { expect_cube(read_gmsh(data("cube_v22.msh"))); }

TEST(GmshReader, Format41) { expect_cube(read_gmsh(data("cube_v41.msh"))); }

TEST(GmshReader, BothFormatsGiveTheSameMesh) {
    const TetMesh a = read_gmsh(data("cube_v22.msh"));
    const TetMesh b = read_gmsh(data("cube_v41.msh"));
    EXPECT_EQ(a.positions, b.positions);
    EXPECT_EQ(a.tets, b.tets);
}

TEST(GmshReader, WindowsLineEndings) {
    const std::filesystem::path path = std::filesystem::temp_directory_path() /
                                       ("lfem_crlf_" + std::to_string(::getpid()) + ".msh");
    {
        std::ifstream in(data("cube_v41.msh"));
        std::ofstream out(path, std::ios::binary);
        std::string line;
        while (std::getline(in, line)) out << line << "\r\n";
    }
    const TetMesh m = read_gmsh(path.string());
    std::filesystem::remove(path);
    expect_cube(m);
}

struct BadFile {
    const char* name;
    int line;
    const char* says;  // a fragment of the message
};

TEST(GmshReader, MalformedFilesNameTheLine) {
    const BadFile cases[] = {
        {"bad_binary.msh", 2, "binary"},
        {"bad_version.msh", 2, "unsupported .msh version 3.0"},
        {"bad_truncated_nodes.msh", 9, "truncated $Nodes section: expected 5 nodes, found 3"},
        {"bad_non_numeric.msh", 7, "'abc' is not a number"},
        {"bad_unknown_tag.msh", 14, "unknown node tag 7"},
        {"bad_zero_volume.msh", 15, "zero volume"},
        {"bad_no_tets.msh", 13, "no tetrahedra"},
        {"bad_eof.msh", 13, "unexpected end of file in $Elements"},
        {"bad_v41_node_total.msh", 14, "announces 5 nodes but its blocks hold 4"},
        {"bad_huge_count.msh", 7, "truncated $Nodes section"},
        {"bad_v41_huge_block.msh", 8, "expected 1 field in a node tag, found 3"},
        {"bad_duplicate_tag.msh", 10, "node tag 2 is defined twice (first on line 7)"},
        {"bad_missing_end.msh", 7, "expected $EndNodes"},
        {"bad_nan.msh", 6, "not finite"},
        {"bad_repeated_node.msh", 13, "repeats node tag 2"},
        {"bad_no_format.msh", 1, "$Nodes before $MeshFormat"},
        {"bad_v41_short_tet.msh", 19, "expected 5 fields"},
        {"bad_unclosed_section.msh", 5, "unexpected end of file in $Comments"},
        {"bad_empty.msh", 0, "no $MeshFormat"},
    };
    for (const BadFile& c : cases) {
        SCOPED_TRACE(c.name);
        const std::string path = data(c.name);
        try {
            read_gmsh(path);
            ADD_FAILURE() << "no error";
        } catch (const Error& e) {
            const std::string message = e.what();
            EXPECT_EQ(e.status(), Status::io_error);
            EXPECT_EQ(message.rfind(path + ":" + std::to_string(c.line) + ": ", 0), 0u) << message;
            EXPECT_NE(message.find(c.says), std::string::npos) << message;
        }
    }
}

TEST(GmshReader, MissingFile) {
    const std::string path = data("no_such_file.msh");
    try {
        read_gmsh(path);
        ADD_FAILURE() << "no error";
    } catch (const Error& e) {
        EXPECT_EQ(e.status(), Status::io_error);
        EXPECT_NE(std::string(e.what()).find(path), std::string::npos) << e.what();
        EXPECT_NE(std::string(e.what()).find("No such file"), std::string::npos) << e.what();
    }
}

TEST(GmshReader, DirectoryIsNotAFile) {
    try {
        read_gmsh(LFEM_TEST_DATA_DIR);
        ADD_FAILURE() << "no error";
    } catch (const Error& e) {
        EXPECT_EQ(e.status(), Status::io_error) << e.what();
    }
}

}  // namespace
}  // namespace lfem
