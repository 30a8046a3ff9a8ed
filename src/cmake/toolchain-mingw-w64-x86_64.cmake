# Cross-build of lfem for 64-bit Windows with Debian's MinGW-w64 (package
# g++-mingw-w64-x86-64-posix: the posix thread model, which std::thread needs). From the
# repository's root:
#
#   cmake -S . -B build-win64 -DCMAKE_TOOLCHAIN_FILE=src/cmake/toolchain-mingw-w64-x86_64.cmake \
#         -DCMAKE_BUILD_TYPE=Release -DLFEM_WITH_CCD=OFF
#   cmake --build build-win64 -j2 --target lfem
#
# gives build-win64/bin/lfem.dll (the C++ runtime, libgcc and winpthreads linked in: the DLL
# is all a game ships), its import library build-win64/liblfem.dll.a and build-win64/lfem.def.
# Debian has no Windows build of libccd, hence LFEM_WITH_CCD=OFF (convex hulls answer
# LFEM_UNSUPPORTED). The examples build into bin/ beside the DLL; run them under Wine with
# /usr/lib/wine/wine64 build-win64/bin/falling_block.exe.
set(CMAKE_SYSTEM_NAME Windows)
set(CMAKE_SYSTEM_PROCESSOR AMD64)
set(LFEM_TRIPLE x86_64-w64-mingw32)
set(CMAKE_C_COMPILER ${LFEM_TRIPLE}-gcc-posix)
set(CMAKE_CXX_COMPILER ${LFEM_TRIPLE}-g++-posix)
set(CMAKE_RC_COMPILER ${LFEM_TRIPLE}-windres)

# Libraries and headers of the target only; programs (ccache, python) from the host.
set(CMAKE_FIND_ROOT_PATH /usr/${LFEM_TRIPLE})
set(CMAKE_FIND_ROOT_PATH_MODE_PROGRAM NEVER)
set(CMAKE_FIND_ROOT_PATH_MODE_LIBRARY ONLY)
set(CMAKE_FIND_ROOT_PATH_MODE_INCLUDE ONLY)
set(CMAKE_FIND_ROOT_PATH_MODE_PACKAGE ONLY)
# Eigen is header-only: the host's headers (libeigen3-dev) serve every target.
set(Eigen3_DIR /usr/share/eigen3/cmake CACHE PATH "Eigen's CMake package (header-only, any target)")
