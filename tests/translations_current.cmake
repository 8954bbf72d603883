# Fails when a user-visible string of the sources is missing from the .ts files: lupdate runs over the
# sources into copies of the translation files, which must then still be complete.
file(GLOB ts_files "${SRC}/i18n/kontur_*.ts")
file(REMOVE_RECURSE "${WORK}")
file(MAKE_DIRECTORY "${WORK}")
file(COPY ${ts_files} DESTINATION "${WORK}")
file(GLOB copies "${WORK}/kontur_*.ts")
file(GLOB sources "${SRC}/qml/*.qml" "${SRC}/src/app/*.cpp" "${SRC}/src/cli/*.cpp" "${SRC}/src/cli/*.h"
     "${SRC}/src/print/*.cpp" "${SRC}/models/*/*.cpp"
     "${SRC}/models/*/*.h" "${SRC}/src/app/*.h")
execute_process(COMMAND "${LUPDATE}" ${sources} "-I${SRC}" -ts ${copies} -no-obsolete -locations none -silent
                RESULT_VARIABLE result)
if(NOT result EQUAL 0)
  message(FATAL_ERROR "lupdate failed (${result})")
endif()
# English keeps only plural forms (i18n/plurals/kontur_en.ts, lupdate -pluralonly).
file(COPY "${SRC}/i18n/plurals/kontur_en.ts" DESTINATION "${WORK}")
execute_process(COMMAND "${LUPDATE}" ${sources} "-I${SRC}" -ts "${WORK}/kontur_en.ts" -pluralonly -no-obsolete
                        -locations none -silent
                RESULT_VARIABLE result)
if(NOT result EQUAL 0)
  message(FATAL_ERROR "lupdate -pluralonly failed (${result})")
endif()
set(TS_DIR "${WORK}")
include("${CMAKE_CURRENT_LIST_DIR}/translations_complete.cmake")
