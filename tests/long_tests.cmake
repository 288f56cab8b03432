# Read by ctest after the discovered GoogleTest cases (tests/CMakeLists.txt): the tests that take
# over a minute under AddressSanitizer get the label `long`. scripts/test runs them in the Release
# pass only; under the sanitizers (ctest -LE "quick|long") the test named after each covers the
# same code path in seconds. Costs under ASan + UBSan on 2 cores: tests/sanitize/CTestCostData.txt.
set(clumpkit_long_tests
  # 2 builds of the tiny specimen, a SIGKILL and a SIGINT with resumes (412 s under ASan) ->
  # CliFaults.SpecimenStoppedAfterItsFirstStageResumesToTheSameBytes (stopped and resumed),
  # DemPhysics.ResultsAreBitIdenticalForOneAndTwoThreads (thread count)
  Cli.SpecimenSameForAnyThreadCountAndAfterAKill
  # element tests through the CLI (140-280 s each) -> DemElementTest.* (the same drive on a
  # small compressed cube, 1 and 2 threads) and
  # CliElementTest.ShortTriaxialOfASmallCompressedCylinderSavesItsConsolidatedState (the job)
  CliElementTest.TriaxialHasAPeakAndTheSameBytesForOneAndTwoThreads
  # ParaView's reader (python3-vtk9, uninstrumented) glyphing the tiny specimen's export (36 s
  # under ASan, nearly all of it the Python side) -> CliImport.LammpsRoundTripKeepsTheMeasurements
  # (`export vtk` of the imported specimen)
  CliEngines.VtkReadsTheSpheresAndGlyphsThemToTheirTrueSize
  CliElementTest.IsotropicAndOedometerGiveModuliWithTheOedometerStiffer
  CliElementTest.CompressedCuboidAndItsScaledCopyTestTheSameBitForBit
  CliElementTest.SpecimenScaledByTwoTestsTheSameBitForBit
  # `test cpt` on the tiny specimen, 1 and 2 threads (24 s in Release) -> DemCpt.* (the same
  # push on a small compressed cube: 1 and 2 threads, stopped and continued) and
  # CliCpt.BadProbesAreRefusedBeforeAnythingIsWritten (the job's checks)
  CliCpt.PushIntoTheTinySpecimenSameBytesForOneAndTwoThreads
  # `test oedometer --save-consolidated` on the tiny specimen, then LAMMPS on it (110 s) ->
  # CliElementTest.ShortTriaxialOfASmallCompressedCylinderSavesItsConsolidatedState
  # (--save-consolidated),
  # CliImport.LammpsRoundTripKeepsTheMeasurements (export, LAMMPS, import)
  CliImport.LammpsOedometerFromTheSavedConsolidatedStateHasClumpkitsModulus
  # `test cpt --save-consolidated` on the tiny specimen, then the CPT deck in LAMMPS ->
  # CliLammpsCpt.OneSphereOnTheConeAndOneOnTheShaftGiveTheClosedForms (the deck's probe),
  # CliElementTest.ShortTriaxialOfASmallCompressedCylinderSavesItsConsolidatedState
  # (--save-consolidated)
  CliLammpsCpt.TheSavedConsolidatedChamberStartsAtTheConfiningStressInLammps
  CliLammpsCpt.TheSavedSegmentChamberStartsAtTheConfiningStressInLammps
  # a crushable specimen and its oedometer through the CLI (1 and 2 threads, stopped and
  # resumed), and its control (59 and 24 s in Release) ->
  # CrushableCompression.* (the preparation, 1 and 2 threads), DemElementTest.* (the drive),
  # BondsCsv.* (the files), Breakage.* and FragmentSizes.* (the measures) and
  # CliCrushable.BadCrushableRecipesAreRefusedWithOneLine (the recipe's checks)
  CliCrushable.OedometerBreaksTheCellsConservingVolumeSameBytesForAnyThreadsAndResume
  CliCrushable.TheUnbreakableControlKeepsItsGrading
  # the bundled test recipe on the tiny specimen (80 s) ->
  # CliElementTest.ShortTriaxialOfASmallCompressedCylinderSavesItsConsolidatedState (the job,
  # --save-consolidated), StageFiles.ElementTest... (stopped and resumed)
  CliElementTest.BundledTestRecipeParses
  # similarity of compressed packings (100-200 s) -> DemStiffnessScaling.ScaledCopyMidRun...
  DemStiffnessScaling.PackingScaledByPowersOfTwoIsBitwiseSimilar
  DemStiffnessScaling.PackingScaledByThreeIsSimilarWithinRounding
  # gravity deposition of 150 spheres to equilibrium (166 s) ->
  # Deposition.ThirtySpheresSettleBitIdenticalForThreads
  Deposition.SettlesInsideTheCylinderToARandomPackBitIdenticalForThreads
  # golden hashes of a settling pack, unsorted and sorted (150 s each) ->
  # DemGolden.SmallSettlingPackingSorted (4 layers instead of 16), FallingSpheres, FallingClumps
  DemGolden.SettlingPacking
  # the small settling pack once per SIMD instruction set (4 x 15 s) ->
  # DemGolden.ShortCasesWithSimdOffGiveTheSameBits (scalar reference against the golden hashes)
  # and PairKernel.EveryInstructionSetGivesTheReferenceBits (every set, kernel alone)
  DemGolden.SmallSettlingPackingOnEveryInstructionSet
  DemGolden.SettlingPackingSortedEvery1000Steps
  # compression of 570 spheres (80 s each) ->
  # DemCompression.FiveDiameterCubeIsExactForAnyThreadsAndAtTwiceTheSize
  DemCompression.ReachesTheTargetPorosityWithoutGradientAndIsThreadIndependent
  DemCompression.ACopyAtTwiceTheSizeIsTheSameSpecimenScaledExactly
  # zoned compression of ~300 spheres twice (1 and 2 threads) -> ZonedPacking.*
  DemCompression.ZonedCylinderKeepsItsZonesForAnyThreads
)
foreach(t IN LISTS clumpkit_long_tests)
  set_tests_properties(${t} PROPERTIES LABELS long)
endforeach()
