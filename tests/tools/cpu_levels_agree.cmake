# ctest scene_digest_cpu_levels_agree: the element kernel's instruction-set variants
# (src/common/cpu_dispatch.h) give bitwise the same physics. scene_digest runs with the CPU's
# own variant, then with LFEM_CPU_LEVEL capping it to AVX2 and to the baseline; every digest
# must be the same. (On a CPU without AVX-512 the first two runs use the same variant.)
#   cmake -DDIGEST=<scene_digest> -P cpu_levels_agree.cmake
set(reference "")
foreach(level "" x86-64-v3 baseline)
  execute_process(COMMAND ${CMAKE_COMMAND} -E env LFEM_CPU_LEVEL=${level} ${DIGEST}
                  OUTPUT_VARIABLE digests RESULT_VARIABLE status)
  if(NOT status EQUAL 0)
    message(FATAL_ERROR "scene_digest with LFEM_CPU_LEVEL='${level}' failed (${status})")
  endif()
  if(level STREQUAL "")
    set(reference "${digests}")
    string(REGEX MATCHALL "\n" lines "${digests}")
    list(LENGTH lines count)
  elseif(NOT digests STREQUAL reference)
    message(FATAL_ERROR "LFEM_CPU_LEVEL=${level} changes the physics:\n${digests}\nagainst the CPU's own "
                        "variant:\n${reference}")
  endif()
endforeach()
message(STATUS "${count} scene digests the same with the CPU's own kernel variant, x86-64-v3 and baseline")
