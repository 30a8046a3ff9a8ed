# Cross-build of lfem for ARM64 (AArch64) Linux with Debian's cross compiler (package
# g++-aarch64-linux-gnu), against Debian's arm64 packages through multiarch
# (dpkg --add-architecture arm64; libccd-dev:arm64). From the repository's root:
#
#   cmake -S . -B build-arm64 -DCMAKE_TOOLCHAIN_FILE=src/cmake/toolchain-aarch64-linux-gnu.cmake \
#         -DCMAKE_BUILD_TYPE=Release
#   cmake --build build-arm64 -j2 --target lfem
#
# gives build-arm64/liblfem.so for aarch64. Without libccd:arm64, add -DLFEM_WITH_CCD=OFF.
# On an x86-64 host, run its programs with
#
#   qemu-aarch64 -L /usr/aarch64-linux-gnu -E LD_LIBRARY_PATH=/usr/aarch64-linux-gnu/lib PROGRAM
#
# -L gives the cross toolchain's loader (libc6-arm64-cross); LD_LIBRARY_PATH keeps its libc
# with it: the loader would otherwise take multiarch's libc6:arm64, another build of glibc,
# and hang in the first pthread_create.
set(CMAKE_SYSTEM_NAME Linux)
set(CMAKE_SYSTEM_PROCESSOR aarch64)
set(LFEM_TRIPLE aarch64-linux-gnu)
set(CMAKE_C_COMPILER ${LFEM_TRIPLE}-gcc)
set(CMAKE_CXX_COMPILER ${LFEM_TRIPLE}-g++)
# Multiarch: the target's libraries and CMake packages live in /usr/lib/aarch64-linux-gnu
# beside the host's; its headers in /usr/include, which Debian's cross compiler searches last.
set(CMAKE_LIBRARY_ARCHITECTURE ${LFEM_TRIPLE})
set(CMAKE_FIND_ROOT_PATH /usr/${LFEM_TRIPLE} /)
set(CMAKE_FIND_ROOT_PATH_MODE_PROGRAM NEVER)
set(CMAKE_CROSSCOMPILING_EMULATOR qemu-aarch64 -L /usr/${LFEM_TRIPLE} -E LD_LIBRARY_PATH=/usr/${LFEM_TRIPLE}/lib)
