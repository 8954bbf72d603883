# The scale sweep of kontur-cli (issue 17): every command on the same small inputs written at scales
# 1e-300 … 1e300 (the unit-scale coordinates with an exponent appended, so every file holds exactly the
# scaled numbers). Each run must answer: exit code 0 with finite JSON only, or exit code 1 or 2 with a
# message (run_cli.cmake, RC answer). The per-test TIMEOUT is the guard against a command that does not
# return (arc length asked to 1e-9 at 1e7 froze); no time is asserted. convert and info read a document
# holding all 14 curve kinds, and must know each of them (no "cannot be drawn by this version").
# Included from tests/cli/CMakeLists.txt (kontur_cli_test).
set(sweep_dir ${CMAKE_CURRENT_BINARY_DIR}/scalesweep)
file(MAKE_DIRECTORY ${sweep_dir})

# "x y" pairs at unit scale: x increases (a function spline needs that), no three in a line.
set(sweep_knots "0 0;1 2;3 3;4 1;6 2")
set(sweep_four "0 0;1 2;3 3;4 1")

# Writes the pairs of `pairs` scaled by 10^exp as "xeEXP yeEXP" lines (points text) or CSV rows.
function(sweep_points_file path pairs exp csv)
  set(text "")
  if(csv)
    set(text "x,y\n")
  endif()
  foreach(pair IN LISTS pairs)
    string(REPLACE " " ";" xy "${pair}")
    list(GET xy 0 x)
    list(GET xy 1 y)
    if(csv)
      string(APPEND text "${x}e${exp},${y}e${exp}\n")
    else()
      string(APPEND text "${x}e${exp} ${y}e${exp}\n")
    endif()
  endforeach()
  file(WRITE ${path} "${text}")
endfunction()

# A JSON array of points scaled by 10^exp.
function(sweep_json_points out pairs exp)
  set(items "")
  foreach(pair IN LISTS pairs)
    string(REPLACE " " ";" xy "${pair}")
    list(GET xy 0 x)
    list(GET xy 1 y)
    list(APPEND items "[${x}e${exp},${y}e${exp}]")
  endforeach()
  list(JOIN items "," joined)
  set(${out} "[${joined}]" PARENT_SCOPE)
endfunction()

# The 14 kinds of src/io/records.cpp, each with a well-formed record (docs/file-formats.md; settings as
# models/document/documentio.cpp writes them: tangentEnds for clamped, global-bspline and hermite, order for bspline).
function(sweep_document path exp)
  sweep_json_points(knots "${sweep_knots}" ${exp})
  sweep_json_points(four "${sweep_four}" ${exp})
  # A composite curve of 3 knots: its 7-point control vector (handles collinear through each knot).
  sweep_json_points(control "0 0;1 1;2 1;3 0;4 -1;5 -1;6 0" ${exp})
  sweep_json_points(ends "1 1;1 -1" ${exp})
  sweep_json_points(tangents "1 1;1 1;1 0;1 -1;1 1" ${exp})
  set(curves
    "{\"kind\":\"bezier\",\"points\":${four}}"
    "{\"kind\":\"interpolating\",\"parameterization\":\"chord\",\"points\":${four}}"
    "{\"kind\":\"least-squares\",\"parameterization\":\"centripetal\",\"points\":${knots}}"
    "{\"kind\":\"composite\",\"points\":${control},\"nodeTypes\":[\"smooth\",\"symmetric\",\"corner\"]}"
    "{\"kind\":\"natural\",\"parameterization\":\"chord\",\"points\":${knots}}"
    "{\"kind\":\"clamped\",\"parameterization\":\"chord\",\"points\":${knots},\"settings\":{\"tangentEnds\":${ends}}}"
    "{\"kind\":\"not-a-knot\",\"parameterization\":\"uniform\",\"points\":${knots}}"
    "{\"kind\":\"periodic\",\"parameterization\":\"centripetal\",\"points\":${knots}}"
    "{\"kind\":\"catmull-rom\",\"parameterization\":\"centripetal\",\"points\":${knots}}"
    "{\"kind\":\"hermite\",\"parameterization\":\"chord\",\"points\":${knots},\"settings\":{\"tangentEnds\":${tangents}}}"
    "{\"kind\":\"bspline\",\"points\":${knots},\"settings\":{\"order\":4}}"
    "{\"kind\":\"global-bspline\",\"parameterization\":\"chord\",\"points\":${knots},\"settings\":{\"tangentEnds\":${ends}}}"
    "{\"kind\":\"polynomial\",\"parameterization\":\"uniform\",\"points\":${knots}}"
    "{\"kind\":\"function-spline\",\"points\":${knots}}")
  list(JOIN curves ",\n  " joined)
  file(WRITE ${path} "{\"format\":\"kontur\",\"version\":1,\"units\":\"mm\",\"curves\":[\n  ${joined}\n]}\n")
