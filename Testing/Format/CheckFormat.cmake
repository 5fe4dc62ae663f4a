# clang-format --dry-run -Werror over the C++ sources of Module, Testing, Support, Benchmarks
# and Examples.
#   cmake -DCLANG_FORMAT=... -DSOURCE_DIR=... -P CheckFormat.cmake
if (NOT CLANG_FORMAT)
  message(FATAL_ERROR "clang-format was not found: install it (apt-get install clang-format; "
    "./build.sh does) and configure again")
endif ()
file(GLOB_RECURSE sources RELATIVE "${SOURCE_DIR}"
  "${SOURCE_DIR}/Module/*.cxx" "${SOURCE_DIR}/Module/*.h"
  "${SOURCE_DIR}/Testing/*.cxx" "${SOURCE_DIR}/Testing/*.h"
  "${SOURCE_DIR}/Support/*.h"
  "${SOURCE_DIR}/Benchmarks/*.cxx" "${SOURCE_DIR}/Benchmarks/*.h"
  "${SOURCE_DIR}/Examples/*.cxx" "${SOURCE_DIR}/Examples/*.h")
execute_process(COMMAND "${CLANG_FORMAT}" --dry-run -Werror ${sources}
  WORKING_DIRECTORY "${SOURCE_DIR}" RESULT_VARIABLE result ERROR_VARIABLE errors)
if (NOT result EQUAL 0)
  message(FATAL_ERROR "not formatted as .clang-format asks (run clang-format -i on them):\n${errors}")
endif ()
list(LENGTH sources count)
message(STATUS "${count} files formatted")
