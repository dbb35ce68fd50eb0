# Runs a code example of a document as written there, so that the docs cannot drift from
# the programs. An example is the fenced code block right after a line
# "<!-- example: NAME -->" in the document.
#   -DKIND=sh:    runs the block with bash in the source tree; "build/" means the build
#                 folder, "out/" a scratch folder; fails on a non-zero exit or an
#                 {"error": ...} answer (fsi-step).
#   -DKIND=embed: installs the build into a scratch prefix, then configures, builds and
#                 runs a CMake project made of the blocks CMAKE (CMakeLists.txt) and CPP
#                 (main.cpp) against it.
# Inputs: -DSOURCE_DIR -DBINARY_DIR -DDOC=<file in the source tree> -DKIND and
#   -DEXAMPLE=<name> (sh) or -DCMAKE_EXAMPLE=<name> -DCPP_EXAMPLE=<name> -DGENERATOR
#   -DSANITIZE (embed).

function(doc_example name out_var)
  file(READ ${SOURCE_DIR}/${DOC} _text)
  set(_marker "<!-- example: ${name} -->")
  string(FIND "${_text}" "${_marker}" _at)
  if(_at LESS 0)
    message(FATAL_ERROR "${DOC}: no example marked '${_marker}'")
  endif()
  string(SUBSTRING "${_text}" ${_at} -1 _text)
  string(FIND "${_text}" "```" _open)
  string(SUBSTRING "${_text}" ${_open} -1 _text)
  string(FIND "${_text}" "\n" _eol)       # end of the opening fence line
  math(EXPR _eol "${_eol} + 1")
  string(SUBSTRING "${_text}" ${_eol} -1 _text)
  string(FIND "${_text}" "\n```" _close)
  if(_close LESS 0)
    message(FATAL_ERROR "${DOC}: the example '${name}' has no closing fence")
  endif()
  math(EXPR _close "${_close} + 1")
  string(SUBSTRING "${_text}" 0 ${_close} _code)
  set(${out_var} "${_code}" PARENT_SCOPE)
endfunction()

get_filename_component(_doc_name ${DOC} NAME_WE)
set(_tmp ${BINARY_DIR}/test_tmp/doc_examples/${_doc_name})

if(KIND STREQUAL "sh")
  doc_example(${EXAMPLE} _code)
  set(_dir ${_tmp}/${EXAMPLE})
  file(REMOVE_RECURSE ${_dir})
  file(MAKE_DIRECTORY ${_dir}/out)
  # build/... -> the build folder, out/... -> the scratch folder (word starts only).
  string(REGEX REPLACE "(^|[ \t\n'\"=|])build/" "\\1${BINARY_DIR}/" _code "${_code}")
  string(REGEX REPLACE "(^|[ \t\n'\"=|])out/" "\\1${_dir}/out/" _code "${_code}")
  file(WRITE ${_dir}/example.sh "set -euo pipefail\n${_code}")
  message("running ${DOC}'s example '${EXAMPLE}':\n${_code}")
  execute_process(COMMAND bash ${_dir}/example.sh WORKING_DIRECTORY ${SOURCE_DIR}
    OUTPUT_VARIABLE _stdout ERROR_VARIABLE _stderr RESULT_VARIABLE _rc TIMEOUT 240)
  message("${_stdout}")
  if(NOT _rc EQUAL 0)
    message(FATAL_ERROR "${DOC}'s example '${EXAMPLE}' exited with ${_rc}:\n${_stderr}")
  endif()
  if(_stdout MATCHES "\"error\"")
    message(FATAL_ERROR "${DOC}'s example '${EXAMPLE}' answered with an error")
  endif()
  file(GLOB_RECURSE _made RELATIVE ${_dir}/out ${_dir}/out/*)
  list(LENGTH _made _n)
  if(_code MATCHES "out/" AND _n EQUAL 0)
    message(FATAL_ERROR "${DOC}'s example '${EXAMPLE}' wrote nothing into out/")
  endif()
  message("${DOC}'s example '${EXAMPLE}' ran; ${_n} file(s) written")
elseif(KIND STREQUAL "embed")
  doc_example(${CMAKE_EXAMPLE} _cmake)
  doc_example(${CPP_EXAMPLE} _cpp)
  set(_dir ${_tmp}/${CPP_EXAMPLE})
  set(_prefix ${_dir}/prefix)
  file(REMOVE_RECURSE ${_dir})
  file(WRITE ${_dir}/src/CMakeLists.txt "${_cmake}")
  file(WRITE ${_dir}/src/main.cpp "${_cpp}")
  set(_flags "")
  if(SANITIZE)
    set(_flags "-DCMAKE_CXX_FLAGS=-fsanitize=address,undefined;-DCMAKE_EXE_LINKER_FLAGS=-fsanitize=address,undefined")
  endif()
  file(STRINGS ${_dir}/src/CMakeLists.txt _exe REGEX "^add_executable\\(")
  string(REGEX REPLACE "^add_executable\\(([A-Za-z0-9_-]+).*" "\\1" _exe "${_exe}")
  foreach(_step
      "${CMAKE_COMMAND};--install;${BINARY_DIR};--prefix;${_prefix}"
      "${CMAKE_COMMAND};-S;${_dir}/src;-B;${_dir}/build;-G;${GENERATOR};-DCMAKE_BUILD_TYPE=Release;-DCMAKE_PREFIX_PATH=${_prefix};${_flags}"
      "${CMAKE_COMMAND};--build;${_dir}/build"
      "${_dir}/build/${_exe};${_dir}/run")
    execute_process(COMMAND ${_step} WORKING_DIRECTORY ${_dir}
      RESULT_VARIABLE _rc OUTPUT_VARIABLE _out ERROR_VARIABLE _err TIMEOUT 600)
    if(NOT _rc EQUAL 0)
      message(FATAL_ERROR "${DOC}'s examples '${CMAKE_EXAMPLE}' + '${CPP_EXAMPLE}': step failed (${_rc}): ${_step}\n${_out}\n${_err}")
    endif()
  endforeach()
  message("${_out}")
  message("${DOC}'s examples '${CMAKE_EXAMPLE}' + '${CPP_EXAMPLE}' built against the installed package and ran")
else()
  message(FATAL_ERROR "doc_examples.cmake: KIND must be sh or embed, not '${KIND}'")
endif()
