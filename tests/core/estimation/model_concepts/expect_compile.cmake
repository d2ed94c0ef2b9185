# Runs the C++ compiler on one source, syntax only, and checks the outcome (ctest model_concepts_*):
#   cmake -DCXX=... -DSOURCE=... -DINCLUDES="dir|dir" [-DDEFINE=NAME] -DEXPECT=pass
#   cmake ... -DEXPECT=fail -DCONCEPT=Name -DMEMBER="model.jacobian(x)" [-DFORBID=text]
# EXPECT=fail passes only when compilation fails AND the diagnostics name the unsatisfied concept and
# the invalid expression (GCC: "satisfaction of 'Concept<...>'" and "required expression '...' is
# invalid"; Clang: "does not satisfy 'Concept'" and "because '...' would be invalid"), and never FORBID
# (the expression of another member: the probe must fail for the member it leaves out, and only it).
cmake_minimum_required(VERSION 3.25)
foreach(var CXX SOURCE INCLUDES EXPECT)
  if(NOT DEFINED ${var})
    message(FATAL_ERROR "expect_compile.cmake: ${var} not set")
  endif()
endforeach()

string(REPLACE "|" ";" include_dirs "${INCLUDES}")
set(args -std=c++20 -fsyntax-only -fdiagnostics-color=never)
if(CXX MATCHES "clang")
  list(APPEND args -fno-caret-diagnostics)
else()
  list(APPEND args -fno-diagnostics-show-caret)
endif()
foreach(dir IN LISTS include_dirs)
  list(APPEND args -I${dir})
endforeach()
if(DEFINED DEFINE AND NOT DEFINE STREQUAL "")
  list(APPEND args -D${DEFINE})
endif()
# LC_ALL=C: ASCII quotes in the diagnostics, whatever the locale of the machine running ctest.
execute_process(COMMAND ${CMAKE_COMMAND} -E env LC_ALL=C ${CXX} ${args} ${SOURCE}
                RESULT_VARIABLE rc OUTPUT_VARIABLE out ERROR_VARIABLE out)

if(EXPECT STREQUAL "pass")
  if(NOT rc EQUAL 0)
    message(FATAL_ERROR "expected ${SOURCE} to compile, it did not (${rc}):\n${out}")
  endif()
  message(STATUS "compiled: ${SOURCE}")
  return()
endif()

if(rc EQUAL 0)
  message(FATAL_ERROR "expected ${SOURCE} (-D${DEFINE}) to fail to compile, it compiled")
endif()
string(REGEX REPLACE "([][.*+?^$()|\\])" "\\\\\\1" member_re "${MEMBER}")
set(concept_re "(satisfaction of|does not satisfy) '(reckoner::est::)?${CONCEPT}[<']")
set(member_re "'${member_re}' (is|would be) invalid")
foreach(re concept_re member_re)
  if(NOT out MATCHES "${${re}}")
    message(FATAL_ERROR "the compiler's message does not match \"${${re}}\":\n${out}")
  endif()
endforeach()
if(DEFINED FORBID AND NOT FORBID STREQUAL "" AND out MATCHES "'${FORBID}")
  message(FATAL_ERROR "the compiler's message also names '${FORBID}':\n${out}")
endif()
message(STATUS "rejected as expected: ${CONCEPT}, ${MEMBER} (-D${DEFINE})")
