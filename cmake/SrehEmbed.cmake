# sreh_embed_files(TARGET HEADER <include path> NAMESPACE <ns> PREFIX <p> FILES f...):
# reads the files at build time and compiles them into TARGET, e.g. the
# packaged charting library for pages served or written without a CDN.
# Generates <build>/generated/<HEADER> declaring, in namespace NS,
#   std::string_view find_<p>(std::string_view file_name); // "" if none
#   std::vector<std::string_view> <p>_names();
# Files are looked up by their base name. Rebuilt when a file changes.
set(SREH_EMBED_SCRIPT ${CMAKE_CURRENT_LIST_DIR}/embed_files.cmake)

function(sreh_embed_files target)
  cmake_parse_arguments(ARG "" "HEADER;NAMESPACE;PREFIX" "FILES" ${ARGN})
  set(gen_dir ${CMAKE_CURRENT_BINARY_DIR}/generated)
  set(header ${gen_dir}/${ARG_HEADER})
  get_filename_component(stem ${ARG_HEADER} NAME_WE)
  set(source ${gen_dir}/${stem}_embedded.cpp)
  string(REPLACE ";" "|" files "${ARG_FILES}")
  add_custom_command(
    OUTPUT ${header} ${source}
    COMMAND ${CMAKE_COMMAND} "-DHEADER=${header}" "-DSOURCE=${source}" "-DINCLUDE=${ARG_HEADER}"
            "-DNAMESPACE=${ARG_NAMESPACE}" "-DPREFIX=${ARG_PREFIX}" "-DFILES=${files}" -P ${SREH_EMBED_SCRIPT}
    DEPENDS ${ARG_FILES} ${SREH_EMBED_SCRIPT}
    COMMENT "Embedding ${ARG_HEADER}"
    VERBATIM)
  target_sources(${target} PRIVATE ${source} ${header})
  target_include_directories(${target} PUBLIC ${gen_dir})
endfunction()

# Debian's libjs-dygraphs (dygraph.min.js, dygraph.min.css), checked once:
# the charting library the reports inline and serve's live page serves.
set(SREH_DYGRAPHS_DIR /usr/share/javascript/dygraphs)
set(SREH_DYGRAPHS_FILES ${SREH_DYGRAPHS_DIR}/dygraph.min.js ${SREH_DYGRAPHS_DIR}/dygraph.min.css)
foreach(f ${SREH_DYGRAPHS_FILES})
  if(NOT EXISTS ${f})
    message(FATAL_ERROR "${f} missing: install Debian's libjs-dygraphs (./setup.sh)")
  endif()
endforeach()