endfunction()

set(KONTUR_SWEEP_TIMEOUT 20)
foreach(exp -300 -170 -6 0 6 7 160 300)
  set(s "1e${exp}")
  set(d ${sweep_dir}/${s})
  file(MAKE_DIRECTORY ${d})
  sweep_points_file(${d}/knots.txt "${sweep_knots}" ${exp} OFF)
  sweep_points_file(${d}/four.txt "${sweep_four}" ${exp} OFF)
  sweep_points_file(${d}/knots.csv "${sweep_knots}" ${exp} ON)
  sweep_document(${d}/kinds.kontur ${exp})
  set(unknown_kind "cannot be drawn by this version|unsupported-kind")
  # Each entry: a name and the command line; RC answer for all, with the kind check on convert and info.
  set(runs
    "fit_ls|fit|--in|${d}/knots.txt"
    "fit_interpolate|fit|--method|interpolate|--param|centripetal|--in|${d}/four.txt"
    "bezier|bezier|--in|${d}/four.txt|--at|0,0.5,1|--length|1e-9|--nearest|2e${exp},5e${exp}|--bbox|--elevate|2"
    "composite|composite|--in|${d}/knots.txt"
    "composite_closed|composite|--closed|--in|${d}/knots.txt"
    "spline_function|spline|--kind|natural|--function|--at|2e${exp}|--in|${d}/knots.txt"
    "info_document|info|${d}/kinds.kontur"
    "info_csv|info|--kind|least-squares|${d}/knots.csv"
    "convert_kontur|convert|${d}/kinds.kontur|${d}/out.kontur"
    "convert_svg|convert|${d}/kinds.kontur|${d}/out.svg"
    "convert_txt|convert|${d}/kinds.kontur|${d}/out.txt"
    "convert_csv|convert|--curve|4|${d}/kinds.kontur|${d}/out.csv"
    "convert_txt_to_svg|convert|--kind|natural|${d}/knots.txt|${d}/natural.svg")
  foreach(kind natural clamped not-a-knot periodic catmull-rom hermite bspline global-bspline polynomial)
    list(APPEND runs "spline_${kind}|spline|--kind|${kind}|--at|0|--in|${d}/knots.txt")
  endforeach()
  foreach(op bezier-length bezier-nearest fit-ls spline-natural)
    list(APPEND runs "bench_${op}|bench|${op}|--n|8|--repeat|1|--scale|${s}")
  endforeach()
  foreach(run IN LISTS runs)
    string(REPLACE "|" ";" parts "${run}")
    list(POP_FRONT parts name)
    set(extra)
    if(name MATCHES "^(info|convert)")
      list(APPEND extra OUT_NOT "${unknown_kind}" ERR_NOT "${unknown_kind}")
    endif()
    if(name STREQUAL "convert_txt")
      list(APPEND extra REMOVE ${d}/out.txt)
    endif()
    kontur_cli_test(sweep_${name}_${s} ARGS ${parts} RC answer TIMEOUT ${KONTUR_SWEEP_TIMEOUT} ${extra})
  endforeach()
endforeach()

# Representable answers are computed, and scale with the input: the cubic of four.txt has the length
# 5.37001561905193… at unit scale (Simpson's rule with 40,000 intervals, independent of Kontur), so
# 5.37001561905193e-300 at 1e-300, asked to a relative 1e-12 and checked to a relative 1e-9; its x
# extent is 0 … 4 exactly (x' > 0).
foreach(exp -300 -170 -6 0 6 7 160 300)
  set(s "1e${exp}")
  math(EXPR accuracy "${exp} - 12")
  kontur_cli_test(sweep_bezier_length_${s} ARGS bezier --in ${sweep_dir}/${s}/four.txt --length 1e${accuracy} --bbox
    RC 0 TIMEOUT ${KONTUR_SWEEP_TIMEOUT}
    RANGES length=5.370015614e${exp}:5.370015624e${exp} bbox.0.0=0:0 bbox.1.0=4e${exp}:4e${exp})
endforeach()

# At the scales doubles handle without trouble the document is an answer, not an error: every kind's
# shape, a length and a bounding box (the error path of the sweep cannot hide a broken command there).
foreach(s 1e-6 1e0 1e6)
  kontur_cli_test(sweep_info_all_kinds_${s} ARGS info ${sweep_dir}/${s}/kinds.kontur RC 0
    TIMEOUT ${KONTUR_SWEEP_TIMEOUT} OUT_NOT "\"error\"" LENGTHS curves=14
    CHECKS curves.0.kind=bezier curves.13.kind=function-spline curves.4.segments=4)
endforeach()
