# The files kept in the repository that the program makes from the table of
# settings (app/settings/settings_table.cxx): the scene files' schema and the
# option reference. Run with cmake -P:
#   -DPROGRAM=path/to/shadelab -DSOURCE_DIR=... -DMODE=check   fails, naming
#     each file that is not what the program makes now;
#   -DMODE=write   writes them (the target regenerate).
function(generated file)
  execute_process(COMMAND "${PROGRAM}" ${ARGN} OUTPUT_VARIABLE made RESULT_VARIABLE status)
  if(NOT status EQUAL 0)
    message(FATAL_ERROR "${PROGRAM} ${ARGN} failed (${status})")
  endif()
  if(MODE STREQUAL "write")
    file(WRITE "${SOURCE_DIR}/${file}" "${made}")
    return()
  endif()
  file(READ "${SOURCE_DIR}/${file}" kept)
  if(NOT kept STREQUAL made)
    message(FATAL_ERROR "${file} is not what the table of settings makes now: "
      "cmake --build <build folder> --target regenerate, and commit it")
  endif()
endfunction()

generated(data/scene.schema.json render --print-schema)
generated(doc/user/options.md print-reference)
