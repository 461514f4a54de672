# `cmake --install build --prefix P`: P/bin/cdvp, the presets in
# P/share/cdvp/boards, the README, LICENSE and docs in P/share/doc/cdvp, and a
# man page in P/share/man/man1/cdvp.1 generated from the --help texts.
install(TARGETS cdvp RUNTIME DESTINATION ${CMAKE_INSTALL_BINDIR})
install(DIRECTORY ${CMAKE_SOURCE_DIR}/platform/boards/ DESTINATION ${CDVP_INSTALL_BOARDS_DIR}
        FILES_MATCHING PATTERN "*.json")
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
            -P ${CMAKE_SOURCE_DIR}/cmake/man_page.cmake
    DEPENDS cdvp ${CMAKE_SOURCE_DIR}/cmake/man_page.cmake
    COMMENT "Generating the cdvp man page from --help")
  add_custom_target(cdvp_man_page ALL DEPENDS ${cdvp_man_page})
  install(FILES ${cdvp_man_page} DESTINATION ${CMAKE_INSTALL_MANDIR}/man1)
else()
  message(STATUS "help2man not found: no man page (apt-get install help2man)")
endif()
