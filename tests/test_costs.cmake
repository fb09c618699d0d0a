# ctest -j starts the tests of highest COST first. After a run it has each
# test's measured time (build/Testing/Temporary/CTestCostData.txt) and uses
# that; on a clean clone it has only these: the longest tests, in seconds of
# a run at -j2 on two cores, so that they start first instead of landing at
# the end, where one alone would keep the run going while the other core idles.
# Included after every test folder's own test file (tests/CMakeLists.txt);
# a name a folder does not have is ignored there.
foreach(test_and_cost
    Launch.RestartsAKilledProcessAndCtrlCLeavesACompleteReplayableLog=99
    StereoCalibrateProcess.SimulatorEndToEndRecoversTheTruth=80
    FlatWall.FastMatcherModesKeepTheWallAtTwoMetres=57
    RectifiedRows.SimulatedFisheyeRigLatLonFindsMoreBoardsOnTheirRows=47
    RectifiedRows.RealFisheyeStereoRosLatLonFindsMoreBoards=34
    MultiHost.CaptureOnOneHostCalibrationOnTheOther=34
    FisheyeWall.BsplineThetaCalibrationGivesTheWallAtTwoMetres=30
    Replay.TheSameLogGivesTheSameCornersAndCalibrationEveryTime=27
    FlatWall.BsplineCalibrationGivesAFlatWallAtTwoMetresAndPoly6IsWorse=26
    CalibSimFisheye.RenderedDetectedAndCalibratedRecoversTheTruth=26
    RealFisheyeStereo.AngleModelsUseEveryViewAndBsplineThetaFitsNoWorseThanCvFisheye=24
    RealBabelCalib.TrainTestProtocolBsplineThetaNoWorseThanKb4=23
    FisheyeRoom.LatLonCoversTheCommonFieldAndFindsEveryWall=19
    CalibSharpKnee.OnTheTheiaLikeLensTheChoiceIsNoWorseThanThirteen=18
    Replay.LiveReplayOfTheCornersGivesTheBatchCalibration=14
    CalibSharpKnee.AutomaticKnotsFollowAKneeThirteenCannot=14
    HealthReplay.PitchedRightCameraIsMisaligned=14
    CalibSynthetic.MustacheTableIIPolynomialsCannotFollow=12
    HealthLive.RefineCommandRepairsTheCalibrationAndStereoMatchRebuildsItsMaps=12
    HealthReplay.RefineRepairsAPitchedCalibration=12
    ProjectionUncertainty.PredictsTheSpreadOfRenoisedSolves=12
    CalibSynthetic.BarrelLensBothModelsReachTheNoiseFloor=12
    StereoCalibrateProcess.OnceOverALogGivesTheSameCalibrationTwice=12
    HealthReplay.SameLogGivesTheSameHealthMessages=11
    HostilePeer.WithTheRigKeyOnlyACommandSignedWithItIsObeyedOnce=11
    HealthReplay.TrueCalibrationIsOkOnBoardAndWall=10)
  string(REPLACE "=" ";" pair ${test_and_cost})
  list(GET pair 0 test)
  list(GET pair 1 cost)
  set_tests_properties(${test} PROPERTIES COST ${cost})
endforeach()
