# tamponade_add_catch_tests(<target>): registers every Catch2 test case of <target> with CTest,
# labelled by its tag: [unit], [validation] or [stability]. A test case without one of these tags
# is not part of the default suite (e.g. [benchmark] cases run only by hand).
include(Catch)
function(tamponade_add_catch_tests target)
  foreach(label unit validation stability)
    # --warn NoTests: a registered test whose name filter matches no test case fails instead of
    # passing empty (a ';' in a test name once split it into a CMake list: six test cases had
    # never run).
    catch_discover_tests(${target}
      TEST_SPEC "[${label}]"
      EXTRA_ARGS --warn NoTests
      PROPERTIES LABELS ${label}
      WORKING_DIRECTORY ${TAMPONADE_SOURCE_ROOT})
  endforeach()
endfunction()
