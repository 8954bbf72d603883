# Runs a program once (kontur-cli, or kontur for its command line) and checks its exit code, its
# stderr and its output (ctest -P script). The exit code is always checked: a matching output with the
# wrong exit code fails (ctest's PASS_REGULAR_EXPRESSION alone would ignore it).
# -DEXE=path -DARGS="a|b|c" -DRC=0|nonzero|answer|<n> [-DREMOVE=file] [-DERR_REGEX=...] [-DOUT_REGEX=...] [-DERR_NOT=...] [-DOUT_NOT=...]
# [-DTEXT=ON] [-DCHECKS="path.to.0=value|path=value"] [-DRANGES="path=lo:hi|..."] [-DLENGTHS="params=6|..."]:
# without TEXT, stdout of a successful run must be one JSON object with finite numbers only (no null,
# which is what a non-finite number would become). CHECKS compare the JSON value at a dotted path as
# text as CMake re-prints it (exact for short numbers like 0.75 and for strings); RANGES check that a
# number lies in [lo, hi] (a tolerance for values that are not exact); LENGTHS compare array lengths.
string(REPLACE "|" ";" args "${ARGS}")
if(DEFINED REMOVE)
  file(REMOVE "${REMOVE}") # an output the command appends to (points text), so that each run starts anew
endif()
execute_process(COMMAND "${EXE}" ${args} RESULT_VARIABLE rc OUTPUT_VARIABLE out ERROR_VARIABLE err)

if(RC STREQUAL "answer")
  # Either a result (exit code 0, checked below: finite JSON) or the error convention: exit code 1 (bad
  # input) or 2 (bad usage) with a message on stderr and nothing on stdout. A crash is neither.
  if(NOT rc EQUAL 0)
    if(NOT (rc EQUAL 1 OR rc EQUAL 2))
      message(FATAL_ERROR "expected exit code 0, 1 or 2, got '${rc}'; stderr: ${err}")
    endif()
    if(NOT err MATCHES "^kontur-cli: [^\n]+" OR NOT out STREQUAL "")
      message(FATAL_ERROR "exit code ${rc} without a message on stderr (or with output): stdout: ${out} stderr: ${err}")
    endif()
  endif()
elseif(RC STREQUAL "nonzero")
  if(rc EQUAL 0)
    message(FATAL_ERROR "expected a failure, got exit code 0; stdout: ${out}")
  endif()
elseif(NOT rc EQUAL RC)
  message(FATAL_ERROR "expected exit code ${RC}, got ${rc}; stderr: ${err}")
endif()
if(DEFINED OUT_REGEX AND NOT out MATCHES "${OUT_REGEX}")
  message(FATAL_ERROR "stdout does not match '${OUT_REGEX}': ${out}")
endif()
if(DEFINED ERR_REGEX AND NOT err MATCHES "${ERR_REGEX}")
  message(FATAL_ERROR "stderr does not match '${ERR_REGEX}': ${err}")
endif()
if(DEFINED OUT_NOT AND out MATCHES "${OUT_NOT}")
  message(FATAL_ERROR "stdout matches '${OUT_NOT}', which it must not: ${out}")
endif()
if(DEFINED ERR_NOT AND err MATCHES "${ERR_NOT}")
  message(FATAL_ERROR "stderr matches '${ERR_NOT}', which it must not: ${err}")
endif()

if(rc EQUAL 0 AND NOT TEXT)
  # Parsing the whole document proves it is valid JSON.
  string(JSON type ERROR_VARIABLE jsonError TYPE "${out}")
  if(jsonError OR NOT type STREQUAL "OBJECT")
    message(FATAL_ERROR "stdout is not a JSON object (${jsonError}): ${out}")
  endif()
  # Finite numbers only: outside the strings, no null (nor NaN or Infinity, which are not JSON).
  string(REGEX REPLACE "\"([^\"\\]|\\.)*\"" "\"\"" bare "${out}")
  if(bare MATCHES "null|nan|NaN|inf|Inf")
    message(FATAL_ERROR "exit code 0 with a non-finite number (${CMAKE_MATCH_0}) in the output: ${out}")
  endif()
endif()

# The JSON at a dotted path of stdout into `result`: its value (what = GET) or an array's length
# (what = LENGTH); a missing path fails the test.
function(json_at what path result)
  string(REPLACE "." ";" keys "${path}")
  string(JSON actual ERROR_VARIABLE jsonError ${what} "${out}" ${keys})
  if(jsonError)
    message(FATAL_ERROR "no ${path} in the output (${jsonError}): ${out}")
  endif()
  set(${result} "${actual}" PARENT_SCOPE)
endfunction()

# Fails unless the JSON at `path` is `expected`: its value as text (what = GET) or an array's length
# (what = LENGTH).
function(expect_json what path expected)
  json_at(${what} "${path}" actual)
  if(what STREQUAL "LENGTH")
    if(NOT actual EQUAL expected)
      message(FATAL_ERROR "${path}: expected length ${expected}, got ${actual}")
    endif()
  elseif(NOT actual STREQUAL expected)
    message(FATAL_ERROR "${path}: expected ${expected}, got ${actual}")
  endif()
endfunction()

# CHECKS (path=value) and LENGTHS (path=n).
foreach(what IN ITEMS GET LENGTH)
  if(what STREQUAL "GET")
    string(REPLACE "|" ";" checks "${CHECKS}")
  else()
    string(REPLACE "|" ";" checks "${LENGTHS}")
  endif()
  foreach(check IN LISTS checks)
    string(REGEX MATCH "^([^=]+)=(.*)$" _ "${check}")
    expect_json(${what} "${CMAKE_MATCH_1}" "${CMAKE_MATCH_2}")
  endforeach()
endforeach()

string(REPLACE "|" ";" ranges "${RANGES}")
foreach(check IN LISTS ranges)
  if(NOT check MATCHES "^([^=]+)=([^:]+):(.+)$")
    message(FATAL_ERROR "malformed range check '${check}' (path=lo:hi)")
  endif()
  set(path "${CMAKE_MATCH_1}")
  set(lo "${CMAKE_MATCH_2}")
  set(hi "${CMAKE_MATCH_3}")
  json_at(GET "${path}" actual)
  # if() compares numbers as doubles (sscanf "%lg"); a non-number fails both comparisons.
  if(NOT (actual GREATER_EQUAL lo AND actual LESS_EQUAL hi))
    message(FATAL_ERROR "${path}: expected a number in [${lo}, ${hi}], got ${actual}")
  endif()
endforeach()
