# tamponade_add_catch_tests(<target> [LONG]): registers every Catch2 test case of <target> with
# CTest, labelled by its tag: [unit], [validation] or [stability]. A test case without one of these
# tags is not part of the default suite (e.g. [benchmark] cases run only by hand).
# A validation also tagged [long] (one that takes minutes) gets the label `long` instead (one
# label: catch_discover_tests does not pass a list of labels through), which tools/test.sh leaves
# out unless asked (`bash tools/test.sh -L long`). Pass LONG for the targets that have such test
# cases (a discovery that finds no test case prints a configure warning).
include(Catch)
function(tamponade_add_catch_tests target)
  cmake_parse_arguments(ARG "LONG" "" "" ${ARGN})
  foreach(label unit validation stability)
    set(spec "[${label}]")
    if(ARG_LONG AND label STREQUAL "validation")
      set(spec "[validation]~[long]")
      catch_discover_tests(${target}
        TEST_SPEC "[validation][long]"
        EXTRA_ARGS --warn NoTests
        PROPERTIES LABELS long
        WORKING_DIRECTORY ${TAMPONADE_SOURCE_ROOT})
    endif()
    # --warn NoTests: a registered test whose name filter matches no test case fails instead of
    # passing empty (a ';' in a test name once split it into a CMake list: six test cases had
    # never run).
    catch_discover_tests(${target}
      TEST_SPEC "${spec}"
      EXTRA_ARGS --warn NoTests
      PROPERTIES LABELS ${label}
      WORKING_DIRECTORY ${TAMPONADE_SOURCE_ROOT})
  endforeach()
endfunction()
