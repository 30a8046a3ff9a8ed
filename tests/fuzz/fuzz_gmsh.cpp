// libFuzzer target: the Gmsh reader (lfem_mesh_load_gmsh) on arbitrary bytes. A file is either
// read into a mesh that passes lfem's checks (positive-volume tets of 4 or 10 nodes, indices
// in range) or refused with LFEM_IO_ERROR / LFEM_INVALID_MESH and a message; nothing else may
// happen.
#include <sys/mman.h>
#include <unistd.h>

#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <string>

#include "lfem.h"

namespace {

[[noreturn]] void broken(const char* what) {
    std::fprintf(stderr, "fuzz_gmsh: %s\n", what);
    std::abort();
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
    // The bytes as a file without touching the disk.
    const int fd = memfd_create("fuzz.msh", 0);
    if (fd < 0) return 0;
    if (size && write(fd, data, size) != ssize_t(size)) {
        close(fd);
        return 0;
    }
    const std::string path = "/proc/self/fd/" + std::to_string(fd);
    lfem_mesh* mesh = nullptr;
    const lfem_status s = lfem_mesh_load_gmsh(path.c_str(), &mesh);
    close(fd);
    if (s != LFEM_OK) {
        if (mesh) broken("a failed load returned a mesh");
        if (s != LFEM_IO_ERROR && s != LFEM_INVALID_MESH && s != LFEM_OUT_OF_MEMORY)
            broken(lfem_last_error());
        if (!*lfem_last_error()) broken("a failed load left no message");
        return 0;
    }
    const uint32_t n = lfem_mesh_get_node_count(mesh), t = lfem_mesh_get_tet_count(mesh);
    const uint32_t per_tet = lfem_mesh_get_nodes_per_tet(mesh);
    if (per_tet != 4 && per_tet != 10) broken("a loaded mesh has tets of neither 4 nor 10 nodes");
    const double* x = lfem_mesh_get_positions(mesh);
    const uint32_t* tets = lfem_mesh_get_tets(mesh);
    if (n == 0 || t == 0) broken("a loaded mesh is empty");
    for (uint32_t i = 0; i < 3 * n; ++i)
        if (!std::isfinite(x[i])) broken("a loaded position is not finite");
    for (uint32_t e = 0; e < t; ++e) {
        const uint32_t* v = &tets[std::size_t(per_tet) * e];
        for (uint32_t a = 0; a < per_tet; ++a)
            if (v[a] >= n) broken("a loaded tet index is out of range");
        double d[3][3];
        for (int a = 0; a < 3; ++a)
            for (int k = 0; k < 3; ++k) d[a][k] = x[3 * v[a + 1] + k] - x[3 * v[0] + k];
        const double det = d[0][0] * (d[1][1] * d[2][2] - d[1][2] * d[2][1]) -
                           d[0][1] * (d[1][0] * d[2][2] - d[1][2] * d[2][0]) +
                           d[0][2] * (d[1][0] * d[2][1] - d[1][1] * d[2][0]);
        if (!(det > 0.0)) broken("a loaded tet is not positively oriented");
    }
    // The mesh is good enough for a body.
    lfem_world_def wd = lfem_world_def_default();
    lfem_world* world = nullptr;
    if (lfem_world_create(&wd, &world) != LFEM_OK) broken("world");
    lfem_body_def bd = lfem_body_def_default();
    lfem_body body{};
    if (lfem_body_create(world, &bd, &body) != LFEM_OK) broken("body");
    const lfem_status added =
        (per_tet == 10 ? lfem_body_add_quadratic_mesh : lfem_body_add_mesh)(world, body, x, n, tets, t);
    if (added != LFEM_OK && added != LFEM_INVALID_MESH) broken(lfem_last_error());
    lfem_world_destroy(world);
    lfem_mesh_destroy(mesh);
    return 0;
}
