# Man pages for the programs, generated at build time by help2man from each program's own
# --help and --version (the same CLI11 option definitions, so the page cannot drift from the
# program). `pdd_add_man_page(<target>)` adds <build>/man/man1/<target>.1 to ALL and installs it
# into ${CMAKE_INSTALL_MANDIR}/man1; without help2man (Debian package help2man) it does nothing.
# Off by default in sanitizer builds and when cross-compiling, where the programs cannot run
# at build time as they are.
find_program(HELP2MAN_EXECUTABLE help2man)
set(_pdd_man_default OFF)
if(HELP2MAN_EXECUTABLE AND NOT PDD_SANITIZE AND NOT PDD_SANITIZE_THREAD
   AND NOT CMAKE_CROSSCOMPILING)
  set(_pdd_man_default ON)
endif()
option(PDD_MAN_PAGES "Generate and install the programs' man pages (help2man)" ${_pdd_man_default})
if(PDD_MAN_PAGES AND NOT HELP2MAN_EXECUTABLE)
  message(FATAL_ERROR "PDD_MAN_PAGES needs help2man (Debian package help2man)")
endif()
if(PDD_BUILD_DRIVERS AND NOT HELP2MAN_EXECUTABLE)
  message(STATUS "help2man not found (Debian package help2man): no man pages for the programs")
endif()

function(pdd_add_man_page target)
  if(NOT PDD_MAN_PAGES)
    return()
  endif()
  set(page ${PROJECT_BINARY_DIR}/man/man1/${target}.1)
  add_custom_command(OUTPUT ${page}
    COMMAND ${CMAKE_COMMAND} -DHELP2MAN=${HELP2MAN_EXECUTABLE}
            -DPROGRAM=$<TARGET_FILE:${target}> -DOUTPUT=${page}
            -P ${PROJECT_SOURCE_DIR}/cmake/PddManPage.cmake
    DEPENDS ${target} ${PROJECT_SOURCE_DIR}/cmake/PddManPage.cmake
    COMMENT "help2man: man/man1/${target}.1" VERBATIM)
  add_custom_target(${target}-man ALL DEPENDS ${page})
  install(FILES ${page} DESTINATION ${CMAKE_INSTALL_MANDIR}/man1)
endfunction()
