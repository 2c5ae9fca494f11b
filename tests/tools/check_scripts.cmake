# The quick-start scripts' configure lines (issue 12): `./demo.sh && ./test.sh`
# on one checkout must run the whole suite, and ctest must refuse an empty run.
#   -DSOURCE=<project source dir>
file(READ ${SOURCE}/test.sh test_sh)
file(READ ${SOURCE}/demo.sh demo_sh)
# Every configuration test.sh uses (release and --sanitize) turns tests on.
string(REGEX MATCHALL "config=\\([^)]*\\)" configs "${test_sh}")
list(LENGTH configs n)
if(n LESS 2)
  message(FATAL_ERROR "test.sh: expected a release and a sanitizer config=(...) line, found ${n}")
endif()
foreach(c ${configs})
  if(NOT c MATCHES "-DSREH_BUILD_TESTS=ON")
    message(FATAL_ERROR "test.sh: ${c} does not force -DSREH_BUILD_TESTS=ON (a cache from ./demo.sh would turn tests off)")
  endif()
endforeach()
if(NOT test_sh MATCHES "cmake -S \\. -B \"\\$build\" \"\\$\\{config\\[@\\]\\}\"")
  message(FATAL_ERROR "test.sh: the configure line does not pass \${config[@]}")
endif()
if(NOT test_sh MATCHES "ctest [^\n]*--no-tests=error")
  message(FATAL_ERROR "test.sh: ctest without --no-tests=error passes with zero tests")
endif()
# demo.sh shares build/ with test.sh: same build type, so neither undoes the other.
if(NOT demo_sh MATCHES "cmake -S \\. -B build -DCMAKE_BUILD_TYPE=Release")
  message(FATAL_ERROR "demo.sh: expected 'cmake -S . -B build -DCMAKE_BUILD_TYPE=Release ...'")
endif()
# CI runs test.sh (both stages).
file(READ ${SOURCE}/.ci/run ci)
if(NOT ci MATCHES "\\./test\\.sh\n" OR NOT ci MATCHES "\\./test\\.sh --sanitize")
  message(FATAL_ERROR ".ci/run: expected ./test.sh and ./test.sh --sanitize")
endif()
if(NOT ci MATCHES "tests/fuzz/run\\.sh")
  message(FATAL_ERROR ".ci/run: expected the bounded fuzz run tests/fuzz/run.sh")
endif()
