# Installs the build tree into a scratch prefix, then configures, builds and runs a tiny
# project that uses find_package(hypergas); with PYTHON and PYTHON_DIR, imports the installed
# Python package from <prefix>/PYTHON_DIR and runs a DSMC gas. Fails on any non-zero step.
file(REMOVE_RECURSE ${WORK_DIR})
function(step)
  execute_process(COMMAND ${ARGN} RESULT_VARIABLE rc OUTPUT_VARIABLE out ERROR_VARIABLE err)
  if(NOT rc EQUAL 0)
    message(FATAL_ERROR "step failed (${rc}): ${ARGN}\n${out}\n${err}")
  endif()
  message(STATUS "${out}")
endfunction()
step(${CMAKE_COMMAND} --install ${BUILD_DIR} --prefix ${WORK_DIR}/prefix --component Unspecified)
step(${CMAKE_COMMAND} -S ${CONSUMER_DIR} -B ${WORK_DIR}/build -DCMAKE_PREFIX_PATH=${WORK_DIR}/prefix)
step(${CMAKE_COMMAND} --build ${WORK_DIR}/build)
step(${WORK_DIR}/build/consumer)
if(PYTHON)
  step(${CMAKE_COMMAND} -E env PYTHONPATH=${WORK_DIR}/prefix/${PYTHON_DIR} ${PYTHON} -c
       "import hypergas\ng = hypergas.DSMC(dim=3, n=1000).run(1.0)\nassert g.collisions > 0\nprint(hypergas.__file__)")
endif()
