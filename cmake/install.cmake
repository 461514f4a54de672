# `cmake --install build --prefix P`: P/bin/cdvp, the presets in
# P/share/cdvp/boards, the RTL kit in P/share/cdvp/rtl, the JSON Schemas of
# the run report and a sweep row in P/share/cdvp/schema, the README, LICENSE
# and docs in P/share/doc/cdvp, and a man page in P/share/man/man1/cdvp.1
# generated from the --help texts.
install(DIRECTORY ${CMAKE_SOURCE_DIR}/platform/boards/ DESTINATION ${CDVP_INSTALL_BOARDS_DIR}
        FILES_MATCHING PATTERN "*.json")
# The RTL kit (models/rtl_engine/rtl_kit.h): what --fidelity rtl compiles a
# variant the binary does not hold from, laid out as in the source tree.
get_property(cdvp_rtl_kit GLOBAL PROPERTY CDVP_RTL_KIT)
foreach(file IN LISTS cdvp_rtl_kit)
  get_filename_component(directory ${file} DIRECTORY)
  install(FILES ${CMAKE_SOURCE_DIR}/${file} DESTINATION ${CDVP_INSTALL_RTL_DIR}/${directory})
endforeach()
install(DIRECTORY ${CMAKE_SOURCE_DIR}/docs/schema/ DESTINATION ${CMAKE_INSTALL_DATADIR}/cdvp/schema
        FILES_MATCHING PATTERN "*.schema.json")
install(FILES ${CMAKE_SOURCE_DIR}/README.md ${CMAKE_SOURCE_DIR}/LICENSE DESTINATION ${CMAKE_INSTALL_DOCDIR})
# docs/ keeps its name, so the README's links into it hold.
install(DIRECTORY ${CMAKE_SOURCE_DIR}/docs DESTINATION ${CMAKE_INSTALL_DOCDIR})

# The man page is generated from the binary's own --help output, so it cannot
# drift from it. Without help2man the build goes on without one (CI installs
# it through scripts/setup.sh, and the install test then checks the page).
find_program(CDVP_HELP2MAN help2man)
if(CDVP_HELP2MAN)
  set(cdvp_man_page ${CMAKE_BINARY_DIR}/cdvp.1)
  add_custom_command(
    OUTPUT ${cdvp_man_page}
    COMMAND ${CMAKE_COMMAND} -DCDVP=$<TARGET_FILE:cdvp> -DHELP2MAN=${CDVP_HELP2MAN} -DOUT=${cdvp_man_page}
            -DBOARDS=${CMAKE_SOURCE_DIR}/platform/boards -P ${CMAKE_SOURCE_DIR}/cmake/man_page.cmake
    DEPENDS cdvp ${CMAKE_SOURCE_DIR}/cmake/man_page.cmake
    COMMENT "Generating the cdvp man page from --help")
  add_custom_target(cdvp_man_page ALL DEPENDS ${cdvp_man_page})
  install(FILES ${cdvp_man_page} DESTINATION ${CMAKE_INSTALL_MANDIR}/man1)
else()
  message(STATUS "help2man not found: no man page (apt-get install help2man)")
endif()

# The C++ package (docs/library.md): the libraries below the command line,
# static and position-independent, with their headers under
# P/include/cdvp (included as "models/board/collision_board.h" and so on), a
# CMake package (find_package(cdvp CONFIG REQUIRED): cdvp::board,
# cdvp::platform, cdvp::bullet, cdvp::study, ...) and a pkg-config file.
# Static, so that a user's program or module carries the model it was built
# against and no library path is needed at run time; position-independent so
# that a shared library or Python module may link them.
set(cdvp_package_libraries
    # target                export name    what it is
    cdvp_models_base        base           # geometry, register bank, transactions, bad input
    cdvp_models_blocks      blocks         # the board's blocks
    cdvp_models_board_spec  board_spec     # BoardConfig, BoardEngine
    cdvp_models_engines     engines        # the clocked and fast engines
    cdvp_models_rtl         rtl_engine     # the RTL engine and the list of built RTL variants
    cdvp_models             board_core     # BoardCore and the engine factory, no SystemC
    cdvp_models_systemc     board          # CollisionBoard, PciBus, PciBridge: the board as SystemC IP
    cdvp_driver             driver         # BoardDriver against a HostPort
    cdvp_settings           settings       # the settings table, their values and origins, presets, config files
    cdvp_platform           platform       # VirtualBoard, the analytic platform, the device fit
    cdvp_timing             timing
    cdvp_scene              scene          # traces, pairs CSV, spheres
    cdvp_baselines          baselines      # software broad phases
    cdvp_apps               apps           # the bouncing spheres
    cdvp_bullet             bullet         # BoardBroadphase for btDiscreteDynamicsWorld
    cdvp_output             output         # transactional output files
    cdvp_run                run            # RunSpec and run(): one run in this process
    cdvp_study              study)         # child runs, reports, sweeps, merges, fidelity
