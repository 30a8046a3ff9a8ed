/* lfem.h compiles as strict C99 (-std=c99 -pedantic -Werror, see CMakeLists.txt), stands alone
 * (it is included first) and survives a second inclusion; and the library actually loaded has
 * the version the header announces. Exit status 0 on success. */
#include <lfem.h>
#include <lfem.h>

#include <stdio.h>
#include <string.h>

int main(void) {
    const uint32_t expected = ((uint32_t)LFEM_VERSION_MAJOR << 16) |
                              ((uint32_t)LFEM_VERSION_MINOR << 8) | (uint32_t)LFEM_VERSION_PATCH;
    const uint32_t loaded = lfem_version();
    const char* loaded_string = lfem_version_string();
    char expected_string[64];
    lfem_world_def world_def = lfem_world_def_default();
    lfem_body_def body_def = lfem_body_def_default();
    lfem_body null_body = {0, 0};
    lfem_status status = LFEM_INVALID_MESH;
    int failures = 0;

    snprintf(expected_string, sizeof expected_string, "%d.%d.%d", LFEM_VERSION_MAJOR,
             LFEM_VERSION_MINOR, LFEM_VERSION_PATCH);
    if (loaded != expected) {
        fprintf(stderr, "lfem_version() = 0x%06lx, header LFEM_VERSION_* = 0x%06lx\n",
                (unsigned long)loaded, (unsigned long)expected);
        ++failures;
    }
    if (loaded_string == NULL || strcmp(loaded_string, expected_string) != 0) {
        fprintf(stderr, "lfem_version_string() = \"%s\", header says \"%s\"\n",
                loaded_string ? loaded_string : "(null)", expected_string);
        ++failures;
    }
    if (lfem_status_string(status) == NULL || lfem_last_error() == NULL) {
        fprintf(stderr, "lfem_status_string / lfem_last_error returned NULL\n");
        ++failures;
    }
    if (lfem_body_is_valid(NULL, null_body) != 0) {
        fprintf(stderr, "lfem_body_is_valid(NULL, {0, 0}) != 0\n");
        ++failures;
    }
    (void)world_def;
    (void)body_def;
    if (failures == 0)
        printf("lfem.h is C99-clean; library version %s matches the header\n", loaded_string);
    return failures == 0 ? 0 : 1;
}
