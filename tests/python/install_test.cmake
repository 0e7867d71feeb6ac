# Run by CTest (tests/python/CMakeLists.txt): installs the Python module of the build tree
# BUILD_DIR (component `python`) into WORK_DIR/prefix, then imports it from
# WORK_DIR/prefix/MODULE_DIR with PYTHON and checks a tetrahedron there: the module must
# come from the prefix, not the build tree, and must work. Fails on any step's non-zero exit.
file(REMOVE_RECURSE ${WORK_DIR})
function(step)
  execute_process(COMMAND ${ARGN} RESULT_VARIABLE rc OUTPUT_VARIABLE out ERROR_VARIABLE err)
  message(STATUS "${out}")
  if(NOT rc EQUAL 0)
    message(FATAL_ERROR "failed (${rc}): ${ARGN}\n${out}\n${err}")
  endif()
endfunction()
step(${CMAKE_COMMAND} --install ${BUILD_DIR} --prefix ${WORK_DIR}/prefix --component python)
set(site ${WORK_DIR}/prefix/${MODULE_DIR})
step(${CMAKE_COMMAND} -E env PYTHONPATH=${site} ${PYTHON} -c
     "import pdr, pathlib; \
assert pathlib.Path(pdr.__file__).parent == pathlib.Path('${site}'), pdr.__file__; \
r = pdr.check([[0,0,0],[1,0,0],[0,1,0],[0,0,1]], [[0,1,2,3]]); \
assert r['ok'], r; print(pdr.__file__, pdr.__version__)")
