# Runs PROGRAM with ARGS and --out OUT; passes only when it exits 2, says "error:" and
# writes nothing (OUT does not exist afterwards). Used by the water guard-rail tests.
file(REMOVE_RECURSE "${OUT}")
execute_process(COMMAND "${PROGRAM}" ${ARGS} --out "${OUT}" RESULT_VARIABLE rc OUTPUT_VARIABLE out ERROR_VARIABLE err)
if(NOT rc EQUAL 2)
  message(FATAL_ERROR "expected exit 2, got ${rc}\nstdout: ${out}\nstderr: ${err}")
endif()
if(NOT err MATCHES "error:")
  message(FATAL_ERROR "expected an error message on stderr, got: ${err}")
endif()
if(EXISTS "${OUT}")
  message(FATAL_ERROR "${OUT} was written")
endif()
message(STATUS "${err}")
