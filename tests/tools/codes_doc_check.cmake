# docs/errors.md must be what `sreh-twin codes --markdown` prints (issue 39).
execute_process(COMMAND ${EXE} codes --markdown OUTPUT_VARIABLE generated RESULT_VARIABLE rc)
if(NOT rc EQUAL 0)
  message(FATAL_ERROR "sreh-twin codes --markdown: exit ${rc}")
endif()
file(READ ${DOC} in_tree)
if(NOT generated STREQUAL in_tree)
  file(WRITE ${CMAKE_CURRENT_BINARY_DIR}/errors.md.generated "${generated}")
  message(FATAL_ERROR "docs/errors.md differs from the code table: regenerate it with\n"
                      "  sreh-twin codes --markdown > docs/errors.md\n"
                      "(what it prints is in ${CMAKE_CURRENT_BINARY_DIR}/errors.md.generated; diff the two)")
endif()
