# The app's room rule (cmake/fiberbridge_layers.cmake) must refuse what it is there to refuse.
# Run as a ctest: cmake -DSOURCE=<repo> -DWORK=<scratch dir> -P app_rooms_check.cmake.
# It copies source/app and include/fiberbridge/app to WORK, checks the copy is clean, then plants
# one violation of each kind (an output including an item, run including an item's private
# header, a file in no room) and expects each to stop the check naming its file.
cmake_minimum_required(VERSION 3.20)

file(REMOVE_RECURSE ${WORK})
file(COPY ${SOURCE}/source/app DESTINATION ${WORK}/source)
file(COPY ${SOURCE}/include/fiberbridge/app DESTINATION ${WORK}/include/fiberbridge)

function(expect_check should_pass planted)
  execute_process(COMMAND ${CMAKE_COMMAND} -DPROJECT_SOURCE_DIR=${WORK}
                          -DLAYERS=${SOURCE}/cmake/fiberbridge_layers.cmake
                          -P ${SOURCE}/tests/app/app_rooms_run.cmake
                  RESULT_VARIABLE rc OUTPUT_VARIABLE out ERROR_VARIABLE err)
  if(should_pass AND NOT rc EQUAL 0)
    message(FATAL_ERROR "the clean tree was refused:\n${err}")
  endif()
  if(NOT should_pass)
    if(rc EQUAL 0)
      message(FATAL_ERROR "planted ${planted} was not refused")
    endif()
    string(FIND "${err}" "${planted}" at)
    if(at EQUAL -1)
      message(FATAL_ERROR "planted ${planted}, but the refusal does not name it:\n${err}")
    endif()
  endif()
endfunction()

expect_check(TRUE "")

set(f ${WORK}/source/app/outputs/text_report.cc)
file(READ ${f} original)
file(APPEND ${f} "#include \"fiberbridge/app/items/items.h\"\n")
expect_check(FALSE "source/app/outputs/text_report.cc")
file(WRITE ${f} "${original}")

set(f ${WORK}/source/app/run/resume_store.cc)
file(READ ${f} original)
file(APPEND ${f} "#include \"items/chain_study_item.h\"\n")
expect_check(FALSE "source/app/run/resume_store.cc")
file(WRITE ${f} "${original}")

file(WRITE ${WORK}/source/app/stray.cc "// in no room\n")
expect_check(FALSE "source/app/stray.cc")
file(REMOVE ${WORK}/source/app/stray.cc)

expect_check(TRUE "")
file(REMOVE_RECURSE ${WORK})
