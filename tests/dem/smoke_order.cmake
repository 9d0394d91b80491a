# Included by ctest after the discovered Catch tests (tests/CMakeLists.txt), whose names are
# "unit:" and the test case's (catch_discover_tests drops TEST_PREFIX's trailing space): the smoke runs that
# start from the engine's shared smoke specimen (tests/support/smoke_specimens.hpp) run after the
# one that consolidates it, so that none of them holds a ctest slot while waiting on its lock.
# The YADE twins of CV, the start of shear and the implausible speed are heavy (their LIGGGHTS runs
# hold the same checks in the default suite): their names carry the "heavy:" prefix.
foreach(engine LIGGGHTS YADE)
  set(first "unit:${engine} smoke CNL: sigma_n stays within 5 % of the target during shear")
  set(prefix unit)
  if(engine STREQUAL "YADE")
    set(prefix heavy)
  endif()
  foreach(later "unit:${engine} smoke CNS: d sigma_n / d u_n matches K within 10 %"
                "${prefix}:${engine} smoke CV: the plate does not move and sigma_n is free"
                "${prefix}:${engine} smoke start of shear: from the rest state, tau rises without a start-up plateau"
                "${prefix}:${engine}: the smoke scene at inertial number 1e6 is failed as implausible, not complete")
    set_tests_properties("${later}" PROPERTIES DEPENDS "${first}")
  endforeach()
endforeach()
