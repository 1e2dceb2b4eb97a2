# Read by ctest (each test program's folder lists it in TEST_INCLUDE_FILES, after the tests
# gtest_discover_tests found): the longest tests' COST, so that `ctest -j` starts them first. A
# fresh build has no timings of its own (build/Testing/Temporary/CTestCostData.txt) and would
# start them in listing order, the longest last. The costs are seconds each took alone on the
# project's 2-core VM (2026-11-27); the first pattern a test's name matches gives its cost. A test
# matched by none keeps ctest's own figure (none on a fresh build: it starts after these).
set(dyop_test_costs
  "^ManyWorlds\\.ResetLoopEpisodesUnderEveryBackend" 3.3
  "^CompareSummary\\." 2
  "^ManyWorlds\\.ResidentMemoryStaysFlat" 1.8
  "^Recycling\\.PyramidAndStackStandAsWithoutIt$" 1.7
  "^Catalogue/LinCannySkips\\..*/(rain|tumbler|tiles|tile_map)$" 1.6
  "^ConvexPairAccuracy\\.NormalIsUnit" 1.5
  "^Compare\\.TinyRunWritesTheReportTheCsvAndTheCharts$" 1.4
  "^TileSlopes\\.EveryKindAndNeighbourhoodIsCoveredOnce" 1.3
  "^ExactBackends/SkipsInEveryScene\\..*/(rain|tumbler)_" 1.2
  "^DyopFast\\.NeverCallsAnApartPairPenetrating" 1.2
  "^Batch\\.AgreesWithSatOnEveryPairClass" 1.1
  "^EveryMethod/MethodAccuracy\\." 1
  "^Recycling\\." 1
  "^ExactBackends/SkipsInEveryScene\\..*/(tiles|tile_map)_" 0.9
  "/StacksAndPiles(UnderDyopFast)?\\.PilesOfConcaveBodies" 0.9
  "^Catalogue/LinCannySkips\\." 0.8
  "^Structures/Standing\\." 0.8
  "^ManyWorlds\\." 0.7)

foreach(dyop_test IN LISTS dyop_tests_TESTS box2d_bridge_tests_TESTS testbed_tests_TESTS)
  # Parameterised tests are listed with their parameter ("name  # GetParam() = ...").
  string(REGEX REPLACE "  # .*$" "" dyop_test_name "${dyop_test}")
  set(dyop_rest ${dyop_test_costs})
  while(dyop_rest)
    list(POP_FRONT dyop_rest dyop_pattern dyop_cost)
    if(dyop_test_name MATCHES "${dyop_pattern}")
      set_tests_properties("${dyop_test}" PROPERTIES COST ${dyop_cost})
      break()
    endif()
  endwhile()
endforeach()
