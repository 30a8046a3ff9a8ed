// lfem.h compiles as strict C++11 (-std=c++11 -pedantic -Werror, see CMakeLists.txt), and its
// declarations have C linkage: these calls link only if the header wraps them in extern "C".
// lfem_types.h, which lfem.h includes, stands alone (it is included first here; header_c99.c
// includes lfem.h first), and both survive a second inclusion. Exit status 0 on success.
#include <lfem_types.h>
#include <lfem.h>
#include <lfem.h>

#include <cstdio>
#include <cstring>
#include <type_traits>

static_assert(std::is_standard_layout<lfem_world_def>::value, "lfem_world_def is plain C data");
static_assert(std::is_trivially_copyable<lfem_world_def>::value, "lfem_world_def is plain C data");
static_assert(std::is_standard_layout<lfem_body_def>::value, "lfem_body_def is plain C data");
static_assert(std::is_standard_layout<lfem_world_stats>::value, "lfem_world_stats is plain C data");
static_assert(std::is_standard_layout<lfem_body>::value, "lfem_body is plain C data");
static_assert(sizeof(lfem_status) == 4, "lfem_status is 32 bits");
static_assert(sizeof(lfem_body_type) == 4 && sizeof(lfem_model) == 4, "enums are 32 bits");

int main() {
    int failures = 0;
    const lfem_world_def world_def = lfem_world_def_default();
    const lfem_body_def body_def = lfem_body_def_default();
    const lfem_body null_body = {0, 0};
    lfem_world* world = nullptr;

    if (lfem_version() != ((uint32_t(LFEM_VERSION_MAJOR) << 16) |
                           (uint32_t(LFEM_VERSION_MINOR) << 8) | uint32_t(LFEM_VERSION_PATCH))) {
        std::fprintf(stderr, "lfem_version() does not match LFEM_VERSION_*\n");
        ++failures;
    }
    if (std::strcmp(lfem_status_string(LFEM_OK), lfem_status_string(LFEM_INVALID_ARGUMENT)) == 0) {
        std::fprintf(stderr, "lfem_status_string gives the same text for two statuses\n");
        ++failures;
    }
    if (lfem_body_is_valid(nullptr, null_body) != 0) {
        std::fprintf(stderr, "lfem_body_is_valid(nullptr, {0, 0}) != 0\n");
        ++failures;
    }
    if (lfem_world_create(&world_def, &world) != LFEM_OK || world == nullptr) {
        std::fprintf(stderr, "lfem_world_create failed: %s\n", lfem_last_error());
        ++failures;
    }
    lfem_world_destroy(world);
    lfem_world_destroy(nullptr);
    lfem_mesh_destroy(nullptr);
    lfem_vtk_series_destroy(nullptr);
    (void)body_def;
    if (failures == 0) std::printf("lfem.h is C++11-clean with C linkage\n");
    return failures == 0 ? 0 : 1;
}
