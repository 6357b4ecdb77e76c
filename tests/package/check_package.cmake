# The CTest test "package" (tests/CMakeLists.txt) runs this script: it
# installs the build into a prefix inside the build tree, checks the
# installed programs, then configures, builds and runs the project of this
# folder against the prefix, as another CMake project would use asos.
#   cmake -DASOS_BINARY_DIR=... -DASOS_VERSION=... -DWORK=... -DGENERATOR=...
#         -DBUILD_TYPE=... -DCXX=... -P check_package.cmake
function(run what)
  execute_process(COMMAND ${ARGN} RESULT_VARIABLE status OUTPUT_VARIABLE out ERROR_VARIABLE out)
  if(NOT status EQUAL 0)
    message(FATAL_ERROR "package test: ${what} failed (${status}):\n${out}")
  endif()
  set(output "${out}" PARENT_SCOPE)
endfunction()

set(prefix ${WORK}/prefix)
set(build ${WORK}/build)
file(REMOVE_RECURSE ${WORK})

run("install" ${CMAKE_COMMAND} --install ${ASOS_BINARY_DIR} --prefix ${prefix})

foreach(program asos asos-bench)
  run("${program} --version" ${prefix}/bin/${program} --version)
  if(NOT output STREQUAL "${program} ${ASOS_VERSION}\n")
    message(FATAL_ERROR "package test: ${program} --version printed '${output}'")
  endif()
endforeach()
# The installed asos-bench finds its default scene in the prefix, wherever
# it is run from.
execute_process(COMMAND ${prefix}/bin/asos-bench render -W 8 -H 6 --threads 1 --repeat 1
  WORKING_DIRECTORY ${WORK} RESULT_VARIABLE status OUTPUT_VARIABLE output ERROR_VARIABLE output)
string(FIND "${output}" "${prefix}/share/asos/examples/default.pov" at)
if(NOT status EQUAL 0 OR at EQUAL -1)
  message(FATAL_ERROR "package test: the installed asos-bench did not render its default scene:\n${output}")
endif()

run("configure" ${CMAKE_COMMAND} -S ${CMAKE_CURRENT_LIST_DIR} -B ${build} -G ${GENERATOR}
  -DCMAKE_BUILD_TYPE=${BUILD_TYPE} -DCMAKE_CXX_COMPILER=${CXX} -DCMAKE_PREFIX_PATH=${prefix}
  -DASOS_EXPECTED_VERSION=${ASOS_VERSION})
string(FIND "${output}" "from ${prefix}/" at)
if(at EQUAL -1)
  message(FATAL_ERROR "package test: asos was not found in ${prefix}:\n${output}")
endif()
run("build" ${CMAKE_COMMAND} --build ${build})
run("the program" ${build}/asos_package_test ${build})
message(STATUS "${output}")