if(TARGET cdvp_models_rtl_verilated)
  list(APPEND cdvp_package_libraries cdvp_models_rtl_verilated rtl_verilated)  # the Verilator-built board RTL
endif()
set(cdvp_package_targets "")
set(cdvp_package_list ${cdvp_package_libraries})
while(cdvp_package_list)
  list(POP_FRONT cdvp_package_list target export_name)
  set_target_properties(${target} PROPERTIES EXPORT_NAME ${export_name})
  target_include_directories(${target} INTERFACE $<INSTALL_INTERFACE:${CMAKE_INSTALL_INCLUDEDIR}/cdvp>)
  add_library(cdvp::${export_name} ALIAS ${target})
  list(APPEND cdvp_package_targets ${target})
endwhile()
install(TARGETS ${cdvp_package_targets} EXPORT cdvpTargets ARCHIVE DESTINATION ${CMAKE_INSTALL_LIBDIR})
# The binary too, as cdvp::cdvp: the study library runs it for each point.
set_target_properties(cdvp PROPERTIES EXPORT_NAME cdvp)
install(TARGETS cdvp EXPORT cdvpTargets RUNTIME DESTINATION ${CMAKE_INSTALL_BINDIR})
# Headers: every header of the layers the libraries hold (the public surface
# and the internals it includes; docs/library.md says which is which).
foreach(dir models platform sw/timing sw/scene sw/baselines sw/apps sw/bullet sw/output sw/run sw/study)
  install(DIRECTORY ${CMAKE_SOURCE_DIR}/${dir}/ DESTINATION ${CMAKE_INSTALL_INCLUDEDIR}/cdvp/${dir}
          FILES_MATCHING PATTERN "*.h" PATTERN "rtl" EXCLUDE PATTERN "boards" EXCLUDE PATTERN "figures" EXCLUDE)
endforeach()
# Public headers that moved keep a forwarding header at their old path, which
# includes the new one and says so (docs/library.md); the source tree has none.
install(DIRECTORY ${CMAKE_SOURCE_DIR}/cmake/moved_headers/ DESTINATION ${CMAKE_INSTALL_INCLUDEDIR}/cdvp
        FILES_MATCHING PATTERN "*.h")
set(cdvp_cmake_dir ${CMAKE_INSTALL_LIBDIR}/cmake/cdvp)
install(EXPORT cdvpTargets NAMESPACE cdvp:: DESTINATION ${cdvp_cmake_dir})
include(CMakePackageConfigHelpers)
configure_package_config_file(${CMAKE_SOURCE_DIR}/cmake/cdvpConfig.cmake.in ${CMAKE_BINARY_DIR}/cdvpConfig.cmake
                              INSTALL_DESTINATION ${cdvp_cmake_dir}
                              PATH_VARS CDVP_INSTALL_BOARDS_DIR CDVP_INSTALL_RTL_DIR CMAKE_INSTALL_INCLUDEDIR)
write_basic_package_version_file(${CMAKE_BINARY_DIR}/cdvpConfigVersion.cmake COMPATIBILITY SameMinorVersion)
install(FILES ${CMAKE_BINARY_DIR}/cdvpConfig.cmake ${CMAKE_BINARY_DIR}/cdvpConfigVersion.cmake
        DESTINATION ${cdvp_cmake_dir})
# The prefix relative to the .pc file, so that a moved prefix still works.
file(RELATIVE_PATH cdvp_pc_up "/p/${CMAKE_INSTALL_LIBDIR}/pkgconfig" "/p")
set(cdvp_pc_rtl_verilated "")
if(TARGET cdvp_models_rtl_verilated)
  set(cdvp_pc_rtl_verilated " -lcdvp_models_rtl_verilated")
endif()
configure_file(${CMAKE_SOURCE_DIR}/cmake/cdvp.pc.in ${CMAKE_BINARY_DIR}/cdvp.pc @ONLY)
install(FILES ${CMAKE_BINARY_DIR}/cdvp.pc DESTINATION ${CMAKE_INSTALL_LIBDIR}/pkgconfig)
