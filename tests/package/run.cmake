# The ctest test install_package (cmake -P): installs the build BUILD_DIR (config CONFIG) into
# WORK_DIR/prefix, configures and builds the outside project PROJECT_DIR (this folder) against it
# with GENERATOR and the compiler CXX, runs it, and removes WORK_DIR again. Fails on any error.
foreach(var BUILD_DIR CONFIG PROJECT_DIR WORK_DIR GENERATOR CXX)
  if(NOT DEFINED ${var})
    message(FATAL_ERROR "run.cmake: -D${var}=... is missing")
  endif()
endforeach()
set(prefix ${WORK_DIR}/prefix)
set(build ${WORK_DIR}/build)

function(step)
  execute_process(COMMAND ${ARGN} RESULT_VARIABLE rc OUTPUT_VARIABLE out ERROR_VARIABLE out)
  if(NOT rc EQUAL 0)
    file(REMOVE_RECURSE ${WORK_DIR})
    string(REPLACE ";" " " cmd "${ARGN}")
    message(FATAL_ERROR "install_package: failed (${rc}): ${cmd}\n${out}")
  endif()
  message("${out}")
endfunction()

file(REMOVE_RECURSE ${WORK_DIR})
step(${CMAKE_COMMAND} --install ${BUILD_DIR} --config ${CONFIG} --prefix ${prefix})
step(${CMAKE_COMMAND} -S ${PROJECT_DIR} -B ${build} -G ${GENERATOR} -DCMAKE_BUILD_TYPE=${CONFIG}
     -DCMAKE_CXX_COMPILER=${CXX} -DCMAKE_PREFIX_PATH=${prefix})
# The package must be the one just installed, not another copy (e.g. in /usr/local).
file(STRINGS ${build}/CMakeCache.txt found REGEX "^HausdorffLens_DIR:")
if(NOT found MATCHES "=${prefix}/")
  file(REMOVE_RECURSE ${WORK_DIR})
  message(FATAL_ERROR "install_package: found another HausdorffLens package: ${found}")
endif()
step(${CMAKE_COMMAND} --build ${build} --config ${CONFIG})
find_program(exe package_test PATHS ${build} ${build}/${CONFIG} NO_DEFAULT_PATH REQUIRED)
step(${exe})
file(REMOVE_RECURSE ${WORK_DIR})
