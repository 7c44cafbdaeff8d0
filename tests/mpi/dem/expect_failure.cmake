# expect_failure.cmake: run `MPIEXEC NPFLAG NP EXE ARGS...` (ARGS separated by
# '|') and pass only if it exits non-zero, within 30 s, with stderr matching
# the regular expression EXPECT. Used for LIGGGHTS' error path, where the
# failure itself is the expected behaviour.
string(REPLACE "|" ";" args "${ARGS}")
execute_process(COMMAND ${MPIEXEC} ${NPFLAG} ${NP} ${EXE} ${args}
                RESULT_VARIABLE rc OUTPUT_VARIABLE out ERROR_VARIABLE err TIMEOUT 30)
message("exit: ${rc}\n--- stdout ---\n${out}--- stderr ---\n${err}--------------")
if(rc MATCHES "timeout")
  message(FATAL_ERROR "the job hung: no exit within 30 s")
endif()
if(rc EQUAL 0)
  message(FATAL_ERROR "the job exited with 0; a LIGGGHTS error must give a non-zero exit")
endif()
if(NOT err MATCHES "${EXPECT}")
  message(FATAL_ERROR "stderr does not contain /${EXPECT}/")
endif()
message("OK: non-zero exit (${rc}) and stderr matches /${EXPECT}/")
