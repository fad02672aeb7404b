# SPDX-License-Identifier: GPL-3.0-or-later
# What every part of the command-line test (test_cli_*.cmake, one ctest each) starts with: a fresh scratch
# directory, the assertions, the shared data and the shells. A part runs the featurerecon program like a user:
# exit codes, error messages, written files.
# -DFEATURERECON=<program> -DDATA=<test/data> -DPROJECT_DATA=<data> -DWORK=<the part's scratch directory>
file(REMOVE_RECURSE ${WORK})
file(MAKE_DIRECTORY ${WORK})

# expect(NAME EXIT_CODE REGEX_ON_OUTPUT args...)
function(expect name code regex)
  execute_process(COMMAND ${FEATURERECON} ${ARGN} RESULT_VARIABLE rc OUTPUT_VARIABLE out ERROR_VARIABLE err)
  set(all "${out}${err}")
  if(NOT rc EQUAL code)
    message(SEND_ERROR "${name}: exit ${rc}, expected ${code}\n${all}")
  elseif(NOT all MATCHES "${regex}")
    message(SEND_ERROR "${name}: output does not match '${regex}':\n${all}")
  else()
    message(STATUS "ok: ${name}")
  endif()
  set(last_output "${out}" PARENT_SCOPE)
  set(last_error "${err}" PARENT_SCOPE)
endfunction()

# expect_same_file(FILE_A FILE_B MESSAGE): the two files hold the same bytes.
function(expect_same_file a b message)
  file(READ ${a} bytes_a HEX)
  file(READ ${b} bytes_b HEX)
  if(NOT bytes_a STREQUAL bytes_b)
    message(SEND_ERROR "${message}: ${a} and ${b} differ")
  endif()
endfunction()

# expect_count(FILE REGEX N): FILE contains REGEX exactly N times.
function(expect_count file regex n)
  file(READ ${file} text)
  string(REGEX MATCHALL "${regex}" found "${text}")
  list(LENGTH found count)
  if(NOT count EQUAL n)
    message(SEND_ERROR "${file}: ${count} matches of '${regex}', expected ${n}")
  endif()
endfunction()

# expect_count_at_least(FILE REGEX N MESSAGE): FILE contains REGEX at least N times.
function(expect_count_at_least file regex n message)
  file(READ ${file} text)
  string(REGEX MATCHALL "${regex}" found "${text}")
  list(LENGTH found count)
  if(count LESS n)
    message(SEND_ERROR "${message}: ${count} matches of '${regex}' in ${file}, expected at least ${n}")
  endif()
endfunction()

# The reference maps of the Chicago benchmark (test/data/chicago_maps).
set(M ${DATA}/chicago_maps/chicago)
# The audit tests' scratch directory.
set(A ${WORK}/audit)
file(MAKE_DIRECTORY ${A})
# Shells for the tests of pipes, signals and file-size limits; those tests are skipped without them.
find_program(SH sh)
find_program(BASH_PROGRAM bash)
