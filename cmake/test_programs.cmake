# How the GoogleTest programs under tests/ are compiled, so that building the
# suite costs less than the code it tests (docs/testing.md, CI). The tests'
# own files are most of a build (their bodies are many small functions, and
# each file parses the same headers); the libraries they test are built as
# every user builds them. Only the build changes: the same tests run.
#
# - One precompiled <gtest/gtest.h>, which every test file includes, parsed
#   once for all of them (one header shared with REUSE_FROM) instead of once
#   in each of some hundred files. Larger headers (nlohmann/json,
#   Boost.Program_options, the standard library) cost more to load than most
#   files saved, and are left out.
# - Unity batches, as for every target (CDVP_UNITY_BATCH, the top
#   CMakeLists.txt): a program's files compiled eight at a time as one
#   translation unit, so the headers they share are parsed once a batch.
# - -O1 for the test bodies in a Release build: -O3 spends most of a test
#   file's compile on code that runs once, while the models they call keep
#   the build's -O3. Benchmarks are not GoogleTest programs and keep -O3.
#
# - In a sanitized build the test programs' own files are not instrumented
#   (cdvp_without_sanitizers): the sanitizers are there for the code under
#   test, which stays instrumented, and instrumenting the test bodies tripled
#   their compile time (docs/testing.md, CI). A model's source compiled into
#   a test program keeps the checks.
#
# Every file still includes what it uses: -DCDVP_PRECOMPILED_HEADERS=OFF
# -DCDVP_UNITY_BATCH=1 builds each file on its own, to check that.
option(CDVP_PRECOMPILED_HEADERS "Precompile <gtest/gtest.h> for the test programs" ON)
set(CDVP_TEST_RELEASE_OPT "-O1" CACHE STRING "Optimisation of the test programs' own files in a Release build")

# The build-system targets of DIR and of the directories below it.
function(cdvp_targets_below dir out)
  get_property(targets DIRECTORY "${dir}" PROPERTY BUILDSYSTEM_TARGETS)
  get_property(subdirectories DIRECTORY "${dir}" PROPERTY SUBDIRECTORIES)
  foreach(subdirectory IN LISTS subdirectories)
    cdvp_targets_below("${subdirectory}" below)
    list(APPEND targets ${below})
  endforeach()
  set(${out} ${targets} PARENT_SCOPE)
endfunction()

# The header belongs to cdvp_test_headers, an empty GoogleTest program that
# needs nothing else built first (a target waits for the one whose header it
# reuses). Every GoogleTest program under tests/ reuses it: all are
# executables with the same flags, which a precompiled header needs; their
# own definitions do not appear in it.
set(cdvp_test_headers_main "${CMAKE_BINARY_DIR}/generated/test_headers_main.cpp")
file(CONFIGURE OUTPUT "${cdvp_test_headers_main}" CONTENT "int main() { return 0; }\n")
add_executable(cdvp_test_headers EXCLUDE_FROM_ALL "${cdvp_test_headers_main}")
set_target_properties(cdvp_test_headers PROPERTIES RUNTIME_OUTPUT_DIRECTORY "${CMAKE_BINARY_DIR}/generated")
target_link_libraries(cdvp_test_headers PRIVATE GTest::gtest)
if(CDVP_PRECOMPILED_HEADERS)
  target_precompile_headers(cdvp_test_headers PRIVATE <gtest/gtest.h> <string> <vector>)
endif()

cdvp_targets_below("${CMAKE_SOURCE_DIR}/tests" cdvp_test_targets)
foreach(target IN LISTS cdvp_test_targets ITEMS cdvp_test_headers)
  get_target_property(type ${target} TYPE)
  get_target_property(libraries ${target} LINK_LIBRARIES)
  if(NOT (type STREQUAL "EXECUTABLE" AND libraries MATCHES "GTest::"))
    continue()
  endif()
  target_compile_options(${target} PRIVATE $<$<CONFIG:Release>:${CDVP_TEST_RELEASE_OPT}>)
  get_target_property(sources ${target} SOURCES)
  get_target_property(source_dir ${target} SOURCE_DIR)
  set(code_under_test "")
  foreach(source IN LISTS sources)
    get_filename_component(source "${source}" ABSOLUTE BASE_DIR "${source_dir}")
    string(FIND "${source}" "${CMAKE_SOURCE_DIR}/tests/" at)
    if(NOT at EQUAL 0 AND NOT source STREQUAL "${cdvp_test_headers_main}")
      list(APPEND code_under_test "${source}")
    endif()
  endforeach()
  cdvp_without_sanitizers(${target} INSTRUMENTED ${code_under_test})
  if(CDVP_PRECOMPILED_HEADERS AND NOT target STREQUAL "cdvp_test_headers")
    target_precompile_headers(${target} REUSE_FROM cdvp_test_headers)
  endif()
endforeach()

# A sanitized build runs no benchmark (they are timed in Release builds):
# there they are not part of `all`, and `cmake --build ... --target NAME`
# still builds one.
if(cdvp_sanitizers)
  foreach(target IN LISTS cdvp_test_targets)
    if(target MATCHES "_bench$")
      set_property(TARGET ${target} PROPERTY EXCLUDE_FROM_ALL ON)
    endif()
  endforeach()
endif()
