# cmake -DCXX=... -DSOURCE=... -DINCLUDE=... -DEXPECT="a|b|c" -P expect_compile_error.cmake
# Passes when SOURCE fails to compile and the compiler's output contains every EXPECT string,
# and the same SOURCE compiles with -DHMIRA_SNIPPET_OK (the capability supplied), which shows
# the failure is due to the missing capability and nothing else.
execute_process(COMMAND ${CXX} -std=c++20 -fsyntax-only -I${INCLUDE} ${SOURCE}
                RESULT_VARIABLE rc OUTPUT_VARIABLE out ERROR_VARIABLE err)
if(rc EQUAL 0)
  message(FATAL_ERROR "${SOURCE} compiled, but it must be rejected")
endif()
string(REPLACE "|" ";" expected "${EXPECT}")
foreach(text IN LISTS expected)
  string(FIND "${out}${err}" "${text}" at)
  if(at EQUAL -1)
    message(FATAL_ERROR "the compiler's message does not mention '${text}':\n${err}")
  endif()
endforeach()
execute_process(COMMAND ${CXX} -std=c++20 -fsyntax-only -DHMIRA_SNIPPET_OK -I${INCLUDE} ${SOURCE}
                RESULT_VARIABLE ok_rc ERROR_VARIABLE ok_err)
if(NOT ok_rc EQUAL 0)
  message(FATAL_ERROR "${SOURCE} with the capability supplied still fails:\n${ok_err}")
endif()
message(STATUS "rejected as expected, naming: ${EXPECT}")
