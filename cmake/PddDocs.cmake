# The documentation site (issue 38 item 2): `cmake --build <build> --target docs` builds the
# pages of docs/ with MkDocs (`mkdocs build --strict`: a broken link or a page missing from
# mkdocs.yml's nav fails it) into <build>/site, and the C++ API reference with Doxygen
# (cmake/Doxyfile.in: documentation errors fail it) into <build>/site/api. Debian packages:
# mkdocs, doxygen (scripts/install-deps.sh). Without them there is no docs target.
find_program(PDD_MKDOCS mkdocs)
find_package(Doxygen QUIET)
if(PDD_MKDOCS AND DOXYGEN_FOUND)
  configure_file(${CMAKE_CURRENT_LIST_DIR}/Doxyfile.in ${PROJECT_BINARY_DIR}/Doxyfile @ONLY)
  add_custom_target(docs
    COMMAND ${PDD_MKDOCS} build --strict --quiet -f ${PROJECT_SOURCE_DIR}/mkdocs.yml
            -d ${PROJECT_BINARY_DIR}/site
    COMMAND Doxygen::doxygen ${PROJECT_BINARY_DIR}/Doxyfile
    COMMAND ${CMAKE_COMMAND} -E echo "docs: ${PROJECT_BINARY_DIR}/site/index.html, the C++ API in ${PROJECT_BINARY_DIR}/site/api/index.html"
    WORKING_DIRECTORY ${PROJECT_SOURCE_DIR}
    COMMENT "MkDocs (--strict) and Doxygen into ${PROJECT_BINARY_DIR}/site"
    VERBATIM)
else()
  message(STATUS "pdd: no docs target (needs mkdocs and doxygen: scripts/install-deps.sh)")
endif()
