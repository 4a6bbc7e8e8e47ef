# Compiles SRC (syntax only) with CXX. With EXPECT set, the compilation must fail and the
# compiler's message must contain EXPECT (the name of the missing capability); without it,
# the compilation must succeed (the control that shows the snippet is otherwise fine).
execute_process(COMMAND ${CXX} -std=c++20 -fsyntax-only ${FLAGS} -I${INC} ${SRC}
                RESULT_VARIABLE rc OUTPUT_VARIABLE out ERROR_VARIABLE err)
if(EXPECT)
  if(rc EQUAL 0)
    message(FATAL_ERROR "${SRC} compiled, but it should be rejected for lacking ${EXPECT}")
  endif()
  string(FIND "${err}" "${EXPECT}" at)
  if(at EQUAL -1)
    message(FATAL_ERROR "${SRC} was rejected, but the message does not name ${EXPECT}:\n${err}")
  endif()
  message(STATUS "rejected as expected, naming ${EXPECT}")
else()
  if(NOT rc EQUAL 0)
    message(FATAL_ERROR "${SRC} should compile:\n${err}")
  endif()
endif()
