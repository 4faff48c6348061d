# CTest `installed_sample`: installs this build into a scratch prefix, configures samples/embedding as an
# application of its own (find_package(shadowfx) through CMAKE_PREFIX_PATH only, never the build tree),
# builds it, checks that it links neither Embree nor assimp nor nlohmann-json, and runs it on an effect:
# the sample exits non-zero on a blank frame.
# cmake -DBUILD_DIR=... -DSOURCE_DIR=... -DWORK_DIR=... -DEFFECT=... [-DLAUNCHER=ccache] -P InstalledSample.cmake
# The plain build's test only: the sanitized build runs the application from its own tree (tests/CMakeLists.txt).
function(run)
  execute_process(COMMAND ${ARGN} RESULT_VARIABLE result OUTPUT_VARIABLE output ERROR_VARIABLE output)
  if(NOT result EQUAL 0)
    string(REPLACE ";" " " command "${ARGN}")
    message(FATAL_ERROR "${command}\nfailed (${result}):\n${output}")
  endif()
  set(output "${output}" PARENT_SCOPE)
endfunction()

file(REMOVE_RECURSE ${WORK_DIR})
set(prefix ${WORK_DIR}/prefix)
run(${CMAKE_COMMAND} --install ${BUILD_DIR} --prefix ${prefix})
set(launcher "")
if(LAUNCHER)
  set(launcher -DCMAKE_CXX_COMPILER_LAUNCHER=${LAUNCHER})
endif()
run(${CMAKE_COMMAND} -S ${SOURCE_DIR}/samples/embedding -B ${WORK_DIR}/build -G Ninja
    -DCMAKE_BUILD_TYPE=RelWithDebInfo -DCMAKE_PREFIX_PATH=${prefix} -DCMAKE_FIND_USE_PACKAGE_REGISTRY=OFF
    ${launcher})
run(${CMAKE_COMMAND} --build ${WORK_DIR}/build --verbose)
string(REGEX MATCH "[^\n]*-o embedding[^\n]*" link_line "${output}")
if(NOT link_line)
  message(FATAL_ERROR "no link line for the sample in the build output:\n${output}")
endif()
if(link_line MATCHES "embree|assimp|nlohmann")
  message(FATAL_ERROR "the sample links more than the effect runtime needs:\n${link_line}")
endif()
if(NOT link_line MATCHES "${prefix}")
  message(FATAL_ERROR "the sample does not link the installed libraries:\n${link_line}")
endif()
run(${WORK_DIR}/build/embedding ${EFFECT} 4)
message("${output}")
