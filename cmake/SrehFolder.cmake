include(GNUInstallDirs)

# sreh_folder_library(NAME [DEPS ...]): one library target per code folder
# (docs/style.md 15), built from every .cpp in the folder, with a namespaced alias.
function(sreh_folder_library name)
  cmake_parse_arguments(ARG "" "" "DEPS;PRIVATE_DEPS" ${ARGN})
  file(GLOB sources CONFIGURE_DEPENDS ${CMAKE_CURRENT_SOURCE_DIR}/*.cpp)
  if(NOT sources) # a header-only folder (or one not written yet)
    add_library(${name} INTERFACE)
    target_include_directories(${name} INTERFACE $<BUILD_INTERFACE:${PROJECT_SOURCE_DIR}>
                                                 $<INSTALL_INTERFACE:${CMAKE_INSTALL_INCLUDEDIR}/sreh_twin>)
    target_link_libraries(${name} INTERFACE ${ARG_DEPS})
  else()
    add_library(${name} STATIC ${sources})
    # Installed headers keep their folder: <prefix>/include/sreh_twin/twin/twin.hpp (issue 13).
    target_include_directories(${name} PUBLIC $<BUILD_INTERFACE:${PROJECT_SOURCE_DIR}>
                                              $<INSTALL_INTERFACE:${CMAKE_INSTALL_INCLUDEDIR}/sreh_twin>)
    target_link_libraries(${name} PUBLIC ${ARG_DEPS} PRIVATE $<BUILD_INTERFACE:sreh_warnings> ${ARG_PRIVATE_DEPS})
  endif()
  add_library(sreh::${name} ALIAS ${name})
endfunction()

# sreh_gtest_folder(NAME [COST SECONDS] DEPS ...): one GoogleTest executable
# per test folder, every *_test.cpp in it, registered with CTest. COST: CTest
# starts costly tests first (a clean checkout has no timings of its own), so
# a minute-long fit does not start last and hold the run's tail alone.
function(sreh_gtest_folder name)
  cmake_parse_arguments(ARG "" "COST" "DEPS" ${ARGN})
  if(NOT ARG_COST)
    set(ARG_COST 0)
  endif()
  file(GLOB sources CONFIGURE_DEPENDS ${CMAKE_CURRENT_SOURCE_DIR}/*_test.cpp)
  if(NOT sources)
    return()
  endif()
  add_executable(${name} ${sources})
  target_link_libraries(${name} PRIVATE ${ARG_DEPS} GTest::gtest_main GTest::gmock sreh_warnings)
  target_compile_definitions(${name} PRIVATE SREH_SOURCE_DIR="${PROJECT_SOURCE_DIR}")
  # Test code is glue around the libraries (compiled -O3, where the time is
  # spent); at -O1 it compiles ~40 % faster, which keeps CI short.
  target_compile_options(${name} PRIVATE $<$<CONFIG:Release>:-O1>)
  if(TARGET sreh_test_pch) # SREH_PCH (tests/CMakeLists.txt)
    target_precompile_headers(${name} REUSE_FROM sreh_test_pch)
  endif()
  # NO_PRETTY_VALUES: a value-parameterised test is named by its name
  # generator, not by the bytes of its parameter (issue 39: short names).
  gtest_discover_tests(${name} DISCOVERY_TIMEOUT 60 NO_PRETTY_VALUES PROPERTIES LABELS unit COST ${ARG_COST})
endfunction()
