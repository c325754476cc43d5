# The whole-simulation checks that take longest, under the label `long`: `./test.sh` leaves them
# out of the developer's loop, `./test.sh --long` and CI (.ci/run) run them. ctest's cost data
# on 2 cores: these ten took about 450 of the suite's 620 test-seconds. Included by ctest after
# the discovered tests (tests/CMakeLists.txt), so the names exist when the label is set.
set(HS_LONG_TESTS
    CliHeartBlood.RhythmsCostWhatPhysiologySays
    CliLumped/PathologyPreset.ShowsItsTextbookSigns/aortic_stenosis
    CliLumped/PathologyPreset.ShowsItsTextbookSigns/mitral_regurgitation
    CliLumped/PathologyPreset.ShowsItsTextbookSigns/dilated_cardiomyopathy
    CliLumped/PathologyPreset.ShowsItsTextbookSigns/anterior_infarct
    CliLumped/PathologyPreset.ShowsItsTextbookSigns/heart_failure_preserved_ef
    CliLumped.CompareDrawsTwoLoopsOnOnePlot
    CliLumped.AWallThatCannotReachTheLumpedVolumeIsNamedInTheSummaryLine
    CliCheckpoint.IrregularResumedGivesTheUninterruptedRun
    CliLumped.NormalLumpedGivesAHeartsPressuresAndItsPlots)
# Every number key of every built-in scenario at its extremes, 20 steps each
# (tests/io/scenario/test_scenario_extremes.cpp): one test per built-in, picked from the discovered
# list so that a new built-in is labelled too.
set(HS_EXTREMES_TESTS)
foreach(test IN LISTS hs_io_tests_TESTS)
  if(test MATCHES "^Builtins/ScenarioExtremes\\.")
    list(APPEND HS_EXTREMES_TESTS ${test})
  endif()
endforeach()
set_tests_properties(${HS_LONG_TESTS} ${HS_EXTREMES_TESTS} PROPERTIES LABELS long)
