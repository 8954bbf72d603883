# Configures tests/fuzz as its own project with clang++, builds it and runs every target for a bounded
# time on the seed corpus of tests/data/fuzz (ctest -P script).
# -DSOURCE=<tests/fuzz> -DBINARY=<build dir> -DCORPUS=<tests/data/fuzz> [-DSEEDS=<tests/fuzz/seeds>]
# -DSECONDS=<per target> -DCXX=<clang++>
if(NOT CXX OR NOT EXISTS "${CXX}")
  message(FATAL_ERROR "clang++ not found (CXX='${CXX}'): install clang and libclang-rt-14-dev (packaging/bootstrap "
                      "does); the fuzz test fails rather than pass unrun")
endif()
execute_process(COMMAND ${CMAKE_COMMAND} -S ${SOURCE} -B ${BINARY} -G Ninja -DCMAKE_CXX_COMPILER=${CXX}
                        -DCMAKE_BUILD_TYPE=RelWithDebInfo RESULT_VARIABLE rc OUTPUT_QUIET)
if(NOT rc EQUAL 0)
  message(FATAL_ERROR "configuring the fuzz targets failed")
endif()
execute_process(COMMAND ${CMAKE_COMMAND} --build ${BINARY} -j 2 RESULT_VARIABLE rc OUTPUT_VARIABLE out ERROR_VARIABLE out)
if(NOT rc EQUAL 0)
  message(FATAL_ERROR "building the fuzz targets failed:\n${out}")
endif()
foreach(target pointstext csv document svg dxf allowance)
  set(work ${BINARY}/corpus/${target})
  file(MAKE_DIRECTORY ${work})
  # New inputs go to the build tree's corpus (first directory); the seeds stay as they are. A fixed
  # random seed keeps the suite's runs alike; longer runs with other seeds are for hunting by hand.
  # The seeds at the scale extremes (tests/fuzz/seeds: 1e-300, 1e300, 1e308, subnormals, -0) beside the corpus.
  set(seeds)
  if(DEFINED SEEDS AND IS_DIRECTORY ${SEEDS}/${target})
    set(seeds ${SEEDS}/${target})
  endif()
  execute_process(COMMAND ${BINARY}/fuzz_${target} -seed=1 -max_total_time=${SECONDS} -rss_limit_mb=1536 -timeout=10
                          -print_final_stats=1 ${work} ${CORPUS}/${target} ${seeds}
                  RESULT_VARIABLE rc OUTPUT_VARIABLE out ERROR_VARIABLE out)
  if(NOT rc EQUAL 0)
    message(FATAL_ERROR "fuzz_${target} found a problem (exit ${rc}):\n${out}")
  endif()
  string(REGEX MATCH "stat::number_of_executed_units: [0-9]+" runs "${out}")
  message(STATUS "fuzz_${target}: ${runs}")
endforeach()
