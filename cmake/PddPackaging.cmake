# The Debian package: `cpack -G DEB` (or `cpack`) in a build directory makes
# pdd_<version>_<arch>.deb of what `cmake --install` installs (the programs, the headers, the
# CMake package, the man pages, the examples' data, the Python module), under /usr. The version
# is project(VERSION)'s. Depends: the -dev packages that find_package(pdd) and the headers need,
# numpy and the interpreter the module was built for; dpkg-shlibdeps (dpkg-dev) adds the shared
# libraries the programs link (libtbb12, libmuparser2v5, libmetis5, libopenmpi3, ...).
# scripts/check-deb.sh builds it and checks its contents.
set(CPACK_GENERATOR DEB)
set(CPACK_PACKAGE_NAME pdd)
set(CPACK_PACKAGE_VERSION ${PROJECT_VERSION})
set(CPACK_PACKAGE_VENDOR "The pdd developers")
set(CPACK_PACKAGE_CONTACT "The pdd developers")
set(CPACK_PACKAGE_DESCRIPTION_SUMMARY "${PROJECT_DESCRIPTION}")
set(CPACK_PACKAGE_DESCRIPTION "pdd meshes 2D domains with guaranteed quality in parallel: the \
domain is split by the Medial Axis Domain Decomposition into subdomains meshed independently. \
The package holds the programs (pdd-mesh, pdd-triangle, ...), the C++20 library (libpdd and \
its headers) with its CMake package (find_package(pdd): pdd::pdd, pdd::header_only), the man \
pages and the pdd Python module. Licence: \
pdd's own code is MIT; the programs and the module link CGAL's GPLv3+ packages (2D \
Triangulation, Mesh_2), so the binaries are covered by the GPL (README.md, Licence).")
set(CPACK_RESOURCE_FILE_LICENSE ${PROJECT_SOURCE_DIR}/LICENSE)
# Debian's machine-readable copyright file (what is MIT, what is GPL-3+ and why), where Debian
# policy wants it: /usr/share/doc/pdd/copyright.
install(FILES ${PROJECT_SOURCE_DIR}/cmake/debian/copyright DESTINATION ${CMAKE_INSTALL_DOCDIR})
set(CPACK_PACKAGING_INSTALL_PREFIX /usr)
set(CPACK_DEBIAN_FILE_NAME DEB-DEFAULT) # pdd_0.1.0_amd64.deb
set(CPACK_DEBIAN_PACKAGE_SECTION science)
set(CPACK_DEBIAN_PACKAGE_SHLIBDEPS ON)

set(_pdd_deb_depends libcgal-dev libboost-dev libtbb-dev libmuparser-dev)
if(METIS_FOUND)
  list(APPEND _pdd_deb_depends libmetis-dev)
endif()
if(PDD_WITH_MPI)
  list(APPEND _pdd_deb_depends libopenmpi-dev)
  set(CPACK_DEBIAN_PACKAGE_RECOMMENDS openmpi-bin) # mpiexec, for pdd-mesh-mpi
endif()
if(PDD_PYTHON)
  # The module is built for one interpreter (pdd.cpython-311-...so): python3 of that minor.
  set(_pdd_py ${Python_VERSION_MAJOR}.${Python_VERSION_MINOR})
  math(EXPR _pdd_py_next "${Python_VERSION_MINOR} + 1")
  list(APPEND _pdd_deb_depends "python3 (>= ${_pdd_py})"
       "python3 (<< ${Python_VERSION_MAJOR}.${_pdd_py_next})" python3-numpy)
endif()
list(JOIN _pdd_deb_depends ", " CPACK_DEBIAN_PACKAGE_DEPENDS)

# Every component in one package: the default one (everything but the module's usual copy)
# and python-deb, the module where Debian's python3 finds packaged modules
# (/usr/lib/python3/dist-packages; python/CMakeLists.txt). The `python` component, the module
# under the interpreter's site-packages for `cmake --install`, is left out.
set(CPACK_DEB_COMPONENT_INSTALL ON)
set(CPACK_COMPONENTS_GROUPING ALL_COMPONENTS_IN_ONE)
set(CPACK_COMPONENTS_ALL Unspecified)
if(PDD_PYTHON)
  list(APPEND CPACK_COMPONENTS_ALL python-deb)
endif()
include(CPack)
