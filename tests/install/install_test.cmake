# The installed package on its own: installs the build in BUILD_DIR into a scratch prefix, then configures, builds
# and runs tests/install/consumer against that prefix, as a project outside satviz would.
# Usage: cmake -DBUILD_DIR=... -DCONFIG=... -DWORK_DIR=... -DCONSUMER_DIR=... -DGENERATOR=... -DCXX_COMPILER=...
#        -DLINK_FLAGS=... -DWITH_SCENE=ON|OFF -DWITH_APP=ON|OFF -P install_test.cmake
# LINK_FLAGS: what a program needs to link satviz's libraries as this build compiled them (the sanitizers).
set(prefix ${WORK_DIR}/prefix)
set(build ${WORK_DIR}/build)
file(REMOVE_RECURSE ${WORK_DIR})

function(run)
  execute_process(COMMAND ${ARGN} RESULT_VARIABLE status)
  if(NOT status EQUAL 0)
    string(REPLACE ";" " " command "${ARGN}")
    message(FATAL_ERROR "install test: failed (${status}): ${command}")
  endif()
endfunction()

run(${CMAKE_COMMAND} --install ${BUILD_DIR} --prefix ${prefix} --config ${CONFIG})
foreach(file include/satviz/sat.h share/satviz/scenes/overlapping_boxes.json)
  if(NOT EXISTS ${prefix}/${file})
    message(FATAL_ERROR "install test: ${file} is not installed")
  endif()
endforeach()

# Every installed scene names a schema that exists beside it.
file(GLOB installed_scenes ${prefix}/share/satviz/scenes/*.json)
foreach(scene IN LISTS installed_scenes)
  file(READ ${scene} text)
  string(REGEX MATCH "\"\\$schema\": \"([^\"]*)\"" found "${text}")
  get_filename_component(dir ${scene} DIRECTORY)
  if(NOT found OR NOT EXISTS ${dir}/${CMAKE_MATCH_1})
    message(FATAL_ERROR "install test: ${scene} names the schema '${CMAKE_MATCH_1}', which is not installed there")
  endif()
endforeach()

run(${CMAKE_COMMAND} -S ${CONSUMER_DIR} -B ${build} -G ${GENERATOR} -DCMAKE_BUILD_TYPE=Release
    -DCMAKE_CXX_COMPILER=${CXX_COMPILER} -DCMAKE_PREFIX_PATH=${prefix} "-DCMAKE_EXE_LINKER_FLAGS=${LINK_FLAGS}")
run(${CMAKE_COMMAND} --build ${build})
run(${build}/consumer)
if(WITH_SCENE)
  run(${build}/consumer_scene ${prefix}/share/satviz/scenes/overlapping_boxes.json)
endif()

# The installed app finds its scenes in PREFIX/share/satviz from PREFIX/bin: without a display, it gets as far as
# the window (it stops before it with "no bundled scenes" when they are missing).
if(WITH_APP)
  execute_process(COMMAND ${CMAKE_COMMAND} -E env --unset=DISPLAY --unset=WAYLAND_DISPLAY ${prefix}/bin/satviz
                  RESULT_VARIABLE status ERROR_VARIABLE errors)
  if(NOT errors MATCHES "cannot open a window")
    message(FATAL_ERROR "install test: the installed satviz (status ${status}) said: ${errors}")
  endif()
endif()
