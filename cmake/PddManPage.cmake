# cmake -DHELP2MAN=... -DPROGRAM=<path of a pdd program> -DOUTPUT=<page.1> -P PddManPage.cmake
# (pdd_add_man_page in PddManPages.cmake): the program's man page by help2man. The program runs
# by its bare name from PATH, so that the page's usage line reads `pdd-mesh [OPTIONS] ...`, not
# the build tree's path; the first line of its --help ("pdd-mesh: what it does") is the page's
# NAME line. help2man fails when --help or --version does not exit 0.
get_filename_component(dir "${PROGRAM}" DIRECTORY)
get_filename_component(name "${PROGRAM}" NAME)
get_filename_component(out_dir "${OUTPUT}" DIRECTORY)
file(MAKE_DIRECTORY "${out_dir}")
set(ENV{PATH} "${dir}:$ENV{PATH}")
execute_process(COMMAND "${name}" --help RESULT_VARIABLE rc OUTPUT_VARIABLE help)
if(NOT rc EQUAL 0 OR help STREQUAL "")
  message(FATAL_ERROR "${name} --help exited with ${rc} and wrote '${help}' to stdout")
endif()
string(REGEX MATCH "^[^\n]*" first "${help}")
string(REGEX REPLACE "^${name}: *" "" description "${first}")
execute_process(COMMAND "${HELP2MAN}" --no-info --section=1
                        "--name=${description}" "--output=${OUTPUT}" "${name}"
                RESULT_VARIABLE rc)
if(NOT rc EQUAL 0)
  file(REMOVE "${OUTPUT}")
  message(FATAL_ERROR "help2man ${name} exited with ${rc}")
endif()
