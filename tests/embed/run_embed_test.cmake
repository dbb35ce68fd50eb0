# Installs the build tree into a scratch prefix, then configures, builds and runs
# tests/embed against it as a separate CMake project.
set(_prefix ${BINARY_DIR}/embed-test/prefix)
set(_build ${BINARY_DIR}/embed-test/build)
file(REMOVE_RECURSE ${BINARY_DIR}/embed-test)
# A sanitizer build's libraries need the sanitizer runtime in the outside program too.
set(_flags "")
if(SANITIZE)
  set(_flags "-DCMAKE_CXX_FLAGS=-fsanitize=address,undefined;-DCMAKE_EXE_LINKER_FLAGS=-fsanitize=address,undefined")
endif()
foreach(_step
    "${CMAKE_COMMAND};--install;${BINARY_DIR};--prefix;${_prefix}"
    "${CMAKE_COMMAND};-S;${SOURCE_DIR}/tests/embed;-B;${_build};-G;${GENERATOR};-DCMAKE_PREFIX_PATH=${_prefix};${_flags}"
    "${CMAKE_COMMAND};--build;${_build}"
    "${_build}/embed_check")
  execute_process(COMMAND ${_step} RESULT_VARIABLE _rc OUTPUT_VARIABLE _out ERROR_VARIABLE _err)
  message("${_out}")
  if(NOT _rc EQUAL 0)
    message(FATAL_ERROR "embed test step failed (${_rc}): ${_step}\n${_err}")
  endif()
endforeach()
