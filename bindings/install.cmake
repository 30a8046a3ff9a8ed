# cmake --install for the bindings (LFEM_INSTALL_BINDINGS, ON by default), included by the
# install section of the top-level CMakeLists.txt after the C library's rules:
#
#   <LFEM_INSTALL_PYTHONDIR>/lfem/        the Python package, plus _install_paths.py telling it
#                                         where the library is from there (so it loads the
#                                         liblfem of its own prefix without any variable)
#   <datadir>/lfem/csharp/Lfem.cs         the C# source (Unity, Godot C#, .NET projects)
#   <libdir>/mono/lfem/Lfem.dll           the assembly, built with mcs when mcs is found, and
#   <libdir>/mono/lfem/Lfem.dll.config    mono's dllmap from "lfem" to the installed liblfem.so.0,
#                                         written at install time for the prefix installed to
#   <libdir>/pkgconfig/lfem-sharp.pc      for mcs -pkg:lfem-sharp (its Libraries lists Lfem.dll)
#
# The Rust crates are not installed: cargo takes them by path or from a registry, and their
# build script finds this installed library through lfem.pc.
# Off by default in a cross build: these rules follow the host (its python3's site folder,
# mono's dllmap to the ELF SONAME); for Windows, Lfem.cs and the Python package load lfem.dll
# from beside the program.
if(CMAKE_CROSSCOMPILING)
  set(lfem_install_bindings_default OFF)
else()
  set(lfem_install_bindings_default ON)
endif()
option(LFEM_INSTALL_BINDINGS "cmake --install also installs the Python package and the C# bindings"
       ${lfem_install_bindings_default})
if(NOT LFEM_INSTALL_BINDINGS)
  return()
endif()
set(lfem_bindings_src ${PROJECT_SOURCE_DIR}/bindings)
set(lfem_bindings_out ${PROJECT_BINARY_DIR}/bindings-install)

# ---- Python ------------------------------------------------------------------------------------
# The conventional site folder of the system python3 under a prefix: Debian's own scheme
# (posix_local) puts the prefix /usr/local's packages in lib/python3.X/dist-packages, the one it
# searches; elsewhere the upstream lib/python3.X/site-packages.
find_program(LFEM_PYTHON3 python3 PATHS /usr/bin NO_DEFAULT_PATH)
find_program(LFEM_PYTHON3 python3)
if(NOT LFEM_INSTALL_PYTHONDIR)
  set(lfem_pythondir lib/python3/site-packages)
  if(LFEM_PYTHON3)
    execute_process(COMMAND ${LFEM_PYTHON3} -c [=[
import os, sysconfig
scheme = getattr(sysconfig, "get_default_scheme", getattr(sysconfig, "_get_default_scheme", None))()
if scheme == "posix_local":
    print(os.path.relpath(sysconfig.get_path("purelib", scheme, vars={"base": "/usr"}), "/usr/local"))
else:
    print(os.path.relpath(sysconfig.get_path("purelib", "posix_prefix", vars={"base": "/", "platbase": "/"}), "/"))
]=] OUTPUT_VARIABLE lfem_pythondir_found OUTPUT_STRIP_TRAILING_WHITESPACE RESULT_VARIABLE lfem_python_status)
    if(lfem_python_status EQUAL 0 AND lfem_pythondir_found)
      set(lfem_pythondir ${lfem_pythondir_found})
    endif()
  else()
    message(STATUS "lfem: no python3 found; the Python package installs to ${lfem_pythondir}")
  endif()
  set(LFEM_INSTALL_PYTHONDIR ${lfem_pythondir} CACHE STRING
      "Where cmake --install puts the Python package lfem (relative to the prefix, or absolute)")
endif()
install(DIRECTORY ${lfem_bindings_src}/python/lfem/ DESTINATION ${LFEM_INSTALL_PYTHONDIR}/lfem
  FILES_MATCHING PATTERN "*.py" PATTERN "py.typed" PATTERN "__pycache__" EXCLUDE)
