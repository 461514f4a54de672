# What every report and host profile records about the build: the compiler,
# the flags cdvp was compiled with and the source's git commit, taken when
# CMake configures. A commit or checkout updates .git's HEAD log, which makes
# the build configure again, so the commit recorded is the one built.
set(CDVP_GIT_COMMIT "unknown")
find_package(Git QUIET)
if(GIT_FOUND)
  execute_process(COMMAND "${GIT_EXECUTABLE}" rev-parse HEAD WORKING_DIRECTORY "${CMAKE_SOURCE_DIR}"
                  OUTPUT_VARIABLE cdvp_commit RESULT_VARIABLE cdvp_git_status ERROR_QUIET
                  OUTPUT_STRIP_TRAILING_WHITESPACE)
  if(cdvp_git_status EQUAL 0 AND cdvp_commit)
    set(CDVP_GIT_COMMIT "${cdvp_commit}")
    execute_process(COMMAND "${GIT_EXECUTABLE}" status --porcelain --untracked-files=no
                    WORKING_DIRECTORY "${CMAKE_SOURCE_DIR}" OUTPUT_VARIABLE cdvp_changes ERROR_QUIET)
    if(cdvp_changes)
      set(CDVP_GIT_COMMIT "${CDVP_GIT_COMMIT} (with uncommitted changes at configure time)")
    endif()
    execute_process(COMMAND "${GIT_EXECUTABLE}" rev-parse --path-format=absolute --git-path logs/HEAD
                    WORKING_DIRECTORY "${CMAKE_SOURCE_DIR}" OUTPUT_VARIABLE cdvp_head_log ERROR_QUIET
                    OUTPUT_STRIP_TRAILING_WHITESPACE)
    if(cdvp_head_log AND EXISTS "${cdvp_head_log}")
      set_property(DIRECTORY "${CMAKE_SOURCE_DIR}" APPEND PROPERTY CMAKE_CONFIGURE_DEPENDS "${cdvp_head_log}")
    endif()
  endif()
endif()
string(TOUPPER "${CMAKE_BUILD_TYPE}" cdvp_build_type_upper)
set(CDVP_COMPILER "${CMAKE_CXX_COMPILER_ID} ${CMAKE_CXX_COMPILER_VERSION}")
get_directory_property(cdvp_compile_options DIRECTORY "${CMAKE_SOURCE_DIR}" COMPILE_OPTIONS)
list(JOIN cdvp_compile_options " " cdvp_compile_options)
string(STRIP "${CMAKE_CXX_FLAGS} ${CMAKE_CXX_FLAGS_${cdvp_build_type_upper}} ${cdvp_compile_options}"
       CDVP_BUILD_FLAGS)
configure_file("${CMAKE_SOURCE_DIR}/sw/run/build_info.cpp.in" "${CMAKE_BINARY_DIR}/generated/build_info.cpp" @ONLY)
