# cmake -DPROGRAM=<path of a pdd program> -DVERSION=<project version> -P PddCheckVersion.cmake
# (the drivers.version.* tests): `<program> --version` exits 0 and prints exactly
# "<program name> <version>" and a newline to stdout.
get_filename_component(name "${PROGRAM}" NAME_WE)
execute_process(COMMAND "${PROGRAM}" --version RESULT_VARIABLE rc OUTPUT_VARIABLE out
                ERROR_VARIABLE err)
if(NOT rc EQUAL 0)
  message(FATAL_ERROR "${name} --version exited with '${rc}' (stderr: '${err}')")
endif()
if(NOT out STREQUAL "${name} ${VERSION}\n")
  message(FATAL_ERROR "${name} --version printed '${out}', expected '${name} ${VERSION}'")
endif()
string(STRIP "${out}" out)
message(STATUS "${name} --version: ${out}")
