# Run by CTest (tests/CMakeLists.txt, installed_package_example): install, build the example
# project against the installed package, run it, check its output.
file(REMOVE_RECURSE ${WORK_DIR})
set(prefix ${WORK_DIR}/prefix)

function(run_step what)
  execute_process(COMMAND ${ARGN} RESULT_VARIABLE status OUTPUT_VARIABLE out ERROR_VARIABLE err)
  if(NOT status EQUAL 0)
    message(FATAL_ERROR "${what} failed (${status}):\n${out}\n${err}")
  endif()
  set(step_output "${out}" PARENT_SCOPE)
endfunction()

run_step("cmake --install" ${CMAKE_COMMAND} --install ${BUILD_DIR} --prefix ${prefix})
foreach(installed include/signorini/signorini.hpp include/signorini/config.hpp
                  lib/cmake/signorini/signoriniConfig.cmake
                  lib/cmake/signorini/signoriniConfigVersion.cmake bin/signorini
                  share/signorini/plot_results.py share/signorini/signorini_figures.py)
  if(NOT EXISTS ${prefix}/${installed})
    message(FATAL_ERROR "not installed: ${installed}")
  endif()
endforeach()
# The plotting module compiled where it was installed (a second run of Python need not compile it).
file(GLOB compiled ${prefix}/share/signorini/__pycache__/signorini_figures.*.pyc)
if(NOT compiled)
  message(FATAL_ERROR "share/signorini/signorini_figures.py was installed but not compiled")
endif()
# Private headers stay private.
foreach(private contact/contact_methods.hpp linalg/detail/cholmod_matrix.hpp)
  if(EXISTS ${prefix}/include/signorini/${private})
    message(FATAL_ERROR "a private header was installed: ${private}")
  endif()
endforeach()

run_step("configure examples/cpp" ${CMAKE_COMMAND} -S ${SOURCE_DIR} -B ${WORK_DIR}/build
         -DCMAKE_PREFIX_PATH=${prefix} -DCMAKE_CXX_COMPILER=${CXX_COMPILER}
         -DCMAKE_BUILD_TYPE=Release)
run_step("build examples/cpp" ${CMAKE_COMMAND} --build ${WORK_DIR}/build)
run_step("run contact_example" ${WORK_DIR}/build/contact_example 60 20 ${WORK_DIR}/results)
message(STATUS "${step_output}")
# Table 1, 60 x 20: M = -6.700472e-05 after 6 Uzawa steps.
if(NOT step_output MATCHES "converged after 6 Uzawa steps, J\\(u\\) = -6\\.700472[0-9]*e-05")
  message(FATAL_ERROR "unexpected answer from the installed library: ${step_output}")
endif()
if(NOT EXISTS ${WORK_DIR}/results/summary.json)
  message(FATAL_ERROR "contact_example wrote no summary.json")
endif()