# The library folder seen from the installed package (relative, so the tree stays relocatable).
if(IS_ABSOLUTE "${LFEM_INSTALL_PYTHONDIR}" OR IS_ABSOLUTE "${CMAKE_INSTALL_LIBDIR}")
  set(lfem_libdir_from_package ${CMAKE_INSTALL_FULL_LIBDIR})
else()
  file(RELATIVE_PATH lfem_libdir_from_package "/prefix/${LFEM_INSTALL_PYTHONDIR}/lfem"
       "/prefix/${CMAKE_INSTALL_LIBDIR}")
  string(REGEX REPLACE "/$" "" lfem_libdir_from_package "${lfem_libdir_from_package}")
endif()
file(WRITE ${lfem_bindings_out}/python/_install_paths.py
  "\"\"\"Written by cmake --install: where the library of this install is, from here.\"\"\"\n\n"
  "LIBDIR_FROM_PACKAGE = \"${lfem_libdir_from_package}\"\n")
install(FILES ${lfem_bindings_out}/python/_install_paths.py
  DESTINATION ${LFEM_INSTALL_PYTHONDIR}/lfem)

# ---- C# --------------------------------------------------------------------------------------------
install(FILES ${lfem_bindings_src}/csharp/Lfem.cs DESTINATION ${CMAKE_INSTALL_DATADIR}/lfem/csharp)
find_program(LFEM_MCS mcs)
if(NOT LFEM_MCS)
  message(STATUS "lfem: mcs not found: cmake --install puts Lfem.cs but no Lfem.dll")
  return()
endif()
set(lfem_assembly ${lfem_bindings_out}/csharp/Lfem.dll)
add_custom_command(OUTPUT ${lfem_assembly}
  COMMAND ${LFEM_MCS} -nologo -warn:4 -warnaserror+ -optimize+ -target:library
          -out:${lfem_assembly} ${lfem_bindings_src}/csharp/Lfem.cs
  DEPENDS ${lfem_bindings_src}/csharp/Lfem.cs
  COMMENT "Compiling the C# bindings (Lfem.dll)")
add_custom_target(lfem_csharp_assembly ALL DEPENDS ${lfem_assembly})
set(lfem_assemblydir ${CMAKE_INSTALL_LIBDIR}/mono/lfem)
install(FILES ${lfem_assembly} DESTINATION ${lfem_assemblydir})
# mono resolves DllImport("lfem") through the dllmap of Lfem.dll.config beside the assembly (and
# beside a program that copies it): the absolute path of the library as installed, so a program
# runs without LD_LIBRARY_PATH. Written at install time, when the prefix is known (--prefix).
install(CODE "
  set(lfem_libdir \"${CMAKE_INSTALL_LIBDIR}\")
  if(NOT IS_ABSOLUTE \"\${lfem_libdir}\")
    set(lfem_libdir \"\${CMAKE_INSTALL_PREFIX}/\${lfem_libdir}\")
  endif()
  file(WRITE \"${lfem_bindings_out}/csharp/Lfem.dll.config\"
    \"<!-- Written by cmake --install: mono loads the native library of Lfem.dll from here. -->\\n\"
    \"<configuration>\\n\"
    \"  <dllmap dll=\\\"lfem\\\" target=\\\"\${lfem_libdir}/$<TARGET_SONAME_FILE_NAME:lfem>\\\" />\\n\"
    \"</configuration>\\n\")
  file(INSTALL DESTINATION \"\${CMAKE_INSTALL_PREFIX}/${lfem_assemblydir}\" TYPE FILE
       FILES \"${lfem_bindings_out}/csharp/Lfem.dll.config\")
")
configure_file(${lfem_bindings_src}/csharp/lfem-sharp.pc.in ${lfem_bindings_out}/csharp/lfem-sharp.pc @ONLY)
install(FILES ${lfem_bindings_out}/csharp/lfem-sharp.pc DESTINATION ${CMAKE_INSTALL_LIBDIR}/pkgconfig)
