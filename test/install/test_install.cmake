# SPDX-License-Identifier: GPL-3.0-or-later
# Installs FeatureRecon into a scratch prefix, then builds and runs a consumer with find_package(FeatureRecon)
# and another with add_subdirectory. -DSOURCE_DIR -DWORK -DGENERATOR [-DCOMPILER_LAUNCHER]
file(REMOVE_RECURSE ${WORK})
set(launcher "")
if(COMPILER_LAUNCHER)
  set(launcher -DCMAKE_CXX_COMPILER_LAUNCHER=${COMPILER_LAUNCHER})
endif()
function(run)
  execute_process(COMMAND ${ARGN} RESULT_VARIABLE rc OUTPUT_VARIABLE out ERROR_VARIABLE err)
  if(NOT rc EQUAL 0)
    message(FATAL_ERROR "failed (${rc}): ${ARGN}\n${out}\n${err}")
  endif()
endfunction()
run(${CMAKE_COMMAND} -S ${SOURCE_DIR} -B ${WORK}/lib -G ${GENERATOR} -DCMAKE_INSTALL_PREFIX=${WORK}/prefix
    -DFEATURERECON_BUILD_TESTS=OFF -DFEATURERECON_BUILD_EXAMPLES=OFF -DFEATURERECON_BUILD_TOOLS=OFF)
run(${CMAKE_COMMAND} --install ${WORK}/lib)
foreach(f include/FeatureRecon/skeleton/Augmented_reeb_graph.h lib/cmake/FeatureRecon/FeatureReconConfig.cmake
          lib/cmake/FeatureRecon/FeatureReconConfigVersion.cmake lib/cmake/FeatureRecon/FeatureReconTargets.cmake)
  if(NOT EXISTS ${WORK}/prefix/${f})
    message(FATAL_ERROR "not installed: ${f}")
  endif()
endforeach()
run(${CMAKE_COMMAND} -S ${SOURCE_DIR}/test/install/consumer -B ${WORK}/consumer -G ${GENERATOR}
    -DCMAKE_PREFIX_PATH=${WORK}/prefix -DCMAKE_BUILD_TYPE=Release ${launcher})
run(${CMAKE_COMMAND} --build ${WORK}/consumer)
run(${WORK}/consumer/consumer)
run(${CMAKE_COMMAND} -S ${SOURCE_DIR}/test/install/consumer -B ${WORK}/subdir -G ${GENERATOR} -DUSE_SUBDIRECTORY=ON
    -DFEATURERECON_SOURCE_DIR=${SOURCE_DIR} -DCMAKE_BUILD_TYPE=Release ${launcher})
run(${CMAKE_COMMAND} --build ${WORK}/subdir)
run(${WORK}/subdir/consumer)
message(STATUS "install and add_subdirectory consumers built and ran")
