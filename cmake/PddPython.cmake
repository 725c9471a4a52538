# Finds what the `pdd` Python module needs: an interpreter that imports numpy (Debian's
# python3-numpy serves /usr/bin/python3; a python3 earlier on PATH, e.g. pyenv's, may lack
# it), its development headers and pybind11 (Debian's pybind11-dev). Sets PDD_PYTHON_FOUND and
# PDD_PYTHON_INSTALL_DIR (site-packages relative to the install prefix).
set(PDD_PYTHON_FOUND FALSE)
if(NOT DEFINED Python_EXECUTABLE)
  find_program(_pdd_path_python NAMES python3)
  foreach(candidate IN ITEMS ${_pdd_path_python} /usr/bin/python3)
    if(EXISTS "${candidate}")
      execute_process(COMMAND "${candidate}" -c "import numpy"
        RESULT_VARIABLE _pdd_numpy_rc OUTPUT_QUIET ERROR_QUIET)
      if(_pdd_numpy_rc EQUAL 0)
        set(Python_EXECUTABLE "${candidate}" CACHE FILEPATH "Python interpreter for pdd's module")
        break()
      endif()
    endif()
  endforeach()
endif()
if(DEFINED Python_EXECUTABLE)
  find_package(Python 3.8 COMPONENTS Interpreter Development.Module NumPy)
  if(Python_FOUND AND Python_NumPy_FOUND)
    set(PYBIND11_FINDPYTHON ON)
    find_package(pybind11 2.6 CONFIG QUIET)
    if(pybind11_FOUND)
      set(PDD_PYTHON_FOUND TRUE)
    endif()
  endif()
endif()
if(PDD_PYTHON_FOUND AND NOT DEFINED PDD_PYTHON_INSTALL_DIR)
  # e.g. /usr/local/lib/python3.11/dist-packages -> lib/python3.11/dist-packages
  execute_process(COMMAND "${Python_EXECUTABLE}" -c
    "import os, sysconfig; p = sysconfig.get_paths()['platlib']; print(os.path.relpath(p, os.path.dirname(os.path.dirname(os.path.dirname(p)))))"
    OUTPUT_VARIABLE _pdd_site OUTPUT_STRIP_TRAILING_WHITESPACE)
  set(PDD_PYTHON_INSTALL_DIR "${_pdd_site}" CACHE STRING
    "Where cmake --install puts the pdd module, relative to CMAKE_INSTALL_PREFIX")
endif()
