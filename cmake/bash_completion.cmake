# Run after the program is linked: writes its bash completion script, which the program makes from its
# own parser (PROGRAM --bash-completion), to OUTPUT.
get_filename_component(dir "${OUTPUT}" DIRECTORY)
file(MAKE_DIRECTORY "${dir}")
execute_process(COMMAND "${PROGRAM}" --bash-completion OUTPUT_FILE "${OUTPUT}.new" RESULT_VARIABLE status)
if(NOT status EQUAL 0)
  message(FATAL_ERROR "${PROGRAM} --bash-completion failed (${status})")
endif()
file(RENAME "${OUTPUT}.new" "${OUTPUT}")
