# A precompiled header for the GoogleTest programs: <gtest/gtest.h>, which
# every test file includes, is parsed once for all of them (one header, shared
# with REUSE_FROM) instead of once in each of some hundred files; it takes
# about a fifth off compiling a test file (docs/testing.md, CI). Larger
# headers (nlohmann/json, Boost.Program_options, the standard library) cost
# more to load than most files saved, and are left out. Only the build gets
# faster: every file still includes what it uses, and
# -DCDVP_PRECOMPILED_HEADERS=OFF builds without the header, to check that.
option(CDVP_PRECOMPILED_HEADERS "Precompile <gtest/gtest.h> for the test programs" ON)

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

if(CDVP_PRECOMPILED_HEADERS)
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
  target_precompile_headers(cdvp_test_headers PRIVATE <gtest/gtest.h> <string> <vector>)
  cdvp_targets_below("${CMAKE_SOURCE_DIR}/tests" cdvp_test_targets)
  foreach(target IN LISTS cdvp_test_targets)
    get_target_property(type ${target} TYPE)
    get_target_property(libraries ${target} LINK_LIBRARIES)
    if(type STREQUAL "EXECUTABLE" AND libraries MATCHES "GTest::")
      target_precompile_headers(${target} REUSE_FROM cdvp_test_headers)
    endif()
  endforeach()
endif()
